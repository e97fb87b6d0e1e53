// A test coast for the tiled shore model: a round island on a 2048² heightmap 4 km
// square (about 2 m pixels), its beach at r = 800 m and a 1:6.7 slope to 160 m of water,
// under ocean_rolling, with a 512² shore model (8 m texels, tiles 256 m a side). The
// preset's longest waves feel the bottom out to about r = 1.3 km: a ring of tiles is
// stored, the open sea beyond it and the island's heart are not.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "tidewater/scene.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::test {

inline constexpr double kCoastBeachRadius = 800.0;  // m

/// Ground height at distance r from the island's centre, m.
inline double tiled_coast_height(double r) {
    return std::clamp(20.0 - 0.15 * (r - (kCoastBeachRadius - 20.0 / 0.15)), -160.0, 40.0);
}

/// `texels_per_wavelength`: the scene's shore.texels_per_wavelength (SceneShore).
inline Result<Scene> tiled_coast_scene(double texels_per_wavelength = kDefaultShoreTexelsPerWavelength) {
    constexpr int kPixels = 2048;
    constexpr double kSize = 4000.0, lo = -160.0, hi = 40.0;
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = kPixels;
    image->pixels.resize(static_cast<std::size_t>(kPixels) * kPixels);
    for (int j = 0; j < kPixels; ++j)
        for (int i = 0; i < kPixels; ++i) {
            const double x = (i / double(kPixels - 1) - 0.5) * kSize, z = (j / double(kPixels - 1) - 0.5) * kSize;
            const double h = tiled_coast_height(std::hypot(x, z));
            image->pixels[static_cast<std::size_t>(j) * kPixels + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::lround((h - lo) / (hi - lo) * 65535.0));
        }
    auto parsed = parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -160}},
        "ocean": "ocean_rolling", "shore": {"resolution": 512}})",
                              "tiled_coast");
    if (!parsed) return parsed.error();
    Scene scene = std::move(parsed).value();
    HeightmapTerrain map;
    map.file = "tiled_coast";
    map.size = {kSize, kSize};
    map.min_height = lo;
    map.max_height = hi;
    map.image = std::move(image);
    scene.terrain = Terrain(map);
    scene.shore.texels_per_wavelength = texels_per_wavelength;
    return scene;
}

}  // namespace tidewater::test
