// Bilinear sampling of a grid whose values sit at texel centres, rows
// along +z, clamped at the edges: the one scalar definition the shore model and
// the shoreline field and the lake and river fields share (the SIMD queries and shaders/shore_fields.glsl use
// the same weights; host_device.h states them).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

namespace tidewater::detail {

/// The four texels around a point and their weights.
struct GridTaps {
    std::size_t k00 = 0, k10 = 0, k01 = 0, k11 = 0;
    int i = 0, j = 0;  ///< the first tap's texel (k00's column and row)
    double w00 = 1.0, w10 = 0.0, w01 = 0.0, w11 = 0.0;

    double operator()(const std::vector<float>& grid) const {
        return w00 * static_cast<double>(grid[k00]) + w10 * static_cast<double>(grid[k10]) +
               w01 * static_cast<double>(grid[k01]) + w11 * static_cast<double>(grid[k11]);
    }
};

/// Taps at world xz `p` of an `nx` x `nz` grid (each >= 1) with outer corner `corner` and
/// texels of `texel` metres. A non-finite point takes the first texel.
inline GridTaps grid_taps(glm::dvec2 corner, double texel, int nx, int nz, glm::dvec2 p) {
    double u = std::clamp((p.x - corner.x) / texel - 0.5, 0.0, nx - 1.0);
    double v = std::clamp((p.y - corner.y) / texel - 0.5, 0.0, nz - 1.0);
    if (std::isnan(u)) u = 0.0;
    if (std::isnan(v)) v = 0.0;
    const int i = std::min(static_cast<int>(u), std::max(nx - 2, 0)),
              j = std::min(static_cast<int>(v), std::max(nz - 2, 0));
    const double fu = u - i, fv = v - j;
    const std::size_t row = static_cast<std::size_t>(nx);
    GridTaps t;
    t.i = i;
    t.j = j;
    t.k00 = static_cast<std::size_t>(j) * row + static_cast<std::size_t>(i);
    t.k10 = t.k00 + (nx > 1 ? 1 : 0);
    t.k01 = t.k00 + (nz > 1 ? row : 0);
    t.k11 = t.k01 + (nx > 1 ? 1 : 0);
    t.w00 = (1 - fu) * (1 - fv);
    t.w10 = fu * (1 - fv);
    t.w01 = (1 - fu) * fv;
    t.w11 = fu * fv;
    return t;
}

/// Taps of a square `resolution`^2 grid.
inline GridTaps grid_taps(glm::dvec2 corner, double texel, int resolution, glm::dvec2 p) {
    return grid_taps(corner, texel, resolution, resolution, p);
}

}  // namespace tidewater::detail
