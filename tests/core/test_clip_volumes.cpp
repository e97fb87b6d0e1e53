// Clip volumes: their signed distances against geometry, the scene key, and the queries
// of a whole scene reporting the surface dry inside them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "../clip_torus.hpp"
#include "test_helpers.hpp"
#include "tidewater/clip_volume.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/distance_texture_png.hpp"
#include "tidewater/detail/image_write.hpp"
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

// A distance texture is its samples, trilinear between them: a ring (concave: its hole is
// outside) sampled at 64 x 24 x 64 points from its exact distance. At the samples it is
// that distance; between them within what the grid resolves near the surface; past the box
// the box's nearest point's plus the way to it; turned with the volume.
TEST(ClipVolume, ADistanceTextureIsItsSamplesBlended) {
    const test::ClipTorus ring;
    const auto texture = ring.texture({64, 24, 64});
    ASSERT_TRUE(texture);
    const glm::dvec3 h = ring.half_extents();
    const ClipVolume v = ClipVolume::distance_texture({5.0, 1.0, -2.0}, h, texture);
    ASSERT_TRUE(validate(v, "v").ok());
    const glm::dvec3 step = 2.0 * h / (glm::dvec3(texture->size()) - 1.0);
    // A sample: (10, 7, 40).
    const glm::dvec3 sample = -h + step * glm::dvec3(10.0, 7.0, 40.0);
    EXPECT_NEAR(clip_distance(v, v.center + sample), ring.distance(sample), 1e-6);
    // Between samples, within 2 cm of the true distance wherever it is under 1 m.
    double worst = 0.0;
    int near_surface = 0;
    for (double x = -h.x; x <= h.x; x += 0.37)
        for (double y = -h.y; y <= h.y; y += 0.23)
            for (double z = -h.z; z <= h.z; z += 0.41) {
                const glm::dvec3 local(x, y, z);
                if (std::abs(ring.distance(local)) > 1.0) continue;
                ++near_surface;
                worst = std::max(worst, std::abs(clip_distance(v, v.center + local) - ring.distance(local)));
            }
    std::printf("distance texture: largest error %.4f m over %d points within 1 m of the ring\n", worst, near_surface);
    EXPECT_GT(near_surface, 500);
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(clip_distance(v, v.center + glm::dvec3(3.5, 0.0, 0.0)), -1.4);  // in the tube
    EXPECT_GT(clip_distance(v, v.center), 1.8);                               // in the hole, 2 m from the tube: outside
    // Past the box along x: the boundary's distance plus the way to it.
    const glm::dvec3 edge(h.x, 0.0, 0.0);
    EXPECT_NEAR(clip_distance(v, v.center + edge + glm::dvec3(2.0, 0.0, 0.0)), clip_distance(v, v.center + edge) + 2.0,
                1e-9);
    // Stood on edge (a quarter about x), the tube crosses y = 3.5 and not z = 3.5.
    const ClipVolume upright =
        ClipVolume::distance_texture({0.0, 0.0, 0.0}, h, texture, glm::angleAxis(0.5 * kPi, glm::dvec3(1.0, 0.0, 0.0)));
    EXPECT_LT(clip_distance(upright, {0.0, 3.5, 0.0}), -1.4);
    EXPECT_GT(clip_distance(upright, {0.0, 0.0, 3.5}), 0.0);
    // A texture is made valid or not at all.
    auto refused = [](glm::uvec3 size, std::vector<float> d) {
        auto made = DistanceTexture::create(size, std::move(d));
        return made ? std::string("(made)") : made.error().message;
    };
    EXPECT_NE(refused({1, 2, 2}, std::vector<float>(4, -1.0f)).find("1 samples along x"), std::string::npos);
    EXPECT_NE(refused({2, 2, 129}, std::vector<float>(516, -1.0f)).find("along z"), std::string::npos);
    EXPECT_NE(refused({2, 2, 2}, std::vector<float>(7, -1.0f)).find("7 distances"), std::string::npos);
    std::vector<float> with_nan(8, -1.0f);
    with_nan[5] = NAN;
    EXPECT_NE(refused({2, 2, 2}, with_nan).find("sample 5"), std::string::npos);
    EXPECT_NE(refused({2, 2, 2}, std::vector<float>(8, 1.0f)).find("nowhere inside"), std::string::npos);
    ClipVolume empty = v;
    empty.texture = nullptr;
    EXPECT_NE(validate(empty, "v").error().message.find("v/texture"), std::string::npos);
}

// The scene's "distance_texture" volume reads the ring from a 16-bit PNG (its slices stacked,
// distances over +-8 m: 0.24 mm a level): the queries find the tube dry and the hole wet.
TEST(ClipVolume, AScenesDistanceTextureClipsARingAndNotItsHole) {
    test::TempDir dir;
    const test::ClipTorus ring;
    const auto texture = ring.texture({48, 16, 48});
    ASSERT_TRUE(texture);
    ASSERT_TRUE(detail::write_distance_texture_png(dir.path / "ring.png", *texture, 8.0).ok());
    const glm::dvec3 h = ring.half_extents();
    const std::string clips = fmt::format(
        R"([{{"shape": "distance_texture", "center": [0, 0, 0], "half_extents": [{}, {}, {}],
             "file": "ring.png", "slices": 48, "range": 8}}])",
        h.x, h.y, h.z);
    auto scene = parse_scene(scene_with(clips), "c.json", dir.path);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_EQ(scene->clip_volumes.size(), 1u);
    const ClipVolume& read = scene->clip_volumes[0];
    ASSERT_EQ(read.shape, ClipVolume::Shape::distance_texture);
    EXPECT_EQ(read.texture->size(), glm::uvec3(48, 16, 48));
    double worst = 0.0;
    for (std::size_t i = 0; i < texture->distances().size(); ++i)
        worst = std::max(worst, std::abs(static_cast<double>(read.texture->distances()[i] - texture->distances()[i])));
    EXPECT_LE(worst, 8.0 / 65535.0 + 1e-6) << "a level of the PNG's 16 bits over +-8 m";
    const double t = 2.0;
    EXPECT_FALSE(query_world_point(*scene, t, {3.5, 0.0}).surface.wet);   // the tube
    EXPECT_FALSE(query_world_point(*scene, t, {0.0, -3.5}).surface.wet);  // across the ring
    EXPECT_TRUE(query_world_point(*scene, t, {0.0, 0.0}).surface.wet);    // its hole
    EXPECT_TRUE(query_world_point(*scene, t, {6.0, 0.0}).surface.wet);    // outside it
}

TEST(ClipVolume, ABadDistanceTextureIsRefusedNamingTheFileAndField) {
    test::TempDir dir;
    const auto texture = test::ClipTorus{}.texture({8, 4, 8});
    ASSERT_TRUE(texture);
    ASSERT_TRUE(detail::write_distance_texture_png(dir.path / "ring.png", *texture, 8.0).ok());
    ASSERT_TRUE(detail::write_png_rgba8(dir.path / "colour.png", 8, 32, std::vector<std::uint8_t>(8 * 32 * 4, 9)).ok());
    {
        std::ofstream corrupt(dir.path / "corrupt.png", std::ios::binary);
        corrupt << "\x89PNG\r\n\x1a\nnot really";
    }
    auto refusal = [&](const std::string& volume) {
        auto scene = parse_scene(scene_with("[" + volume + "]"), "c.json", dir.path);
        return scene ? std::string("(loaded)") : scene.error().message;
    };
    auto textured = [](const std::string& rest) {
        return R"({"shape": "distance_texture", "center": [0, 0, 0], "half_extents": [5, 2, 5], )" + rest + "}";
    };
    EXPECT_EQ(refusal(textured(R"("file": "ring.png", "slices": 8, "range": 8)")), "(loaded)");
    EXPECT_NE(refusal(textured(R"("file": "missing.png", "slices": 8, "range": 8)")).find("/clip_volumes/0/file"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "missing.png", "slices": 8, "range": 8)")).find("missing.png"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "ring.png", "slices": 5, "range": 8)")).find("is not 5 slices"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "ring.png", "slices": 1, "range": 8)")).find("/clip_volumes/0/slices"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "ring.png", "slices": 8)")).find("/clip_volumes/0/range"), std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "ring.png", "slices": 8, "range": -1)")).find("/clip_volumes/0/range"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "colour.png", "slices": 8, "range": 8)")).find("16-bit greyscale"),
              std::string::npos);
    EXPECT_NE(refusal(textured(R"("file": "corrupt.png", "slices": 8, "range": 8)")).find("corrupt.png"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"shape": "distance_texture", "center": [0, 0, 0], "file": "ring.png", "slices": 8,
                          "range": 8})")
                  .find("/clip_volumes/0/half_extents"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"shape": "sphere", "center": [0, 0, 0], "radius": 1, "file": "ring.png"})")
                  .find("/clip_volumes/0/file"),
              std::string::npos);
}

}  // namespace
}  // namespace tidewater
