// A small heightmap island with a shore for edit tests: 1 km at 4 m pixels, 20 m at its
// centre falling 1 m in 20 to the sea (shoreline at r = 400 m), on to a -40 m floor.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <memory>

#include "tidewater/scene.hpp"

namespace tidewater::test {

inline constexpr int kIslandPixels = 257;  // 4 m apart over 1024 m
inline constexpr double kIslandLow = -40.0, kIslandHigh = 30.0;

/// A mound of `bump` m (negative: a dip) and 40 m radius at `at`.
struct Mound {
    glm::dvec2 at{0.0};
    double bump = 0.0;
};

/// An island: 20 m at its centre falling 1 m in 20 to the sea (shoreline at r = 400 m),
/// on to the -40 m floor, with `mounds` on it.
inline std::shared_ptr<Gray16Image> island_pixels_with(std::initializer_list<Mound> mounds) {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = kIslandPixels;
    image->pixels.resize(static_cast<std::size_t>(kIslandPixels) * kIslandPixels);
    for (int j = 0; j < kIslandPixels; ++j)
        for (int i = 0; i < kIslandPixels; ++i) {
            const glm::dvec2 p{4.0 * i - 512.0, 4.0 * j - 512.0};
            double h = std::max(kIslandLow, 20.0 - 0.05 * glm::length(p));
            for (const Mound& m : mounds) {
                const double r = glm::length(p - m.at) / 40.0;
                if (r < 1.0) h += m.bump * (1.0 - r * r) * (1.0 - r * r);
            }
            image->pixels[static_cast<std::size_t>(j) * kIslandPixels + i] =
                static_cast<std::uint16_t>(std::lround((h - kIslandLow) / (kIslandHigh - kIslandLow) * 65535.0));
        }
    return image;
}

/// The island with one mound of `bump` m at `at` (none: the island alone).
inline std::shared_ptr<Gray16Image> island_pixels(glm::dvec2 at = {0.0, 0.0}, double bump = 0.0) {
    return island_pixels_with({Mound{at, bump}});
}

inline Scene island_scene(std::shared_ptr<Gray16Image> pixels) {
    auto parsed = parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -5}},
        "ocean": "ocean_rolling", "shore": {"resolution": 256}})",
                              "land edit");
    EXPECT_TRUE(parsed.ok()) << parsed.error().message;
    Scene scene = std::move(parsed).value();
    HeightmapTerrain map;
    map.size = glm::dvec2(4.0 * (kIslandPixels - 1));
    map.min_height = kIslandLow;
    map.max_height = kIslandHigh;
    map.image = std::move(pixels);
    scene.terrain = Terrain(map);
    return scene;
}

}  // namespace tidewater::test
