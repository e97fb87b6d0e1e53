#include "terrain_brush.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace tidewater::editor {

Terrain brush_terrain(const Terrain& terrain, glm::dvec2 at, double radius, double height) {
    // The pixel grid: the heightmap's own, or 1024 x 1024 over a procedural terrain's extent.
    HeightmapTerrain map;
    bool existing_range = false;
    if (const auto* existing = std::get_if<HeightmapTerrain>(&terrain.shape())) {
        map = *existing;
        existing_range = map.max_height > map.min_height;
    } else {
        auto blank = std::make_shared<Gray16Image>();
        blank->width = blank->height = 1024;
        map.image = blank;
        map.size = glm::dvec2(2.0 * terrain.extent_half_size());
        map.center = terrain.extent_center();
        map.file = "brushed terrain";
    }
    const int w = map.image->width, h = map.image->height;
    std::vector<double> heights(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    // A heightmap keeps its range unless the stroke leaves it, so that the pixels away from
    // the stroke keep their codes and a re-bake finds the stroke's pixels alone changed.
    double lo = existing_range ? map.min_height : 1e300, hi = existing_range ? map.max_height : -1e300;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            // Pixel centres span the extent (as HeightmapTerrain samples them).
            const glm::dvec2 p = map.center + map.size * glm::dvec2(i / double(w - 1) - 0.5, j / double(h - 1) - 0.5);
            const double d = std::hypot(p.x - at.x, p.y - at.y) / radius;
            const double falloff = d < 1.0 ? (1.0 - d * d) * (1.0 - d * d) : 0.0;
            const double v = terrain.shape_height_at(p) + height * falloff;
            heights[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i)] = v;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (!(hi > lo)) hi = lo + 1.0;
    auto image = std::make_shared<Gray16Image>();
    image->width = w;
    image->height = h;
    image->pixels.resize(heights.size());
    for (std::size_t k = 0; k < heights.size(); ++k)
        image->pixels[k] = static_cast<std::uint16_t>(std::lround((heights[k] - lo) / (hi - lo) * 65535.0));
    map.min_height = lo;
    map.max_height = hi;
    map.image = std::move(image);
    return Terrain(map);
}

}  // namespace tidewater::editor
