#include <algorithm>
#include <cmath>

#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

void FieldGrid::texel_of(glm::dvec2 p, int& i, int& j) const {
    const double u = (p.x - corner.x) / texel, v = (p.y - corner.y) / texel;
    // NaN compares false: it lands on texel 0.
    i = u > 0.0 ? static_cast<int>(std::min(u, nx - 1.0)) : 0;
    j = v > 0.0 ? static_cast<int>(std::min(v, nz - 1.0)) : 0;
}

double FieldGrid::sample(const std::vector<float>& field, glm::dvec2 p) const {
    return grid_taps(corner, texel, nx, nz, p)(field);
}

}  // namespace tidewater::detail
