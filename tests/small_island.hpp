// A small procedural island with a 64-texel shore model: the scene tests bake when they
// need a whole bake quickly (well under a second).
#pragma once

namespace tidewater::test {

inline constexpr const char* kSmallIsland = R"({"version": 1, "name": "small island", "water_level": 0,
    "terrain": {"island": {"seed": 7, "radius": 300, "height": 40, "seabed": -30}},
    "ocean": "ocean_rolling", "shore": {"resolution": 64}})";

}  // namespace tidewater::test
