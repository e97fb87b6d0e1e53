// Quality tiers on lavapipe under the validation layer: each tier draws fewer water
// vertices and fragments than the one above it, `low` keeps a reference image of its
// own, the tier's shading is compiled into its pipelines, and an override out of range
// is refused when the renderer is made.
#include <cstdio>
#include <filesystem>

#include "render_fixture.hpp"
#include "tidewater/detail/image_io.hpp"

namespace tidewater {
namespace {

struct TierFrame {
    render::RgbaImage image;
    render::PassInvocations water;
};

class QualityTest : public test::RenderTest {
  protected:
    /// The default scene from its camera at 3 s, through a renderer of `tier`.
    TierFrame render_tier(const Scene& scene, render::Quality tier, std::uint32_t w, std::uint32_t h,
                          const render::QualityOverrides& overrides = {},
                          render::DebugView view = render::DebugView::shaded) {
        auto renderer = test::renderer_with(context(), scene, [&](render::RendererInitInfo& init) {
            init.quality = tier;
            init.quality_overrides = overrides;
        });
        if (!renderer) return {};
        auto target = render::OffscreenTarget::create(context(), w, h);
        EXPECT_TRUE(target.ok()) << target.error().message;
        if (!target.ok()) return {};
        render::FrameInfo frame = test::scene_camera_frame(scene, 3.0);
        frame.view = view;
        auto img = (*target)->render(*renderer, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        auto timings = renderer->timings(frame.frame_index);
        EXPECT_TRUE(timings.ok()) << timings.error().message;
        if (!img.ok() || !timings.ok()) return {};
        EXPECT_TRUE(timings->invocations_counted) << "lavapipe has pipelineStatisticsQuery";
        return {std::move(img).value(), timings->water_invocations};
    }
};

// Ultra down to low: fewer tessellated vertices each step, and no more fragments; `low`
// shades at most 60% of ultra's water fragments (small triangles shade whole 2x2 quads).
TEST_F(QualityTest, EachTierDrawsFewerWaterVerticesThanTheOneAbove) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    constexpr std::uint32_t kW = 320, kH = 180;
    const render::Quality tiers[] = {render::Quality::ultra, render::Quality::high, render::Quality::medium,
                                     render::Quality::low};
    render::PassInvocations above{}, ultra{};
    for (const render::Quality tier : tiers) {
        const TierFrame f = render_tier(*scene, tier, kW, kH);
        ASSERT_FALSE(f.image.pixels.empty()) << render::quality_name(tier);
        const double per_pixel = static_cast<double>(f.water.fragment) / (kW * kH);
        std::printf("%-6s water: %llu tessellated vertices, %llu primitives, %llu fragments (%.2f per pixel)\n",
                    std::string(render::quality_name(tier)).c_str(),
                    static_cast<unsigned long long>(f.water.tessellation_evaluation),
                    static_cast<unsigned long long>(f.water.primitives),
                    static_cast<unsigned long long>(f.water.fragment), per_pixel);
        if (tier != render::Quality::ultra) {
            EXPECT_LT(f.water.tessellation_evaluation, above.tessellation_evaluation) << render::quality_name(tier);
            EXPECT_LE(f.water.fragment, above.fragment) << render::quality_name(tier);
        }
        if (tier == render::Quality::ultra) ultra = f.water;
        if (tier == render::Quality::low) {
            EXPECT_LT(static_cast<double>(f.water.fragment), 0.6 * static_cast<double>(ultra.fragment));
        }
        above = f.water;
    }
}

// `low` has a reference image of its own (TIDEWATER_UPDATE_REFERENCES=1 rewrites it), held
// to the same tolerance as the default tier's (test_render_sky_terrain.cpp).
TEST_F(QualityTest, LowTierMatchesItsReferenceImage) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const TierFrame f = render_tier(*scene, render::Quality::low, 320, 180);
    ASSERT_FALSE(f.image.pixels.empty());
    const std::filesystem::path path = std::filesystem::path(TIDEWATER_REFERENCE_DIR) / "default_shaded_low.png";
    if (std::getenv("TIDEWATER_UPDATE_REFERENCES")) {
        ASSERT_TRUE(detail::write_png_rgba8(path, f.image.width, f.image.height, f.image.pixels).ok());
        return;
    }
    auto reference = detail::read_png_rgba8(path);
    ASSERT_TRUE(reference.ok()) << reference.error().message << " (TIDEWATER_UPDATE_REFERENCES=1 makes it)";
    const test::ImageDifference d = test::image_difference(f.image, *reference);
    std::printf("reference %s: mean difference %.4f, 99th percentile %.4f\n", path.filename().c_str(), d.mean, d.p99);
    EXPECT_LT(d.mean, 0.02);
    EXPECT_LT(d.p99, 0.10);
}

// The tier's shading is compiled into its pipelines (specialization constants): `low`
// shows only the fresh crest foam, and the same tier told to show the foam's four lags
// shows more of it, as whitecaps linger (the `foam` view's mean at 320 x 180, 0.3543 against 0.3580).
TEST_F(QualityTest, TheFoamRemembersAsManyLagsAsTheTierShows) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto mean_foam = [](const render::RgbaImage& img) {
        double sum = 0.0;
        for (std::size_t i = 0; i < img.pixels.size(); i += 4) sum += img.pixels[i];
        return sum / (255.0 * static_cast<double>(img.pixels.size() / 4));
    };
    const TierFrame fresh = render_tier(*scene, render::Quality::low, 320, 180, {}, render::DebugView::foam);
    const TierFrame lingering =
        render_tier(*scene, render::Quality::low, 320, 180, {.foam_lags = 4}, render::DebugView::foam);
    ASSERT_FALSE(fresh.image.pixels.empty());
    ASSERT_FALSE(lingering.image.pixels.empty());
    std::printf("low's foam: %.4f fresh only, %.4f with four lags\n", mean_foam(fresh.image),
                mean_foam(lingering.image));
    EXPECT_GT(mean_foam(lingering.image), mean_foam(fresh.image) + 1e-3);
}

// An override out of range fails create() with an error that names it.
TEST_F(QualityTest, AnOverrideOutOfRangeIsRefused) {
    render::RendererInitInfo init;
    init.device = context();
    init.wireframe = false;
    init.quality_overrides.water_pixels_per_vertex = 0.0;
    auto r = render::Renderer::create(init);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::invalid_argument);
    EXPECT_NE(r.error().message.find("water_pixels_per_vertex"), std::string::npos) << r.error().message;
    init.quality_overrides.water_pixels_per_vertex = 5.0;
    init.quality = render::Quality::low;
    auto made = render::Renderer::create(init);
    ASSERT_TRUE(made.ok()) << made.error().message;
    EXPECT_EQ((*made)->quality().water_pixels_per_vertex, 5.0);
}

}  // namespace
}  // namespace tidewater
