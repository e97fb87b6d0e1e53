// Fills a ShoreField's signed distance and gradient from a ShoreDistance (private).
#pragma once

#include <functional>
#include <stop_token>

#include "shore_geometry.hpp"

namespace tidewater::detail {

/// Every texel's exact signed distance and gradient, on `threads` threads.
/// `progress` gets the fraction of tile rows done. Once `cancel` is requested the
/// remaining tiles are skipped and the field is left incomplete.
void fill_distance_field(const ShoreDistance& distance, ShoreField& field, unsigned threads,
                         const std::function<void(double)>& progress, const std::stop_token& cancel);

}  // namespace tidewater::detail
