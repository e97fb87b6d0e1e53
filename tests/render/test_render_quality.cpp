// Quality tiers on lavapipe under the validation layer: each tier draws fewer water
// vertices and fragments than the one above it, `low` keeps a reference image of its
// own, the tier's shading is compiled into its pipelines, and an override out of range
// is refused when the renderer is made.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "../bowl_terrain.hpp"
#include "render_fixture.hpp"
#include "tidewater/detail/image_io.hpp"

namespace tidewater {
namespace {

struct TierFrame {
    render::RgbaImage image;
    render::PassInvocations water;
};

/// The mean and the spread of the luminance over columns [x0, x1) and rows [y0, y1).
std::pair<double, double> luminance_in(const render::RgbaImage& img, int x0, int x1, int y0, int y1) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++n) {
            const test::Rgb c = test::pixel(img, x, y);
            const double l = 0.3 * c.r + 0.6 * c.g + 0.1 * c.b;
            sum += l;
            sum2 += l * l;
        }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean))};
}

class QualityTest : public test::RenderTest {
  protected:
    /// The default scene from its camera at 3 s, through a renderer of `tier`.
    TierFrame render_tier(const Scene& scene, render::Quality tier, std::uint32_t w, std::uint32_t h,
                          const render::QualityOverrides& overrides = {},
                          render::DebugView view = render::DebugView::shaded) {
        render::FrameInfo frame = test::scene_camera_frame(scene, 3.0);
        frame.view = view;
        return render_tier(scene, frame, tier, w, h, overrides);
    }
    TierFrame render_tier(const Scene& scene, const render::FrameInfo& frame, render::Quality tier, std::uint32_t w,
                          std::uint32_t h, const render::QualityOverrides& overrides) {
        auto renderer = test::renderer_with(context(), scene, [&](render::RendererInitInfo& init) {
            init.quality = tier;
            init.quality_overrides = overrides;
        });
        if (!renderer) return {};
        auto target = render::OffscreenTarget::create(context(), w, h);
        EXPECT_TRUE(target.ok()) << target.error().message;
        if (!target.ok()) return {};
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
// shows more of it, as whitecaps linger (the `foam` view's mean at 320 x 180, 0.3534 against 0.3569).
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

// Caustics are the tier's choice: the ground under 3 m of water with short waves (3 m
// long, 12 cm high) shows the light they focus at `high`, and calm water's light where
// caustics are turned off (as at `low`): the spread of its luminance falls, its mean stays.
TEST_F(QualityTest, CausticsAreTheTiersChoice) {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 12.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.sun_direction = {0.0, 0.8, 0.6};  // behind the camera: no glitter in view
    const Scene shallow =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -3}}, )"
                   R"("ocean": {"waves": [{"direction": 0, "wavelength": 3, "amplitude": 0.06, "steepness": 0.3}]}})");
    auto luminance = [](const render::RgbaImage& img) { return luminance_in(img, 60, 260, 100, 170); };
    const TierFrame with = render_tier(shallow, frame, render::Quality::high, 320, 180, {});
    const TierFrame without = render_tier(shallow, frame, render::Quality::high, 320, 180, {.caustics = false});
    ASSERT_FALSE(with.image.pixels.empty());
    ASSERT_FALSE(without.image.pixels.empty());
    const auto [mean_with, spread_with] = luminance(with.image);
    const auto [mean_without, spread_without] = luminance(without.image);
    std::printf("the ground under 3 m: luminance %.4f +- %.4f with caustics, %.4f +- %.4f without\n", mean_with,
                spread_with, mean_without, spread_without);
    EXPECT_LT(spread_without, 0.5 * spread_with);
    EXPECT_NEAR(mean_without, mean_with, 0.01);
    EXPECT_FALSE(render::quality_settings(render::Quality::low)->caustics);
    EXPECT_TRUE(render::quality_settings(render::Quality::high)->caustics);
}

// A lake's bed is lit through the lake's own waves: under 2 m of a lake 30 m above the sea
// (a bowl in the hills, no ocean), seen from 6 m over the water, the ground's luminance
// spreads with caustics and not without them. Its mean keeps within 10 %: the gain is
// taken where the light enters, not where it lands, which over the lake's ripples
// (D k^2 A past 1) brightens the mean by the first-order model's known bias.
TEST_F(QualityTest, CausticsLightALakesBedFromItsOwnWaves) {
    auto parsed = test::bowl_lake_scene();
    ASSERT_TRUE(parsed) << parsed.error().message;
    auto scene = test::baked(*parsed);
    ASSERT_TRUE(scene) << scene.error().message;
    render::FrameInfo frame;
    frame.time = 2.0;
    frame.camera.position = {-226.0, 34.0, 0.0};
    frame.camera.target = {-232.0, 28.0, 0.0};  // the bed 2 m under the lake's level
    frame.camera.fov_y_deg = 40.0;
    frame.sun_direction = {0.3, 0.9, 0.0};  // behind the camera: no glitter in view
    const TierFrame with = render_tier(*scene, frame, render::Quality::high, 320, 180, {});
    const TierFrame without = render_tier(*scene, frame, render::Quality::high, 320, 180, {.caustics = false});
    ASSERT_FALSE(with.image.pixels.empty());
    ASSERT_FALSE(without.image.pixels.empty());
    auto luminance = [](const render::RgbaImage& img) { return luminance_in(img, 80, 240, 60, 150); };
    const auto [mean_with, spread_with] = luminance(with.image);
    const auto [mean_without, spread_without] = luminance(without.image);
    std::printf("a lake's bed under 2 m: luminance %.4f +- %.4f with caustics, %.4f +- %.4f without\n", mean_with,
                spread_with, mean_without, spread_without);
    EXPECT_LT(spread_without, 0.3 * spread_with);
    EXPECT_NEAR(mean_with / mean_without, 1.0, 0.10);
}

// The scene's reflection is the tier's choice: at `high` the water before the island
// mirrors its green slopes; told not to (as `low` is), the same water reflects the sky
// alone and turns bluer there. Elsewhere the picture is the same.
TEST_F(QualityTest, TheScenesReflectionIsTheTiersChoice) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const TierFrame mirrored = render_tier(*scene, render::Quality::high, 320, 180);
    const TierFrame sky_only = render_tier(*scene, render::Quality::high, 320, 180, {.scene_reflection = false});
    ASSERT_FALSE(mirrored.image.pixels.empty());
    ASSERT_FALSE(sky_only.image.pixels.empty());
    double blue_gain = 0.0;
    int changed = 0, pixels = 0;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x, ++pixels) {
            const test::Rgb a = test::pixel(mirrored.image, x, y), b = test::pixel(sky_only.image, x, y);
            const double d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
            if (d < 2.0 / 255.0) continue;
            ++changed;
            blue_gain += (b.b - b.g) - (a.b - a.g);
        }
    std::printf("scene reflection off: %d of %d pixels change, bluer by %.4f on average there\n", changed, pixels,
                changed > 0 ? blue_gain / changed : 0.0);
    EXPECT_GT(changed, pixels / 100) << "the island's reflection is drawn at high";
    EXPECT_LT(changed, pixels / 2) << "only the reflection changes";
    EXPECT_GT(blue_gain / std::max(changed, 1), 0.0) << "the sky replaces the green slopes";
    EXPECT_FALSE(render::quality_settings(render::Quality::low)->scene_reflection);
    EXPECT_TRUE(render::quality_settings(render::Quality::high)->scene_reflection);
}

// `ultra` shades the water of multisampled targets at every sample where the host enabled
// sampleRateShading, and per pixel otherwise (Renderer::quality() says which); another tier
// asked to by an override is refused where it cannot.
TEST_F(QualityTest, UltraShadesTheWaterPerSampleWhereItCan) {
    auto per_sample = [&](render::Quality tier, VkSampleCountFlagBits samples, bool feature,
                          const render::QualityOverrides& overrides = {}) -> Result<bool> {
        render::RendererInitInfo init;
        init.device = context();
        init.device.enabled_features.sampleRateShading = feature ? VK_TRUE : VK_FALSE;
        init.wireframe = false;
        init.samples = samples;
        init.quality = tier;
        init.quality_overrides = overrides;
        auto r = render::Renderer::create(init);
        if (!r) return r.error();
        return (*r)->quality().water_per_sample;
    };
    ASSERT_TRUE(context().enabled_features.sampleRateShading) << "lavapipe has sampleRateShading";
    const auto ultra4 = per_sample(render::Quality::ultra, VK_SAMPLE_COUNT_4_BIT, true);
    ASSERT_TRUE(ultra4.ok()) << ultra4.error().message;
    EXPECT_TRUE(*ultra4);
    const auto ultra1 = per_sample(render::Quality::ultra, VK_SAMPLE_COUNT_1_BIT, true);
    ASSERT_TRUE(ultra1.ok()) << ultra1.error().message;
    EXPECT_FALSE(*ultra1) << "single-sampled targets: per pixel";
    const auto ultra_no_feature = per_sample(render::Quality::ultra, VK_SAMPLE_COUNT_4_BIT, false);
    ASSERT_TRUE(ultra_no_feature.ok()) << ultra_no_feature.error().message;
    EXPECT_FALSE(*ultra_no_feature) << "without sampleRateShading: per pixel";
    const auto high4 = per_sample(render::Quality::high, VK_SAMPLE_COUNT_4_BIT, true);
    ASSERT_TRUE(high4.ok()) << high4.error().message;
    EXPECT_FALSE(*high4);
    const auto asked = per_sample(render::Quality::high, VK_SAMPLE_COUNT_1_BIT, true, {.water_per_sample = true});
    ASSERT_FALSE(asked.ok());
    EXPECT_NE(asked.error().message.find("quality_overrides.water_per_sample"), std::string::npos)
        << asked.error().message;
}

// `low`'s rings of coarser water (16 patches a side, each patch four times the area of
// `high`'s) still reach the horizon and leave no hole between them: from 400 m up, looking
// 7.6 degrees down at 640 x 360, the water's far edge is within 3 rows of the analytic
// horizon in every column, and no sky shows below it.
TEST_F(QualityTest, LowsCoarserRingsReachTheHorizonWithoutHoles) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    render::FrameInfo frame;
    frame.camera.position = {2000.0, 400.0, 0.0};
    frame.camera.target = {2500.0, 400.0 - 500.0 * std::tan(7.6 * kPi / 180.0), 0.0};
    frame.camera.fov_y_deg = 50.0;
    frame.time = 3.0;
    frame.view = render::DebugView::normals;  // water (0.5 + 0.5 n) against the sky's blue
    ASSERT_EQ(render::quality_settings(render::Quality::low)->far_field_ring_patches, 16);
    const TierFrame low = render_tier(*scene, frame, render::Quality::low, 640, 360, {});
    ASSERT_FALSE(low.image.pixels.empty());
    const double horizon = 180.0 - 180.0 * std::tan(7.6 * kPi / 180.0) / std::tan(25.0 * kPi / 180.0);
    int sky_below = 0;
    for (int x = 0; x < 640; ++x) {
        int top = -1;
        for (int y = 0; y < 360; ++y) {
            const test::Rgb c = test::pixel(low.image, x, y);
            if (top < 0 && c.g > 0.8 && c.g > c.b + 0.15) top = y;  // an upward normal: water
            if (y > horizon + 3.0 && c.b > c.g + 0.1) ++sky_below;
        }
        ASSERT_GE(top, 0) << "no water in column " << x;
        if (x % 48 == 16) {
            EXPECT_NEAR(top, horizon, 3.0) << "column " << x;
        }
    }
    EXPECT_EQ(sky_below, 0) << "sky between the rings";
}

// A wave the tier does not draw one by one is still in the picture as roughness: looking
// toward a low sun over a long swell and a shorter wave, with one wave drawn the heights
// lose the short wave, while the sun's glitter stays as wide as the short wave makes it
// (within a factor of 1.25; 29.5 against 28.8 pixels at 320 x 180), where dropping the
// wave narrows it by a third (18.4).
TEST_F(QualityTest, WavesNotDrawnOneByOneStayAsRoughness) {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 20.0, 0.0};
    frame.camera.target = {100.0, 0.0, 0.0};
    frame.sun_direction = glm::normalize(glm::dvec3(0.9, 0.3, 0.1));
    frame.time = 2.0;
    const std::string swell = R"({"direction": 0, "wavelength": 60, "amplitude": 0.6, "steepness": 0.3})";
    const std::string shorter = R"({"direction": 70, "wavelength": 12, "amplitude": 0.2, "steepness": 0.3})";
    auto sea = [](const std::string& waves) {
        return scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -60}}, )"
                          R"("ocean": {"waves": [)" +
                          waves + "]}}");
    };
    const Scene both = sea(swell + ", " + shorter), swell_only = sea(swell);
    constexpr int kW = 320, kH = 180;
    auto view = [&](const Scene& scene, render::DebugView v, const render::QualityOverrides& o) {
        render::FrameInfo f = frame;
        f.view = v;
        return render_tier(scene, f, render::Quality::high, kW, kH, o).image;
    };
    auto per_pixel = [](const render::RgbaImage& a, const render::RgbaImage& b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        return sum / (255.0 * static_cast<double>(a.pixels.size()));
    };
    // The glitter's width: the pixels of a row more than 0.1 brighter than its median,
    // averaged over the rows of the lower half (the water away from the bright far field).
    auto glitter_width = [](const render::RgbaImage& img) {
        double sum = 0.0;
        int rows = 0;
        for (int y = kH / 2 + 8; y < kH; ++y, ++rows) {
            std::vector<double> l(kW);
            for (int x = 0; x < kW; ++x) {
                const test::Rgb c = test::pixel(img, x, y);
                l[static_cast<std::size_t>(x)] = 0.3 * c.r + 0.6 * c.g + 0.1 * c.b;
            }
            std::vector<double> sorted = l;
            std::nth_element(sorted.begin(), sorted.begin() + kW / 2, sorted.end());
            const double median = sorted[kW / 2];
            sum += static_cast<double>(std::count_if(l.begin(), l.end(), [&](double v) { return v > median + 0.1; }));
        }
        return sum / rows;
    };
    const render::RgbaImage full = view(both, render::DebugView::height, {}),
                            one = view(both, render::DebugView::height, {.waves_drawn = 1}),
                            dropped = view(swell_only, render::DebugView::height, {});
    ASSERT_FALSE(full.pixels.empty() || one.pixels.empty() || dropped.pixels.empty());
    std::printf("heights: one wave drawn changes them by %.4f, dropping the short wave by %.4f\n", per_pixel(full, one),
                per_pixel(full, dropped));
    ASSERT_GT(per_pixel(full, dropped), 0.005) << "the short wave shows";
    EXPECT_GT(per_pixel(full, one), 0.5 * per_pixel(full, dropped)) << "the mesh loses the short wave";

    const double width_full = glitter_width(view(both, render::DebugView::shaded, {})),
                 width_one = glitter_width(view(both, render::DebugView::shaded, {.waves_drawn = 1})),
                 width_dropped = glitter_width(view(swell_only, render::DebugView::shaded, {}));
    std::printf("the glitter's width: %.1f px with both waves drawn, %.1f with one, %.1f without the short wave\n",
                width_full, width_one, width_dropped);
    ASSERT_LT(width_dropped, 0.75 * width_full) << "the short wave widens the glitter";
    EXPECT_GT(width_one, width_full / 1.25) << "its slope variance stays";
    EXPECT_LT(width_one, width_full * 1.25);
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
