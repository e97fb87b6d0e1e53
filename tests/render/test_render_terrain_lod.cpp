// The terrain's level of detail on the device (lavapipe, validation on): a 4 km heightmap
// at 1 m shows its 2 m ditches from 100 m, a low view across it shows no crack between
// levels, and a small memory budget draws it coarser instead of failing.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../island_heightmap.hpp"
#include "render_fixture.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

constexpr int kSide = 4096;                                                 // pixels, 1 m apart
constexpr double kDitchEvery = 40.0, kDitchWidth = 2.0, kDitchDepth = 1.5;  // m

/// A 4 km plain 5 m above the sea with rolling hills to the north (z < -300 m), rough
/// ground to the south-east (x > 300 m, z > 300 m: bumps of 3 to 16 m) and 2 m ditches along
/// z every 40 m (centred on x = 20 + 40k).
Scene ditch_scene() {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = kSide;
    image->pixels.resize(static_cast<std::size_t>(kSide) * kSide);
    const double lo = -5.0, hi = 45.0;  // up to 5 + 14 m on the rough ground, 5 + 24 m on the hills
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const double x = i - 0.5 * (kSide - 1), z = j - 0.5 * (kSide - 1);
            double h = 5.0;
            const double along = std::abs(std::remainder(x - 20.0, kDitchEvery));
            if (along < 0.5 * kDitchWidth) h -= kDitchDepth * 0.5 * (1.0 + std::cos(2.0 * M_PI * along / kDitchWidth));
            if (x > 300.0 && z > 300.0)
                h += 3.0 * (std::sin(x / 2.3) * std::sin(z / 1.7) + 1.0) +
                     4.0 * (std::sin(x / 7.9 + 1.0) * std::cos(z / 11.3) + 1.0);
            if (z < -300.0)
                h += 12.0 * std::min(1.0, (-300.0 - z) / 400.0) * (1.0 + std::sin(x / 90.0) * std::cos(z / 70.0));
            image->pixels[static_cast<std::size_t>(j) * kSide + i] =
                static_cast<std::uint16_t>(std::lround((h - lo) / (hi - lo) * 65535.0));
        }
    auto parsed = parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -5}},
        "ocean": "pool_calm", "shore": {"enabled": false}})",
                              "ditches");
    EXPECT_TRUE(parsed.ok()) << parsed.error().message;
    Scene scene = std::move(parsed).value();
    HeightmapTerrain map;
    map.size = glm::dvec2(kSide - 1);
    map.min_height = lo;
    map.max_height = hi;
    map.image = image;
    scene.terrain = Terrain(map);
    return scene;
}

render::FrameInfo frame_at(glm::dvec3 eye, glm::dvec3 at, render::DebugView view) {
    render::FrameInfo frame;
    frame.camera.position = eye;
    frame.camera.target = at;
    frame.camera.fov_y_deg = 55.0;
    frame.view = view;
    frame.time = 1.0;
    return frame;
}

// From 100 m up, every 2 m ditch in the middle of the view shows in the terrain's normals
// (its walls tilt the normal's x), and the plain between them is flat: the heightmap is
// drawn at its own 1 m, not at the 10 m a whole-extent mesh of 384 cells would give.
TEST_F(RenderTest, TwoMetreDitchesShowFromAHundredMetres) {
    const Scene scene = ditch_scene();
    const auto frame = frame_at({0.0, 100.0, 0.0}, {0.0, 0.0, 1.0}, render::DebugView::normals);
    const render::RgbaImage img = render(scene, frame, 640, 360);
    ASSERT_EQ(img.width, 640u);
    const int row = 180;
    int ditches = 0, shown = 0, flats = 0, flat_ok = 0;
    for (double x = -260.0; x <= 260.0; x += kDitchEvery / 2) {
        const bool ditch = std::abs(std::remainder(x - 20.0, kDitchEvery)) < 1.0;
        const auto p = test::project(frame.camera, 640, 360, {x, 5.0, 0.0});
        if (!p || p->x < 8 || p->x > 631) continue;
        double strongest = 0.0;
        for (int dx = -6; dx <= 6; ++dx)
            strongest = std::max(strongest, std::abs(test::pixel(img, p->x + dx, row).r - 0.5));  // n.x * 0.5
        if (ditch) {
            ++ditches;
            shown += strongest > 0.15 ? 1 : 0;
        } else {
            ++flats;
            flat_ok += strongest < 0.03 ? 1 : 0;
        }
    }
    EXPECT_GE(ditches, 4);
    EXPECT_EQ(shown, ditches) << "ditches seen in the normals";
    EXPECT_EQ(flat_ok, flats) << "flat plain between them";
}

// Low over the plain, looking at the hills: many levels meet in view, and below the
// horizon every pixel is ground (a crack between levels would show the sky through it).
TEST_F(RenderTest, TerrainLevelsMeetWithoutCracks) {
    const Scene scene = ditch_scene();
    for (const auto& [eye, at] : {std::pair{glm::dvec3(30.0, 12.0, 400.0), glm::dvec3(0.0, 10.0, -800.0)},
                                  std::pair{glm::dvec3(-500.0, 60.0, 300.0), glm::dvec3(200.0, 0.0, -600.0)}}) {
        const auto frame = frame_at(eye, at, render::DebugView::shaded);
        const render::RgbaImage img = render(scene, frame, 480, 270);
        int sky_below = 0;
        for (int j = 170; j < 270; ++j)
            for (int i = 0; i < 480; ++i) sky_below += is_sky(test::pixel(img, i, j)) ? 1 : 0;
        EXPECT_EQ(sky_below, 0) << "sky showing through the ground";
        const render::RendererStats stats = renderer_->stats();
        EXPECT_GT(stats.terrain_triangles, 20000u);
    }
}

/// One frame through a renderer of its own whose memory budget is `budget` bytes.
struct BudgetFrame {
    render::RgbaImage image;
    render::RendererStats stats;
};
BudgetFrame render_within_budget(const render::DeviceContext& device, const Scene& scene,
                                 const render::FrameInfo& frame, std::uint64_t budget, std::uint32_t w,
                                 std::uint32_t h) {
    BudgetFrame out;
    auto renderer = test::renderer_within_budget(device, scene, budget);
    if (!renderer) return out;
    auto target = render::OffscreenTarget::create(device, w, h);
    EXPECT_TRUE(target.ok());
    if (!target.ok()) return out;
    auto img = (*target)->render(*renderer, frame);
    EXPECT_TRUE(img.ok()) << img.error().message;
    if (!img.ok()) return out;
    out.image = std::move(img).value();
    out.stats = renderer->stats();
    return out;
}

// A budget of 16 MiB leaves 8 MiB for the height texture: the 4096² heightmap (32 MiB) is
// drawn from every other pixel, without a validation message, and the stats say so.
TEST_F(RenderTest, ASmallMemoryBudgetDrawsCoarserTerrain) {
    const Scene scene = ditch_scene();
    const auto frame = frame_at({0.0, 100.0, 300.0}, {0.0, 0.0, 0.0}, render::DebugView::shaded);
    render(scene, frame, 160, 90);
    EXPECT_GE(renderer_->stats().terrain_bytes, 2ull * kSide * kSide);

    const BudgetFrame small = render_within_budget(context(), scene, frame, 16ull << 20, 160, 90);
    ASSERT_EQ(small.image.width, 160);
    EXPECT_LE(small.stats.terrain_bytes, 8ull << 20);
    EXPECT_GT(small.stats.terrain_bytes, 2ull << 20);
    int land = 0;
    for (int j = 45; j < 90; ++j)
        for (int i = 0; i < 160; ++i) land += is_land(test::pixel(small.image, i, j)) ? 1 : 0;
    EXPECT_GT(land, 160 * 45 / 2) << "the coarser terrain is drawn";

    render::RendererInitInfo init;
    init.device = context();
    init.gpu_memory_budget = 1ull << 20;
    auto refused = render::Renderer::create(init);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("gpu_memory_budget"), std::string::npos);
}

// The shore fields take the other half of the budget: the default island's (24 waves at
// 256², its tiles and its tarn's) need more than 16 MiB, so under a 16 MiB budget they are
// drawn from every k-th texel. The surf is still there, and the frame stays close to the full one.
TEST_F(RenderTest, ASmallMemoryBudgetDrawsCoarserShoreFields) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const render::FrameInfo frame = test::scene_camera_frame(*scene, 3.0);
    const render::RgbaImage full = render(*scene, frame, 320, 180);
    EXPECT_EQ(renderer_->stats().shore_stride, 1u);
    EXPECT_GT(renderer_->stats().shore_bytes, 16ull << 20);
    std::printf("shore fields: %.1f MiB\n", renderer_->stats().shore_bytes / 1048576.0);

    const BudgetFrame small = render_within_budget(context(), *scene, frame, 16ull << 20, 320, 180);
    ASSERT_EQ(small.image.width, 320);
    const render::RendererStats& stats = small.stats;
    EXPECT_GE(stats.shore_stride, 2u);
    EXPECT_LE(stats.shore_stride, 4u);
    EXPECT_LE(stats.shore_bytes, 8ull << 20);
    const double diff = test::mean_difference(full, small.image);
    std::printf("shore fields at stride %u (%.1f MiB): mean difference %.4f\n", stats.shore_stride,
                stats.shore_bytes / 1048576.0, diff);
    EXPECT_GT(diff, 0.0);
    EXPECT_LT(diff, 0.03);
}

/// `scene` with its heightmap raised by up to `height` m over a disc of `radius` m at xz.
Scene with_mound(const Scene& scene, glm::dvec2 at, double radius, double height) {
    auto map = std::get<HeightmapTerrain>(scene.terrain.shape());
    auto image = std::make_shared<Gray16Image>(*map.image);
    const glm::dvec2 pixel = map.size / glm::dvec2(image->width - 1, image->height - 1);
    const glm::dvec2 origin = map.center - 0.5 * map.size;
    for (int j = 0; j < image->height; ++j)
        for (int i = 0; i < image->width; ++i) {
            const double r = glm::length(origin + pixel * glm::dvec2(i, j) - at) / radius;
            if (r >= 1.0) continue;
            auto& px = image->pixels[static_cast<std::size_t>(j) * image->width + i];
            px = static_cast<std::uint16_t>(
                std::min(65535.0, px + height * (1.0 - r * r) * 65535.0 / (map.max_height - map.min_height)));
        }
    map.image = std::move(image);
    Scene edited = scene;
    edited.terrain = Terrain(map);
    return edited;
}

// A brush stroke on a 4 km heightmap drawn: set_scene writes the texels under it alone
// (a few kB of the 32 MiB texture), and the frame is the one a renderer given the edited
// scene afresh draws, pixel for pixel.
TEST_F(RenderTest, ABrushStrokeIsWrittenWhereItChanged) {
    const Scene scene = ditch_scene();
    const auto frame = frame_at({0.0, 60.0, -60.0}, {0.0, 0.0, 60.0}, render::DebugView::shaded);
    // set_scene's time is printed for the record (not asserted): the whole upload, then the stroke's.
    auto seconds = [&](const Scene& s) {
        const auto t0 = std::chrono::steady_clock::now();
        EXPECT_TRUE(renderer_->set_scene(s).ok());
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    const double anew = seconds(scene);
    const std::uint64_t whole = renderer_->stats().scene_upload_bytes;
    EXPECT_GE(whole, 2ull * kSide * kSide) << "the first upload writes the whole texture";
    const render::RgbaImage before = render(scene, frame, 160, 90);

    const Scene stroke = with_mound(scene, {0.0, 60.0}, 15.0, 3.0);
    const double in_place = seconds(stroke);
    const std::uint64_t written = renderer_->stats().scene_upload_bytes;
    std::printf(
        "set_scene of the 4096^2 heightmap: %.3f s whole, %.4f s for a stroke, which wrote %llu bytes of %llu\n", anew,
        in_place, static_cast<unsigned long long>(written), static_cast<unsigned long long>(whole));
    const render::RgbaImage after = render(stroke, frame, 160, 90);
    EXPECT_GT(written, 0u);
    EXPECT_LE(written, 2u * 40u * 40u) << "the texels within the stroke's 15 m and a pixel around it";
    EXPECT_GT(test::mean_difference(before, after), 0.0) << "the mound shows";
    const BudgetFrame fresh =
        render_within_budget(context(), stroke, frame, render::RendererInitInfo{}.gpu_memory_budget, 160, 90);
    EXPECT_EQ(test::mean_difference(after, fresh.image), 0.0) << "the same frame as a fresh upload's";

    // A stroke past the texture's height range is uploaded whole.
    const Scene tall = with_mound(scene, {0.0, 60.0}, 15.0, 44.0);
    render(tall, frame, 160, 90);
    EXPECT_GE(renderer_->stats().scene_upload_bytes, 2ull * kSide * kSide);
}

// The same stroke through bake_scene, on an island with a shore: the re-bake shares the
// shore model's tiles away from the stroke, and set_scene writes the stroke's texels and
// the shore tiles under it, a few per cent of what the first upload wrote; the frame is a
// fresh upload's. Then a stroke on the seabed: the tiles its waves' windows reach (the
// rays alone: with the march, an edit under the water re-bakes the whole model).
TEST_F(RenderTest, ARebakedStrokeIsWrittenWhereItChanged) {
    auto rays_only = [](Scene scene) {
        scene.shore.diffraction = false;
        return scene;
    };
    auto first = bake_scene(rays_only(test::island_scene(test::island_pixels())));
    ASSERT_TRUE(first.ok()) << first.error().message;
    const auto frame = frame_at({-150.0, 120.0, -300.0}, {250.0, 0.0, 0.0}, render::DebugView::shaded);
    const render::RgbaImage before = render(**first, frame, 160, 90);
    const std::uint64_t whole = renderer_->stats().scene_upload_bytes;
    ASSERT_GT(renderer_->stats().shore_bytes, 0u);

    SceneBakeOptions options;
    options.previous = *first;
    auto stroke = bake_scene(rays_only(test::island_scene(test::island_pixels({250.0, 0.0}, 3.0))), options);
    ASSERT_TRUE(stroke.ok()) << stroke.error().message;
    ASSERT_TRUE((*stroke)->bake->reused.ocean_shore_land_edit);
    const render::RgbaImage after = render(**stroke, frame, 160, 90);
    const std::uint64_t written = renderer_->stats().scene_upload_bytes;
    std::printf("a re-baked stroke wrote %llu bytes of the first upload's %llu\n",
                static_cast<unsigned long long>(written), static_cast<unsigned long long>(whole));
    EXPECT_GT(written, 0u);
    EXPECT_LT(written, whole / 20);
    EXPECT_GT(test::mean_difference(before, after), 0.0) << "the mound shows";
    const BudgetFrame fresh =
        render_within_budget(context(), **stroke, frame, render::RendererInitInfo{}.gpu_memory_budget, 160, 90);
    EXPECT_EQ(test::mean_difference(after, fresh.image), 0.0) << "the same frame as a fresh upload's";

    // A stroke on the seabed of the first island (a shoal in 4.75 m of water): the waves
    // re-baked where it reaches, and only those tiles written (the drawn model shares the
    // rest with the first bake too).
    const auto at_shoal = frame_at({100.0, 60.0, 100.0}, {350.0, 0.0, 350.0}, render::DebugView::shaded);
    const render::RgbaImage before_shoal = render(**stroke, at_shoal, 160, 90);
    auto shoal = bake_scene(rays_only(test::island_scene(test::island_pixels({350.0, 350.0}, 2.0))), options);
    ASSERT_TRUE(shoal.ok()) << shoal.error().message;
    ASSERT_TRUE((*shoal)->bake->reused.ocean_shore_water_edit);
    const render::RgbaImage after_shoal = render(**shoal, at_shoal, 160, 90);
    const std::uint64_t shoal_written = renderer_->stats().scene_upload_bytes;
    std::printf("a re-baked stroke on the seabed wrote %llu bytes of the first upload's %llu\n",
                static_cast<unsigned long long>(shoal_written), static_cast<unsigned long long>(whole));
    EXPECT_GT(shoal_written, 0u);
    EXPECT_LT(shoal_written, whole / 2);
    EXPECT_GT(test::mean_difference(before_shoal, after_shoal), 0.0) << "the waves over the shoal change";
    const BudgetFrame fresh_shoal =
        render_within_budget(context(), **shoal, at_shoal, render::RendererInitInfo{}.gpu_memory_budget, 160, 90);
    EXPECT_EQ(test::mean_difference(after_shoal, fresh_shoal.image), 0.0) << "the same frame as a fresh upload's";
}

}  // namespace
}  // namespace tidewater
