// One cell of a shoreline's contour (the shoreline bake's marching squares), as a tiled
// bake passes them between its steps (tiled_shore.hpp).
#pragma once

#include <glm/vec2.hpp>

namespace tidewater::detail {

/// One piece of contour inside cell (i, j) (texels i..i+1 x j..j+1), entering through edge
/// `from_edge` and leaving through `to_edge` (0 bottom, 1 right, 2 top, 3 left), land on its
/// left; `from` and `to` in grid units (texel centre (i, j) is (i, j)).
struct ContourCell {
    int i = 0, j = 0;
    int from_edge = 0, to_edge = 0;
    glm::dvec2 from{0.0}, to{0.0};
};

}  // namespace tidewater::detail
