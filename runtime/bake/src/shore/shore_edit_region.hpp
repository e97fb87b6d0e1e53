// Where a heightmap edit reaches on the shore model's grids: the local re-bakes after an
// edit of dry land (shore_land_edit.cpp) and under the water (shore_water_edit.cpp) start
// from it. Private.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

/// Where `after`'s height may differ from `before`'s (pixels_reach of the changed pixels).
inline HeightmapChange heightmap_change(const Terrain& before, const Terrain& after) {
    const auto pixels = changed_pixels(before, after);
    if (!pixels) return std::nullopt;
    if (!*pixels) return std::optional<WorldRect>{};
    return std::optional<WorldRect>{pixels_reach(std::get<HeightmapTerrain>(before.shape()), **pixels)};
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
