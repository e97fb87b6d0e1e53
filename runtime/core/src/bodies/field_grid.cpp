#include <algorithm>
#include <cmath>

#include "host_device.h"
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

RiverCurrentTaps river_current_taps(const RiverBake& river, glm::dvec2 p) {
    const FieldGrid& g = river.grid;
    const GridTaps taps = grid_taps(g.corner, g.texel, g.nx, g.nz, p);
    const auto column = [&](std::size_t k) { return std::max(static_cast<double>(river.depth[k]), 0.0); };
    RiverCurrentTaps out;
    out.texel = {taps.k00, taps.k10, taps.k01, taps.k11};
    out.weight = {taps.w00 * column(taps.k00), taps.w10 * column(taps.k10), taps.w01 * column(taps.k01),
                  taps.w11 * column(taps.k11)};
    const double water = out.weight[0] + out.weight[1] + out.weight[2] + out.weight[3];
    for (double& w : out.weight) w = water > 0.0 ? w / water : 0.0;
    return out;
}

RiverSample sample_river(const RiverBake& river, glm::dvec2 p) {
    const FieldGrid& g = river.grid;
    const GridTaps taps = grid_taps(g.corner, g.texel, g.nx, g.nz, p);
    RiverSample out;
    out.s = taps(river.channel_s);
    out.n = taps(river.channel_n);
    out.depth = taps(river.depth);
    // The current: the texels' currents weighted by their water columns too, so that the
    // depth times the current is the bilinear field of h u wherever the four are wet, and
    // the current stays within the texels' own next to the banks (river_water.glsl's twin).
    const RiverCurrentTaps current = river_current_taps(river, p);
    for (std::size_t q = 0; q < 4; ++q) {
        out.flow_x += current.weight[q] * static_cast<double>(river.flow_x[current.texel[q]]);
        out.flow_z += current.weight[q] * static_cast<double>(river.flow_z[current.texel[q]]);
    }
    out.surface = taps(river.surface_height);
    return out;
}

bool cut_touches(const TerrainCut& cut, const FieldGrid& grid) {
    const glm::dvec2 lo = cut.corner - glm::dvec2(cut.texel),
                     hi = cut.corner + cut.texel * glm::dvec2(cut.nx + 1, cut.nz + 1);
    const glm::dvec2 glo = grid.corner, ghi = grid.corner + grid.texel * glm::dvec2(grid.nx, grid.nz);
    return lo.x < ghi.x && glo.x < hi.x && lo.y < ghi.y && glo.y < hi.y;
}

std::vector<std::shared_ptr<const TerrainCut>> cuts_under(const std::vector<std::shared_ptr<const TerrainCut>>& cuts,
                                                          const FieldGrid& grid) {
    std::vector<std::shared_ptr<const TerrainCut>> out;
    for (const auto& c : cuts)
        if (c && cut_touches(*c, grid)) out.push_back(c);
    return out;
}

const char* river_end_name(RiverEnd end) {
    switch (end) {
        case RiverEnd::ocean:
            return "ocean";
        case RiverEnd::lake:
            return "lake";
        case RiverEnd::river:
            return "river";
        case RiverEnd::domain_edge:
            break;
    }
    return "domain_edge";
}

SquareRegion lake_basin_region(const LakeBake& lake) {
    const FieldGrid& g = lake.grid;
    SquareRegion region;
    region.center = g.corner + 0.5 * g.texel * glm::dvec2(g.nx, g.nz);
    region.half_size = 0.5 * g.texel * std::max(g.nx, g.nz) * 1.1 + 2.0 * g.texel;
    return region;
}

bool LakeBake::holds(glm::dvec2 p, double terrain_height) const {
    if (!(terrain_height < level)) return false;
    const double u = (p.x - grid.corner.x) / grid.texel, v = (p.y - grid.corner.y) / grid.texel;
    if (!(u > -1.0 && v > -1.0 && u < grid.nx + 1.0 && v < grid.nz + 1.0)) return false;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    // A texel's neighbours too: the lake's edge lies between texel centres.
    for (int j = j0 - 1; j <= j0 + 1; ++j)
        for (int i = i0 - 1; i <= i0 + 1; ++i)
            if (i >= 0 && j >= 0 && i < grid.nx && j < grid.nz && inside[grid.index(i, j)]) return true;
    return false;
}

void pack_query_texels(RiverBake& river, const std::vector<float>& river_weight,
                       const std::vector<float>& still_weight) {
    const std::size_t n = river.grid.size();
    river.query_texels.assign(n * gpu::kRiverQueryStride, 0.0f);
    for (std::size_t t = 0; t < n; ++t) {
        float* q = river.query_texels.data() + t * gpu::kRiverQueryStride;
        q[gpu::kRiverQuerySurface] =
            static_cast<float>(static_cast<double>(river.surface_height[t]) - river.mouth_level);
        q[gpu::kRiverQueryDepth] = river.depth[t];
        q[gpu::kRiverQueryTangentX] = river.tangent_x[t];
        q[gpu::kRiverQueryTangentZ] = river.tangent_z[t];
        q[gpu::kRiverQueryWaveWeight] = river_weight[t];
        q[gpu::kRiverQueryStillWeight] = still_weight[t];
    }
}

}  // namespace tidewater::detail
