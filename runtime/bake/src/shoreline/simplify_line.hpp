// Shoreline simplification (private).
#pragma once

#include "tidewater/detail/shore_bake.hpp"

namespace tidewater::detail {

/// The lattice a shoreline is cut at before it is simplified: lines every `spacing` m
/// from `corner` along x and z. Each piece between two crossings is simplified alone, so
/// an edit of the terrain changes the simplified line only in the pieces it touches.
struct SimplifyLattice {
    glm::dvec2 corner{0.0};
    double spacing = 0.0;  ///< m; 0: no lattice, each line simplified whole
};

/// The line with every vertex dropped that lies within `tolerance` (m) of the simplified
/// line (Douglas-Peucker, Boost.Geometry), piece by piece between the lattice's crossings
/// (the first vertex past each crossing is kept). A closed line then starts at its first
/// such vertex (with none, it is simplified whole and keeps its first vertex); a line that
/// would fall below 3 (closed) or 2 (open) points is returned whole, so tiny islands
/// survive.
std::vector<glm::dvec2> simplify_line(const ShoreLine& line, double tolerance, const SimplifyLattice& lattice = {});

}  // namespace tidewater::detail
