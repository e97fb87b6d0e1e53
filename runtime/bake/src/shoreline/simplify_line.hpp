// Shoreline simplification (private).
#pragma once

#include "tidewater/detail/shore_bake.hpp"

namespace tidewater::detail {

/// The line with every vertex dropped that lies within `tolerance` (m) of the simplified
/// line (Douglas-Peucker, Boost.Geometry). A closed line keeps its first vertex; a line
/// that would fall below 3 (closed) or 2 (open) points is returned whole, so tiny islands
/// survive.
std::vector<glm::dvec2> simplify_line(const ShoreLine& line, double tolerance);

}  // namespace tidewater::detail
