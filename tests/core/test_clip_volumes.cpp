// Clip volumes: their signed distances against geometry, the scene key, and the queries
// of a whole scene reporting the surface dry inside them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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

/// A unit octahedron (its corners on the axes), wound outward.
const std::vector<glm::dvec3> kOctahedron = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
const std::vector<std::array<std::uint32_t, 3>> kOctahedronFaces = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4},
                                                                    {5, 1, 2}, {5, 2, 3}, {5, 3, 4}, {5, 4, 1}};

// A convex mesh clips inside its faces: the distance is the nearest face's inside, and
// outside it is in front of a face (never more than the true distance).
TEST(ClipVolume, AConvexMeshClipsInsideItsFaces) {
    std::vector<glm::dvec3> corners;
    for (const glm::dvec3& v : kOctahedron) corners.push_back(3.0 * v);
    auto made = ClipVolume::convex_mesh({5.0, 0.0, 0.0}, corners, kOctahedronFaces);
    ASSERT_TRUE(made.ok()) << made.error().message;
    const ClipVolume& octahedron = *made;
    ASSERT_EQ(octahedron.planes.size(), 8u);
    EXPECT_TRUE(validate(octahedron, "v").ok());
    // The centre is 3 / sqrt(3) from every face; a corner's neighbourhood inside and out.
    EXPECT_NEAR(clip_distance(octahedron, {5.0, 0.0, 0.0}), -std::sqrt(3.0), 1e-12);
    EXPECT_LT(clip_distance(octahedron, {7.9, 0.0, 0.0}), 0.0);
    EXPECT_GT(clip_distance(octahedron, {8.1, 0.0, 0.0}), 0.0);
    EXPECT_NEAR(clip_distance(octahedron, {5.0 + 2.0, 2.0, 2.0}), (6.0 - 3.0) / std::sqrt(3.0), 1e-12);
    // Between the corners, outside the faces (inside the box round them).
    EXPECT_GT(clip_distance(octahedron, {6.6, 1.6, 0.0}), 0.0);
    // Its queries: the surface is dry over its middle, wet beside it.
    auto scene = parse_scene(scene_with("[]"), "c.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    scene->clip_volumes.push_back(octahedron);
    const double t = 1.0;
    EXPECT_FALSE(query_world_point(*scene, t, {5.0, 0.0}).surface.wet);
    EXPECT_TRUE(query_world_point(*scene, t, {9.0, 0.0}).surface.wet);
    // A box's six faces as a convex mesh give the box's own distances inside.
    const ClipVolume box = ClipVolume::convex(
        {0.0, 0.0, 0.0}, {{1, 0, 0, 2}, {-1, 0, 0, 2}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 2, 1}, {0, 0, -1, 0.5}});
    EXPECT_DOUBLE_EQ(clip_distance(box, {0.0, 0.0, 0.0}), -0.5);  // the +z plane's normal was normalised
    EXPECT_DOUBLE_EQ(clip_distance(box, {3.0, 0.0, 0.0}), 1.0);
}

TEST(ClipVolume, AConvexMeshThatIsOpenConcaveOrFlatIsRefused) {
    auto refusal = [](std::vector<glm::dvec3> v, std::vector<std::array<std::uint32_t, 3>> t) {
        auto made = ClipVolume::convex_mesh({0.0, 0.0, 0.0}, v, t);
        return made ? std::string("(made)") : made.error().message;
    };
    auto open = kOctahedronFaces;
    open.pop_back();
    EXPECT_NE(refusal(kOctahedron, open).find("not closed"), std::string::npos);
    auto dented = kOctahedron;
    dented[0].y = -0.5;  // the top pushed in past the middle
    EXPECT_NE(refusal(dented, kOctahedronFaces).find("not convex"), std::string::npos);
    auto inward = kOctahedronFaces;
    for (auto& f : inward) std::swap(f[1], f[2]);
    EXPECT_NE(refusal(kOctahedron, inward).find("not convex"), std::string::npos);
    std::vector<glm::dvec3> flat = kOctahedron;
    for (auto& v : flat) v.y = 0.0;
    EXPECT_NE(refusal(flat, kOctahedronFaces).find("flat"), std::string::npos);
    auto out_of_range = kOctahedronFaces;
    out_of_range[0][1] = 99;
    EXPECT_NE(refusal(kOctahedron, out_of_range).find("out of range"), std::string::npos);
    EXPECT_FALSE(validate(ClipVolume::convex({0.0, 0.0, 0.0}, {{1, 0, 0, 1}}), "v").ok()) << "one plane";
    EXPECT_FALSE(
        validate(ClipVolume::convex({0.0, 0.0, 0.0}, {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}}), "v")
            .ok())
        << "a zero normal";
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
    // A convex volume: its mesh named where it fails.
    const std::string tetrahedron =
        R"("vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "triangles": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])";
    EXPECT_EQ(refusal(R"([{"shape": "convex", "center": [0, 0, 0], )" + tetrahedron + "}]"), "(loaded)");
    EXPECT_NE(refusal(R"([{"shape": "convex", "center": [0, 0, 0], "vertices": [[0, 0, 0]]}])")
                  .find("/clip_volumes/0/triangles"),
              std::string::npos);
    EXPECT_NE(refusal(R"([{"shape": "convex", "center": [0, 0, 0], "radius": 1, )" + tetrahedron + "}]")
                  .find("/clip_volumes/0/radius"),
              std::string::npos);
    EXPECT_NE(refusal(R"([{"shape": "convex", "center": [0, 0, 0], "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0],
                  [0, 0, 1]], "triangles": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 7]]}])")
                  .find("/clip_volumes/0/triangles/3"),
              std::string::npos);
    EXPECT_NE(refusal(R"([{"shape": "convex", "center": [0, 0, 0], "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0],
                  [0, 0, 1]], "triangles": [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]}])")
                  .find("not convex"),
              std::string::npos)
        << "wound inward";
    EXPECT_NE(refusal(R"([{"shape": "sphere", "center": [0, 0, 0], "radius": 1, )" + tetrahedron + "}]")
                  .find("/clip_volumes/0/vertices"),
              std::string::npos);
}

}  // namespace
}  // namespace tidewater
