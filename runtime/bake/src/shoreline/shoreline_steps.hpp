// The steps of a shoreline bake that a tiled bake (tiled_shore.hpp) runs apart: the
// noise checks and the shoreline from the contour's cells (private).
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

#include "contour.hpp"
#include "shore_geometry.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

/// Texels [i0, i0 + width) x [j0, j0 + height) of a grid.
struct TexelRect {
    int i0 = 0, j0 = 0, width = 0, height = 0;
};

/// The terrain's height above `water_level` (`above`) and the water's depth (`depth`) at
/// the texel centres of rectangle `r` of `grid` (its corner, texel and resolution; row-major,
/// `r.width` a row). Fails naming the first place where the height is not finite.
struct WindowHeights {
    std::vector<double> above;
    std::vector<float> depth;
};
Result<WindowHeights> window_heights(const Terrain& terrain, double water_level, const ShoreField& grid,
                                     const TexelRect& r, unsigned threads);

/// The window's cells that hold land (depth <= 0) and water; `depth` holds its texels
/// (row-major, (i1 - i0 + 1) a row).
std::size_t mixed_cells(const std::vector<float>& depth, const CellWindow& window, unsigned threads);

/// Fails when `mixed` of a grid's `count` cells hold land and water: a terrain that noisy
/// at the water level is not a coast (say, millions of one-texel islands).
Status check_mixed_cells(std::size_t mixed, std::size_t count);

/// The shoreline of an n x n grid (corner and texel in m) from every cell of its contour
/// (sorted by (j, i)): chained, refused when it is noise, in world units, simplified within
/// `tolerance` m and classified (CGAL).
Result<ClassifiedShore> shoreline_from_cells(std::vector<ContourCell> cells, int n, glm::dvec2 corner, double texel,
                                             double tolerance, unsigned threads);

}  // namespace tidewater::detail
