// Bilinear sampling of a square grid whose values sit at texel centres, rows
// along +z, clamped at the edges: the one scalar definition the shore model and
// the shoreline field share (the SIMD queries and shaders/shore_fields.glsl use
// the same weights; host_device.h states them).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

namespace tidewater::detail {

/// The four texels around a point and their weights.
struct GridTaps {
    std::size_t k00 = 0, k10 = 0, k01 = 0, k11 = 0;
    double w00 = 1.0, w10 = 0.0, w01 = 0.0, w11 = 0.0;

    double operator()(const std::vector<float>& grid) const {
        return w00 * static_cast<double>(grid[k00]) + w10 * static_cast<double>(grid[k10]) + w01 * static_cast<double>(grid[k01]) +
               w11 * static_cast<double>(grid[k11]);
    }
};

/// Taps at world xz `p` of a `resolution`^2 grid (resolution >= 2) with outer corner
/// `corner` and texels of `texel` metres.
inline GridTaps grid_taps(glm::dvec2 corner, double texel, int resolution, glm::dvec2 p) {
    const double u = std::clamp((p.x - corner.x) / texel - 0.5, 0.0, resolution - 1.0);
    const double v = std::clamp((p.y - corner.y) / texel - 0.5, 0.0, resolution - 1.0);
    const int i = std::min(static_cast<int>(u), resolution - 2), j = std::min(static_cast<int>(v), resolution - 2);
    const double fu = u - i, fv = v - j;
    GridTaps t;
    t.k00 = static_cast<std::size_t>(j) * static_cast<std::size_t>(resolution) + static_cast<std::size_t>(i);
    t.k10 = t.k00 + 1;
    t.k01 = t.k00 + static_cast<std::size_t>(resolution);
    t.k11 = t.k01 + 1;
    t.w00 = (1 - fu) * (1 - fv);
    t.w10 = fu * (1 - fv);
    t.w01 = (1 - fu) * fv;
    t.w11 = fu * fv;
    return t;
}

}  // namespace tidewater::detail
