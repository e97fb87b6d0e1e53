// A test terrain with a basin in the hills: a bowl 500 m across, floor 10 m, rising to
// 40 m at r = 300 m (a 16-bit heightmap 1 km square, centred on the origin), and a lake in it.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "tidewater/scene.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::test {

inline Terrain bowl_terrain() {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = 257;
    image->pixels.resize(257 * 257);
    for (int j = 0; j < 257; ++j)
        for (int i = 0; i < 257; ++i) {
            const double x = (i - 128) * 1000.0 / 256.0, z = (j - 128) * 1000.0 / 256.0;
            const double h = 10.0 + 30.0 * (x * x + z * z) / (300.0 * 300.0);
            image->pixels[static_cast<std::size_t>(j) * 257 + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::lround(std::min(h, 100.0) / 100.0 * 65535.0));
        }
    HeightmapTerrain map;
    map.file = "bowl";
    map.size = {1000.0 * 257.0 / 256.0, 1000.0 * 257.0 / 256.0};
    map.min_height = 0.0;
    map.max_height = 100.0;
    map.image = std::move(image);
    return Terrain(map);
}

/// The bowl alone with a lake, "bowl", at 30 m in it (parsed, not baked).
inline Result<Scene> bowl_lake_scene() {
    auto parsed = parse_scene(R"({ "version": 1, "name": "hills", "terrain": { "flat": { "height": 0.0 } },
      "lakes": [ { "name": "bowl", "level": 30.0, "at": [0, 0] } ] })",
                              "lake.json");
    if (parsed) parsed->terrain = bowl_terrain();
    return parsed;
}

}  // namespace tidewater::test
