#include "tidewater/detail/heightmap_change.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <variant>

namespace tidewater::detail {

std::optional<std::optional<PixelRect>> changed_pixels(const Terrain& before, const Terrain& after) {
    const auto* a = std::get_if<HeightmapTerrain>(&before.shape());
    const auto* b = std::get_if<HeightmapTerrain>(&after.shape());
    if (!a || !b || !a->image || !b->image || before.cuts() != after.cuts() || a->size != b->size ||
        a->center != b->center || a->min_height != b->min_height || a->max_height != b->max_height)
        return std::nullopt;
    const Gray16Image &x = *a->image, &y = *b->image;
    if (x.width != y.width || x.height != y.height || x.pixels.size() != y.pixels.size() || x.width < 2 || x.height < 2)
        return std::nullopt;
    if (a->image == b->image) return std::optional<PixelRect>{};
    const auto w = static_cast<std::size_t>(x.width);
    PixelRect r{x.width, x.height, -1, -1};
    for (int j = 0; j < x.height; ++j) {
        const std::uint16_t* p = x.pixels.data() + static_cast<std::size_t>(j) * w;
        const std::uint16_t* q = y.pixels.data() + static_cast<std::size_t>(j) * w;
        if (std::memcmp(p, q, w * sizeof(std::uint16_t)) == 0) continue;
        for (int i = 0; i < x.width; ++i)
            if (p[i] != q[i]) {
                r.i0 = std::min(r.i0, i);
                r.i1 = std::max(r.i1, i);
            }
        r.j0 = std::min(r.j0, j);
        r.j1 = std::max(r.j1, j);
    }
    if (r.i1 < 0) return std::optional<PixelRect>{};
    return std::optional<PixelRect>{r};
}

WorldRect pixels_reach(const HeightmapTerrain& map, const PixelRect& pixels) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const int w = map.image->width, h = map.image->height;
    auto along = [](double pixel, int count, double center, double size) {
        return center + (pixel / (count - 1) - 0.5) * size;
    };
    WorldRect r;
    r.lo.x = pixels.i0 == 0 ? -inf : along(pixels.i0 - 1, w, map.center.x, map.size.x);
    r.hi.x = pixels.i1 == w - 1 ? inf : along(pixels.i1 + 1, w, map.center.x, map.size.x);
    r.lo.y = pixels.j0 == 0 ? -inf : along(pixels.j0 - 1, h, map.center.y, map.size.y);
    r.hi.y = pixels.j1 == h - 1 ? inf : along(pixels.j1 + 1, h, map.center.y, map.size.y);
    return r;
}

}  // namespace tidewater::detail
