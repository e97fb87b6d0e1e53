// Clip volumes on lavapipe under the validation layer: an open hull floating in waves is
// dry inside, and a host's clip sphere and convex mesh remove the water where the CPU
// queries say the surface is dry.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "../clip_torus.hpp"
#include "render_fixture.hpp"

namespace tidewater {
namespace {

double largest_difference(Rgb a, Rgb b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

/// An open box 4 x 1.5 x 3 m floating with its rim 0.85 m over the rest level in waves
/// 0.25 m high (their crests reach up its walls): seen from above through its open top,
/// its inside with the hull clipping the water is the inside of the same box with the sea
/// 15 m below it (dry: no water surface, no light lost to water, no caustics), within
/// 2/255 on 99 % of those pixels; without its clip the sea fills it to the waterline.
TEST_F(RenderTest, AnOpenHullIsDryInside) {
    const std::string ocean =
        R"("ocean": {"waves": [{"direction": 30, "wavelength": 12, "amplitude": 0.25, "steepness": 0.5}]})";
    const Scene wet =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -20}}, )" + ocean + "}");
    const Scene dry =
        scene_from(R"({"version": 1, "water_level": -15, "terrain": {"flat": {"height": -20}}, )" + ocean + "}");
    const glm::dvec3 size(4.0, 1.5, 3.0), at(0.0, 0.1, 0.0);
    const HullMesh hull = HullMesh::open_box(size);
    render::FloatDraw hold{&hull, at, glm::dquat(1.0, 0.0, 0.0, 0.0), glm::vec3(0.8f, 0.75f, 0.6f),
                           ClipVolume::box(glm::dvec3(0.0), 0.5 * size)};
    render::FrameInfo frame;
    frame.time = 4.0;
    frame.camera.position = {1.0, 12.0, -6.0};
    frame.camera.target = {0.0, -0.65, 0.0};
    frame.camera.fov_y_deg = 40.0;
    frame.floats = std::span<const render::FloatDraw>(&hold, 1);
    const int w = 320, h = 240;
    const auto clipped = render(wet, frame, w, h);
    const auto reference = render(dry, frame, w, h);
    render::FloatDraw open = hold;
    open.clip.reset();
    frame.floats = std::span<const render::FloatDraw>(&open, 1);
    const auto flooded = render(wet, frame, w, h);
    ASSERT_GT(clipped.width, 0u);
    ASSERT_GT(reference.width, 0u);
    ASSERT_GT(flooded.width, 0u);
    // The pixels whose ray enters the box through its open top, 5 cm clear of the rim.
    const double rim = at.y + 0.5 * size.y;
    int inside = 0, same = 0, flooded_differs = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 d = test::pixel_ray(frame.camera, w, h, x, y);
            const glm::dvec3 p = frame.camera.position + d * ((rim - frame.camera.position.y) / d.y);
            if (std::abs(p.x - at.x) > 0.5 * size.x - 0.05 || std::abs(p.z - at.z) > 0.5 * size.z - 0.05) continue;
            ++inside;
            same += largest_difference(test::pixel(clipped, x, y), test::pixel(reference, x, y)) <= 2.0 / 255.0;
            flooded_differs +=
                largest_difference(test::pixel(flooded, x, y), test::pixel(reference, x, y)) > 8.0 / 255.0;
        }
    std::printf("open hull: %d pixels see its inside; with its clip %d as dry, without it %d show the sea\n", inside,
                same, flooded_differs);
    ASSERT_GT(inside, 2000);
    EXPECT_GE(same, 0.99 * inside);
    EXPECT_GT(flooded_differs, 0.5 * inside);
}

/// A host's clip sphere 3 m round a point of the rest surface: the pixels the frame changes
/// against the same frame without it are those whose surface point query_world, given the
/// same volume, reports dry (the surface found along each pixel's ray from the CPU's heights),
/// but for at most 4 % of them along the edge.
/// A host's clip volume removes the water where the CPU queries say the surface is dry:
/// rendered with and without it, the pixels that change are the pixels whose ray meets a
/// dry surface (fixed-point steps on the CPU's heights), within 4 % of them.
class ClipParity : public RenderTest {
  protected:
    void expect_dry_where_the_queries_say(const ClipVolume& volume, const char* name) {
        const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -8}},
            "ocean": {"waves": [{"direction": 10, "wavelength": 10, "amplitude": 0.08, "steepness": 0.4}]}})");
        render::FrameInfo frame;
        frame.time = 2.0;
        frame.camera.position = {0.0, 12.0, -14.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 50.0;
        const int w = 320, h = 240;
        const auto plain = render(scene, frame, w, h);
        frame.clip_volumes = std::span<const ClipVolume>(&volume, 1);
        const auto clipped = render(scene, frame, w, h);
        ASSERT_GT(plain.width, 0u);
        ASSERT_GT(clipped.width, 0u);
        EXPECT_EQ(renderer_->stats().clip_volumes, 1u);
        QueryOptions options;
        options.clip_volumes = frame.clip_volumes;
        int dry = 0, changed = 0, mismatched = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::dvec3 d = test::pixel_ray(frame.camera, w, h, x, y);
                if (d.y >= -0.05) continue;
                double t = -frame.camera.position.y / d.y;
                WorldPoint water;
                for (int i = 0; i < 6; ++i) {
                    const glm::dvec2 xz(frame.camera.position.x + t * d.x, frame.camera.position.z + t * d.z);
                    if (!query_world(scene, frame.time, std::span<const glm::dvec2>(&xz, 1),
                                     std::span<WorldPoint>(&water, 1), options))
                        FAIL();
                    t = (water.surface.height - frame.camera.position.y) / d.y;
                }
                const bool is_dry = !water.surface.wet;
                const bool is_changed =
                    largest_difference(test::pixel(plain, x, y), test::pixel(clipped, x, y)) > 2.0 / 255.0;
                dry += is_dry;
                changed += is_changed;
                mismatched += is_dry != is_changed;
            }
        std::printf("%s: %d pixels dry by the queries, %d changed in the frame, %d disagree\n", name, dry, changed,
                    mismatched);
        ASSERT_GT(dry, 1500);
        EXPECT_LE(mismatched, 0.04 * dry);
    }
};

TEST_F(ClipParity, AHostsClipSphereRemovesTheWaterWhereTheQueriesSayDry) {
    expect_dry_where_the_queries_say(ClipVolume::sphere({0.0, 0.0, 0.0}, 3.0), "clip sphere");
}

// A convex mesh (an octahedron 4 m from centre to corner, turned 30 degrees about y and
// 20 about x) through the frame's shared planes: the same parity.
TEST_F(ClipParity, AHostsConvexMeshRemovesTheWaterWhereTheQueriesSayDry) {
    const std::vector<glm::dvec3> corners = {{0, 4, 0}, {4, 0, 0}, {0, 0, 4}, {-4, 0, 0}, {0, 0, -4}, {0, -4, 0}};
    const std::vector<std::array<std::uint32_t, 3>> faces = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4},
                                                             {5, 1, 2}, {5, 2, 3}, {5, 3, 4}, {5, 4, 1}};
    const glm::dquat turn = glm::angleAxis(glm::radians(30.0), glm::dvec3(0.0, 1.0, 0.0)) *
                            glm::angleAxis(glm::radians(20.0), glm::dvec3(1.0, 0.0, 0.0));
    auto octahedron = ClipVolume::convex_mesh({0.0, 0.0, 0.0}, corners, faces, turn);
    ASSERT_TRUE(octahedron.ok()) << octahedron.error().message;
    expect_dry_where_the_queries_say(*octahedron, "convex clip volume");
}

// A ring from a distance texture (48 x 16 x 48 samples; concave, so no other shape makes
// it), tilted 15 degrees about x across the waves: the water goes where the tube cuts the
// surface and stays in the ring's hole, as the queries say.
TEST_F(ClipParity, AHostsDistanceTextureRemovesTheWaterWhereTheQueriesSayDry) {
    const test::ClipTorus ring;
    const auto texture = ring.texture({48, 16, 48});
    ASSERT_TRUE(texture);
    const ClipVolume tilted = ClipVolume::distance_texture(
        {0.0, 0.0, 0.0}, ring.half_extents(), texture, glm::angleAxis(glm::radians(15.0), glm::dvec3(1.0, 0.0, 0.0)));
    expect_dry_where_the_queries_say(tilted, "distance texture");
}

}  // namespace
}  // namespace tidewater
