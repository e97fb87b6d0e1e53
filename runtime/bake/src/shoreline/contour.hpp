// Marching squares at level zero over a grid of texel-centre values (private).
// Land is value >= 0. Every segment is oriented with land on its left, and
// segments are linked into chains: closed loops, or open chains that end on
// the domain edge.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "tidewater/detail/contour_cell.hpp"

namespace tidewater::detail {

struct ContourChain {
    std::vector<glm::dvec2> points;  // grid units (texel centre (i, j) is (i, j))
    bool closed = true;
};

/// Cells [i0, i1) x [j0, j1) of a grid: their values are texels [i0, i1] x [j0, j1].
struct CellWindow {
    int i0, j0, i1, j1;
};

/// Marching squares over the window's cells. `values` holds the window's texels, row-major
/// ((i1 - i0 + 1) a row, rows along the second axis). Sorted by (j, i), and in the same
/// order for any `threads`; a tile's cells are the whole grid's in that tile.
std::vector<ContourCell> contour_cells(const std::vector<double>& values, const CellWindow& window, unsigned threads);

/// Links the cells of an n x n grid (every cell's that crosses, sorted by (j, i)) into chains.
std::vector<ContourChain> chain_contour_cells(std::vector<ContourCell> cells, int n);

/// `values` is n x n, row-major with rows along the second axis. Rows of cells are
/// scanned on `threads` threads; the chains come out in the same order for any count.
std::vector<ContourChain> extract_contours(const std::vector<double>& values, int n, unsigned threads);

}  // namespace tidewater::detail
