// Marching squares at level zero over a grid of texel-centre values (private).
// Land is value >= 0. Every segment is oriented with land on its left, and
// segments are linked into chains: closed loops, or open chains that end on
// the domain edge.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace tidewater::detail {

struct ContourChain {
    std::vector<glm::dvec2> points;  // grid units (texel centre (i, j) is (i, j))
    bool closed = true;
};

/// `values` is n x n, row-major with rows along the second axis. Rows of cells are
/// scanned on `threads` threads; the chains come out in the same order for any count.
std::vector<ContourChain> extract_contours(const std::vector<double>& values, int n, unsigned threads);

}  // namespace tidewater::detail
