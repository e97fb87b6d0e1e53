// Where a heightmap edit reaches on the shore model's grids: the local re-bakes after an
// edit of dry land (shore_land_edit.cpp) and under the water (shore_water_edit.cpp) start
// from it. Private.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

/// Where the cuts `after` differs from `before` in cut the ground: the support of the
/// texels that differ between two cuts on the same grid, and the whole reach of a cut
/// that has no such twin (a channel moved, a river added or removed). An empty optional
/// when every cut is the same or holds the same depths.
inline std::optional<WorldRect> cuts_change(const std::vector<std::shared_ptr<const TerrainCut>>& before,
                                            const std::vector<std::shared_ptr<const TerrainCut>>& after) {
    std::optional<WorldRect> rect;
    auto unite = [&](const WorldRect& r) {
        rect = rect ? WorldRect{glm::min(rect->lo, r.lo), glm::max(rect->hi, r.hi)} : r;
    };
    // Texels [i0, i1] x [j0, j1] of a cut reach half a texel before them and one and a
    // half after (bilinear between texel centres, fading over the grid's ring).
    auto reach = [&](const TerrainCut& c, int i0, int j0, int i1, int j1) {
        unite(
            {c.corner + c.texel * glm::dvec2(i0 - 0.5, j0 - 0.5), c.corner + c.texel * glm::dvec2(i1 + 1.5, j1 + 1.5)});
    };
    for (std::size_t k = 0; k < std::max(before.size(), after.size()); ++k) {
        const TerrainCut* a = k < before.size() ? before[k].get() : nullptr;
        const TerrainCut* b = k < after.size() ? after[k].get() : nullptr;
        if (a == b) continue;
        if (a && b && a->corner == b->corner && a->texel == b->texel && a->nx == b->nx && a->nz == b->nz &&
            a->depth.size() == b->depth.size()) {
            int i0 = a->nx, j0 = a->nz, i1 = -1, j1 = -1;
            for (int j = 0; j < a->nz; ++j)
                for (int i = 0; i < a->nx; ++i) {
                    const std::size_t t =
                        static_cast<std::size_t>(j) * static_cast<std::size_t>(a->nx) + static_cast<std::size_t>(i);
                    if (a->depth[t] == b->depth[t]) continue;
                    i0 = std::min(i0, i);
                    j0 = std::min(j0, j);
                    i1 = std::max(i1, i);
                    j1 = std::max(j1, j);
                }
            if (i1 >= 0) reach(*a, i0, j0, i1, j1);
            continue;
        }
        if (a) reach(*a, 0, 0, a->nx - 1, a->nz - 1);
        if (b) reach(*b, 0, 0, b->nx - 1, b->nz - 1);
    }
    return rect;
}

/// Where `after`'s height may differ from `before`'s: the changed pixels' reach when the
/// shapes are the same heightmap with other pixels (or the same shape), and the reach of
/// the cuts that changed (a river's channel re-carved).
inline HeightmapChange heightmap_change(const Terrain& before, const Terrain& after) {
    std::optional<WorldRect> rect;
    const Terrain shape_before = before.with_cuts({}), shape_after = after.with_cuts({});
    if (!(shape_before == shape_after)) {
        const auto pixels = changed_pixels(shape_before, shape_after);
        if (!pixels) return std::nullopt;
        if (*pixels) rect = pixels_reach(std::get<HeightmapTerrain>(before.shape()), **pixels);
    }
    if (const auto cuts = cuts_change(before.cuts(), after.cuts()))
        rect = rect ? WorldRect{glm::min(rect->lo, cuts->lo), glm::max(rect->hi, cuts->hi)} : *cuts;
    return rect ? HeightmapChange{rect} : HeightmapChange{std::optional<WorldRect>{}};
}

/// The texels of a grid whose centres lie in `r` (i1 < i0 when none do).
struct TexelRange {
    int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
    int width() const { return i1 - i0 + 1; }
    int height() const { return j1 - j0 + 1; }
    bool empty() const { return i1 < i0 || j1 < j0; }
    bool contains(int i, int j) const { return i >= i0 && i <= i1 && j >= j0 && j <= j1; }
};
inline TexelRange texels_in(int n, double texel, glm::dvec2 corner, const WorldRect& r) {
    auto first = [&](double lo, double c) {
        return static_cast<int>(std::clamp(std::ceil((lo - c) / texel - 0.5), 0.0, static_cast<double>(n)));
    };
    auto last = [&](double hi, double c) {
        return static_cast<int>(std::clamp(std::floor((hi - c) / texel - 0.5), -1.0, static_cast<double>(n - 1)));
    };
    return {first(r.lo.x, corner.x), first(r.lo.y, corner.y), last(r.hi.x, corner.x), last(r.hi.y, corner.y)};
}

}  // namespace tidewater::detail
