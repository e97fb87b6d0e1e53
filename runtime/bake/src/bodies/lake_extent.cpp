#include "bodies/lake_extent.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace tidewater::detail {

std::vector<float> sample_terrain(const Terrain& terrain, const FieldGrid& grid) {
    std::vector<float> h(grid.size());
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i)
            h[grid.index(i, j)] = static_cast<float>(terrain.height_at(grid.center(i, j)));
    return h;
}

Result<LakeBake> find_lake_extent(const SceneLake& lake, const FieldGrid& grid, const std::vector<float>& heights,
                                  const std::string& where) {
    const double level = lake.body.level();
    if (!grid.contains(lake.at))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}/at: [{}, {}] lies outside the terrain's extent", where, lake.at.x, lake.at.y)};
    int si = 0, sj = 0;
    grid.texel_of(lake.at, si, sj);
    if (!(static_cast<double>(heights[grid.index(si, sj)]) < level))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}/at: the terrain there is {:.2f} m, not under the lake's level {} m", where,
                                 static_cast<double>(heights[grid.index(si, sj)]), level)};
    std::vector<std::uint8_t> inside(grid.size(), 0);
    std::vector<std::pair<int, int>> stack{{si, sj}};
    inside[grid.index(si, sj)] = 1;
    int lo_i = si, hi_i = si, lo_j = sj, hi_j = sj;
    std::size_t count = 0;
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        ++count;
        if (i == 0 || j == 0 || i == grid.nx - 1 || j == grid.nz - 1) {
            const glm::dvec2 c = grid.center(i, j);
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: spills over the domain edge: the terrain under its level {} m reaches the "
                                     "edge at [{:.1f}, {:.1f}] (lower the level or move \"at\")",
                                     where, level, c.x, c.y)};
        }
        lo_i = std::min(lo_i, i);
        hi_i = std::max(hi_i, i);
        lo_j = std::min(lo_j, j);
        hi_j = std::max(hi_j, j);
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
            const std::size_t n = grid.index(i + di, j + dj);
            if (!inside[n] && static_cast<double>(heights[n]) < level) {
                inside[n] = 1;
                stack.push_back({i + di, j + dj});
            }
        }
    }
    LakeBake out;
    out.name = lake.name;
    out.level = level;
    out.texels = count;
    out.grid.texel = grid.texel;
    out.grid.corner = grid.corner + grid.texel * glm::dvec2(lo_i, lo_j);
    out.grid.nx = hi_i - lo_i + 1;
    out.grid.nz = hi_j - lo_j + 1;
    out.inside.assign(out.grid.size(), 0);
    for (int j = lo_j; j <= hi_j; ++j)
        for (int i = lo_i; i <= hi_i; ++i) out.inside[out.grid.index(i - lo_i, j - lo_j)] = inside[grid.index(i, j)];
    return out;
}

}  // namespace tidewater::detail
