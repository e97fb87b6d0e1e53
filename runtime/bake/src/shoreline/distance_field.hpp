// Fills a ShoreField's signed distance and gradient from a ShoreDistance (private).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <stop_token>

#include "shore_geometry.hpp"

namespace tidewater::detail {

/// Every texel's exact signed distance and gradient, on `threads` threads.
/// `progress` gets the fraction of tile rows done. Once `cancel` is requested the
/// remaining tiles are skipped and the field is left incomplete.
void fill_distance_field(const ShoreDistance& distance, ShoreField& field, unsigned threads,
                         const std::function<void(double)>& progress, const std::stop_token& cancel);

/// Texels a side of the blocks the fill lays from the grid's corner (one range query each).
inline constexpr int kDistanceRootBlock = 32;

/// The same over the blocks `roots` of the whole field (kDistanceRootBlock² texels laid
/// from the grid's corner, row-major, ceil(resolution / kDistanceRootBlock) a row, those
/// on the far edges cut at the grid's): each texel gets the value the whole grid's fill
/// gives it.
void fill_distance_roots(const ShoreDistance& distance, ShoreField& field, std::span<const std::size_t> roots,
                         unsigned threads);

/// A square of texels [i0, i0 + size) x [j0, j0 + size) of a grid.
struct TexelWindow {
    int i0 = 0, j0 = 0, size = 0;
};

/// The same over a window of the field's grid (a tile of a tiled bake): `field` places the
/// whole grid (corner, texel, resolution), its depth holds the window's texels (size^2,
/// row-major) and its distance and gradients are written there, sized by the caller.
/// Every texel gets the value the whole grid's fill gives it.
void fill_distance_window(const ShoreDistance& distance, ShoreField& field, const TexelWindow& window, unsigned threads,
                          const std::function<void(double)>& progress, const std::stop_token& cancel);

}  // namespace tidewater::detail
