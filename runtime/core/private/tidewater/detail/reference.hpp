// Reference solvers (not part of the API users call): the scalar double path of the
// water evaluation and the seed project's fixed-point loop (the brute-force shoreline
// distance is the bake's, shore_bake.hpp). Tests and benchmarks measure the fast paths against them; they are slow
// by design. Threading: pure functions of immutable inputs.
#pragma once

#include <glm/vec2.hpp>
#include <span>

#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {

namespace reference {

/// The fixed-point height loop of the boat project this library's queries
/// replace: four passes of x0 = p - d(x0), then eta(x0). Kept only as the
/// baseline the benchmark compares against; it is inaccurate on steep seas.
double fixed_point_height(const WaveSet& set, double local_time, glm::dvec2 point);
/// The same loop over a batch, with the per-wave phase offsets computed once
/// (as a fair baseline would). Heights are eta (no water level added).
void fixed_point_heights(const WaveSet& set, double local_time, std::span<const glm::dvec2> points,
                         std::span<double> heights);

/// query_point on the scalar double path: the same evaluation and Newton solver as the
/// SIMD kernel, in double and one point at a time. The yardstick for the kernel's
/// float arithmetic (tests and benchmarks), not a fast path.
SurfacePoint query_point(const WaterBody& body, double time, glm::dvec2 point);

/// query_world for one point on the scalar double path (rivers and plumes included).
/// The scene must be baked where it has lakes or rivers (a default WorldPoint if not).
WorldPoint query_world_point(const Scene& scene, double time, glm::dvec2 point);

}  // namespace reference

}  // namespace tidewater
