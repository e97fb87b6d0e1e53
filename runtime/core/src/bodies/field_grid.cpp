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

namespace tidewater::detail {

RiverSample sample_river(const RiverBake& river, glm::dvec2 p) {
    const FieldGrid& g = river.grid;
    const GridTaps taps = grid_taps(g.corner, g.texel, g.nx, g.nz, p);
    RiverSample out;
    out.s = taps(river.channel_s);
    out.n = taps(river.channel_n);
    out.flow_x = taps(river.flow_x);
    out.flow_z = taps(river.flow_z);
    out.depth = taps(river.depth);
    out.surface = taps(river.surface_height);
    return out;
}

bool cut_touches(const TerrainCut& cut, const FieldGrid& grid) {
    const glm::dvec2 lo = cut.corner - glm::dvec2(cut.texel), hi = cut.corner + cut.texel * glm::dvec2(cut.nx + 1, cut.nz + 1);
    const glm::dvec2 glo = grid.corner, ghi = grid.corner + grid.texel * glm::dvec2(grid.nx, grid.nz);
    return lo.x < ghi.x && glo.x < hi.x && lo.y < ghi.y && glo.y < hi.y;
}

std::vector<std::shared_ptr<const TerrainCut>> cuts_under(const std::vector<std::shared_ptr<const TerrainCut>>& cuts, const FieldGrid& grid) {
    std::vector<std::shared_ptr<const TerrainCut>> out;
    for (const auto& c : cuts)
        if (c && cut_touches(*c, grid)) out.push_back(c);
    return out;
}

const char* river_end_name(RiverEnd end) {
    switch (end) {
        case RiverEnd::ocean: return "ocean";
        case RiverEnd::lake: return "lake";
        case RiverEnd::river: return "river";
        case RiverEnd::domain_edge: break;
    }
    return "domain_edge";
}

}  // namespace tidewater::detail
