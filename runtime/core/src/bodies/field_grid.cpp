#include <algorithm>
#include <cmath>

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

void FieldGrid::texel_of(glm::dvec2 p, int& i, int& j) const {
    const double u = (p.x - corner.x) / texel, v = (p.y - corner.y) / texel;
    // NaN compares false: it lands on texel 0.
    i = u > 0.0 ? static_cast<int>(std::min(u, nx - 1.0)) : 0;
    j = v > 0.0 ? static_cast<int>(std::min(v, nz - 1.0)) : 0;
}

double FieldGrid::sample(const std::vector<float>& field, glm::dvec2 p) const {
    const double u = std::clamp((p.x - corner.x) / texel - 0.5, 0.0, nx - 1.0);
    const double v = std::clamp((p.y - corner.y) / texel - 0.5, 0.0, nz - 1.0);
    if (!std::isfinite(u) || !std::isfinite(v)) return field[0];
    const int i = std::min(static_cast<int>(u), std::max(nx - 2, 0)), j = std::min(static_cast<int>(v), std::max(nz - 2, 0));
    const int i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, nz - 1);
    const double fu = u - i, fv = v - j;
    auto at = [&](int a, int b) { return static_cast<double>(field[index(a, b)]); };
    return (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i1, j)) + fv * ((1 - fu) * at(i, j1) + fu * at(i1, j1));
}

}  // namespace tidewater::detail
