// Eulerian queries over a shore model (private): Newton on the 2x2 system with
// the shore's local waves, in double, one point at a time.
#pragma once

#include <cstddef>

#include <glm/vec2.hpp>

#include "tidewater/query.hpp"
#include "tidewater/shore_waves.hpp"

namespace tidewater::detail {

/// Solves `n` points; exactly one of `full` and `heights` is non-null.
void solve_points_shore(const WaterBody& body, const ShoreWaves& shore, double local_time, const glm::dvec2* points,
                        std::size_t n, SurfacePoint* full, double* heights);

}  // namespace tidewater::detail
