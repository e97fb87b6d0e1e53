// Clip volumes: their signed distances against geometry, the scene key, and the queries
// of a whole scene reporting the surface dry inside them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tidewater/clip_volume.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

TEST(ClipVolume, SignedDistancesAreTheShapesOwn) {
    const ClipVolume box = ClipVolume::box({10.0, 0.0, 0.0}, {2.0, 1.0, 0.5});
    EXPECT_DOUBLE_EQ(clip_distance(box, {10.0, 0.0, 0.0}), -0.5);  // nearest face: z
    EXPECT_DOUBLE_EQ(clip_distance(box, {13.0, 0.0, 0.0}), 1.0);
    EXPECT_NEAR(clip_distance(box, {13.0, 2.0, 0.0}), std::sqrt(2.0), 1e-12);  // past an edge
    // Turned a quarter about y, its long side lies along z.
    const ClipVolume turned =
        ClipVolume::box({0.0, 0.0, 0.0}, {2.0, 1.0, 0.5}, glm::angleAxis(0.5 * kPi, glm::dvec3(0.0, 1.0, 0.0)));
    EXPECT_LT(clip_distance(turned, {0.0, 0.0, 1.9}), 0.0);
    EXPECT_GT(clip_distance(turned, {1.9, 0.0, 0.0}), 0.0);
    const ClipVolume sphere = ClipVolume::sphere({0.0, 5.0, 0.0}, 2.0);
    EXPECT_DOUBLE_EQ(clip_distance(sphere, {0.0, 5.0, 0.0}), -2.0);
    EXPECT_DOUBLE_EQ(clip_distance(sphere, {3.0, 5.0, 0.0}), 1.0);
    // A capsule lying along x (its axis turned from y by a quarter about z).
    const ClipVolume capsule =
        ClipVolume::capsule({0.0, 0.0, 0.0}, 3.0, 1.0, glm::angleAxis(0.5 * kPi, glm::dvec3(0.0, 0.0, 1.0)));
    EXPECT_NEAR(clip_distance(capsule, {2.5, 0.0, 0.0}), -1.0, 1e-12);
    EXPECT_NEAR(clip_distance(capsule, {5.0, 0.0, 0.0}), 1.0, 1e-12);  // past its end cap
    EXPECT_NEAR(clip_distance(capsule, {0.0, 0.0, 2.0}), 1.0, 1e-12);
    const ClipVolume volumes[] = {box, sphere};
    EXPECT_TRUE(inside_any(volumes, {10.0, 0.5, 0.0}));
    EXPECT_FALSE(inside_any(volumes, {0.0, 0.0, 0.0}));
    EXPECT_FALSE(validate(ClipVolume::sphere({0.0, 0.0, 0.0}, -1.0), "v").ok());
    EXPECT_FALSE(validate(ClipVolume::box({0.0, NAN, 0.0}, {1.0, 1.0, 1.0}), "v").ok());
}

std::string scene_with(const std::string& clips) {
    return R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -10}},
      "ocean": {"waves": [{"direction": 0, "wavelength": 20, "amplitude": 0.3, "steepness": 0.5}]},
      "clip_volumes": )" +
           clips + "}";
}

/// Inside a clip volume the surface is dry and nothing is under it; beside it, wet.
TEST(ClipVolume, QueriesReportTheSurfaceDryInsideAScenesOrAHostsVolume) {
    auto scene = parse_scene(scene_with(R"([{"shape": "box", "center": [0, 0, 0], "half_extents": [3, 2, 1], "yaw": 90},
        {"shape": "capsule", "center": [40, 0, 0], "half_length": 2, "radius": 1.5}])"),
                             "c.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_EQ(scene->clip_volumes.size(), 2u);
    const double t = 2.0;
    // The box turned a quarter: 3 m along z, 1 m along x.
    EXPECT_FALSE(query_world_point(*scene, t, {0.0, 2.5}).surface.wet);
    EXPECT_TRUE(query_world_point(*scene, t, {2.5, 0.0}).surface.wet);
    EXPECT_FALSE(query_world_point(*scene, t, {40.5, 0.0}).surface.wet);
    EXPECT_TRUE(query_world_point(*scene, t, {43.0, 0.0}).surface.wet);
    // A host's sphere, and the submersion of a point in it and of one beside it.
    const ClipVolume sphere = ClipVolume::sphere({-20.0, 0.0, 0.0}, 2.0);
    QueryOptions options;
    options.clip_volumes = std::span<const ClipVolume>(&sphere, 1);
    const glm::dvec2 xz[] = {{-20.0, 0.5}, {-20.0, 3.0}};
    WorldPoint water[2];
    ASSERT_TRUE(query_world(*scene, t, xz, water, options).ok());
    EXPECT_FALSE(water[0].surface.wet);
    EXPECT_TRUE(water[1].surface.wet);
    EXPECT_EQ(water[0].body.kind, BodyKind::ocean);  // still the ocean's place, dry
    const glm::dvec3 points[] = {{-20.0, -1.0, 0.5}, {-20.0, -1.0, 3.0}};
    Submersion sub[2];
    ASSERT_TRUE(query_submersion(*scene, t, points, sub, options).ok());
    EXPECT_FALSE(sub[0].under);
    EXPECT_TRUE(sub[1].under);
    EXPECT_TRUE(query_world_point(*scene, t, {-20.0, 0.5}).surface.wet);  // without the host's volume
}

TEST(ClipVolume, BadVolumesAreRefusedNamingTheField) {
    auto refusal = [](const std::string& clips) {
        auto scene = parse_scene(scene_with(clips), "c.json");
        return scene ? std::string("(loaded)") : scene.error().message;
    };
    EXPECT_NE(refusal(R"([{"shape": "cone", "center": [0, 0, 0], "radius": 1}])").find("c.json: /clip_volumes/0/shape"),
              std::string::npos);
    EXPECT_NE(refusal(R"([{"shape": "sphere", "center": [0, 0, 0], "radius": -1}])").find("/clip_volumes/0/radius"),
              std::string::npos);
    EXPECT_NE(refusal(R"([{"shape": "box", "center": [0, 0, 0]}])").find("/clip_volumes/0/half_extents"),
              std::string::npos);
    EXPECT_NE(
        refusal(R"([{"shape": "box", "center": [0, 0], "half_extents": [1, 1, 1]}])").find("/clip_volumes/0/center"),
        std::string::npos);
    EXPECT_NE(
        refusal(R"([{"shape": "capsule", "center": [0, 0, 0], "radius": 1}])").find("/clip_volumes/0/half_length"),
        std::string::npos);
    EXPECT_NE(
        refusal(R"([{"shape": "sphere", "center": [0, 0, 0], "radius": 1, "yaw": 1e9}])").find("/clip_volumes/0/yaw"),
        std::string::npos);
    EXPECT_NE(refusal(R"({"shape": "sphere"})").find("/clip_volumes: expected an array"), std::string::npos);
}

}  // namespace
}  // namespace tidewater
