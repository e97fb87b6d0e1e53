// The view from under a body's surface on lavapipe under the validation layer: no sky
// but through the surface, Snell's window, the seabed fading as Beer–Lambert says, and
// the renderer's answer for its camera the same as query_submersion's.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "render_fixture.hpp"

namespace tidewater {
namespace {

/// The default scene seen level from 3 m under the sea (the issue's view, 9 m over the
/// seabed) and from 15 m (13 m over it, further out), and looking 50 degrees up from 3 m: the frame is
/// drawn from under the surface, as query_submersion says of the camera, and no pixel shows
/// the sky's own colour. (Drawn as from the air, the upper half of the level view was sky.)
TEST_F(RenderTest, UnderTheSeaNoPixelShowsTheSkyButThroughTheSurface) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    struct View {
        glm::dvec3 position, target;
    };
    for (const View& view :
         {View{{900.0, -3.0, 300.0}, {700.0, -6.0, 100.0}}, View{{1300.0, -15.0, 1200.0}, {1100.0, -18.0, 900.0}},
          View{{900.0, -3.0, 300.0}, {880.0, -3.0 + 20.0 * std::tan(0.87), 300.0}}}) {
        render::FrameInfo frame;
        frame.camera.position = view.position;
        frame.camera.target = view.target;
        frame.time = 3.0;
        const auto img = render(*scene, frame);
        ASSERT_GT(img.width, 0u);
        Submersion asked;
        ASSERT_TRUE(query_submersion(*scene, frame.time, std::span<const glm::dvec3>(&view.position, 1),
                                     std::span<Submersion>(&asked, 1))
                        .ok());
        const Submersion drawn = renderer_->stats().camera;
        EXPECT_TRUE(asked.under);
        EXPECT_EQ(drawn.under, asked.under);
        EXPECT_EQ(drawn.body, asked.body);
        EXPECT_DOUBLE_EQ(drawn.depth, asked.depth);
        int sky = 0;
        for (int y = 0; y < static_cast<int>(img.height); ++y)
            for (int x = 0; x < static_cast<int>(img.width); ++x) sky += is_sky(test::pixel(img, x, y));
        const bool up = view.target.y > view.position.y;
        std::printf("from %.0f m under, %s: %d sky-coloured pixels\n", -view.position.y, up ? "looking up" : "level",
                    sky);
        if (!up) {
            EXPECT_EQ(sky, 0);
        }
        if (up) {
            // Looking up, the sky shows through Snell's window only: never more than 60
            // degrees from the zenith (48.6 degrees, widened by the waves' slopes).
            int outside = 0, inside = 0;
            for (int y = 0; y < static_cast<int>(img.height); ++y)
                for (int x = 0; x < static_cast<int>(img.width); ++x) {
                    const double zenith = std::acos(test::pixel_ray(frame.camera, img.width, img.height, x, y).y);
                    if (!is_sky(test::pixel(img, x, y))) continue;
                    if (zenith > 60.0 * kPi / 180.0) ++outside;
                    if (zenith < 40.0 * kPi / 180.0) ++inside;
                }
            EXPECT_EQ(outside, 0);
            EXPECT_GT(inside, 1000) << "the sky through the window";
        }
    }
}

/// Snell's window from below calm water (a 1 mm swell) over a deep, dark bottom, looking
/// 60 degrees up from 5 m under: the sky is seen within 48.6 degrees of the zenith
/// (asin(1 / 1.333)) and outside it the surface reflects the water below. The window's edge,
/// where the brightness falls half-way from the sky's to the water's, lies within a degree
/// and a half of it.
TEST_F(RenderTest, SnellsWindowFromBelowIsFortyEightAndAHalfDegrees) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -300}},
        "ocean": {"waves": [{"direction": 0, "wavelength": 50, "amplitude": 0.001, "steepness": 0.1}]}})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, -5.0, 0.0};
    frame.camera.target = {10.0, -5.0 + 10.0 * std::tan(60.0 * kPi / 180.0), 0.0};
    frame.camera.fov_y_deg = 90.0;
    frame.sun_direction = {-0.3, 0.6, 0.74};  // behind the camera: its disc outside the frame
    const int w = 320, h = 320;
    const auto img = render(scene, frame, w, h);
    ASSERT_TRUE(renderer_->stats().camera.under);
    // Brightness by zenith angle, in half-degree bins.
    std::map<int, std::pair<double, int>> bins;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double zenith = std::acos(test::pixel_ray(frame.camera, w, h, x, y).y) * 180.0 / kPi;
            const Rgb c = test::pixel(img, x, y);
            auto& bin = bins[static_cast<int>(std::floor(zenith * 2.0))];
            bin.first += (c.r + c.g + c.b) / 3.0;
            ++bin.second;
        }
    auto mean_between = [&](double lo, double hi) {
        double sum = 0.0;
        int n = 0;
        for (const auto& [b, v] : bins)
            if (b / 2.0 >= lo && b / 2.0 < hi) {
                sum += v.first;
                n += v.second;
            }
        return sum / std::max(n, 1);
    };
    const double sky = mean_between(30.0, 40.0), water = mean_between(55.0, 70.0);
    ASSERT_GT(sky, water + 0.2) << "the window is brighter than the water around it";
    double edge = 0.0;
    for (const auto& [b, v] : bins) {
        if (b / 2.0 < 40.0) continue;
        if (v.first / v.second < 0.5 * (sky + water)) {
            edge = b / 2.0;
            break;
        }
    }
    const double critical = std::asin(1.0 / gpu::kWaterRefractiveIndex) * 180.0 / kPi;
    std::printf("Snell's window: sky %.3f, water %.3f, edge at %.1f degrees (critical angle %.2f)\n", sky, water, edge,
                critical);
    EXPECT_NEAR(edge, critical, 1.5);
}

/// A flat sandy seabed 2 m under a camera 6 m under calm water, without caustics: along the
/// view its colour fades toward the water's own as e^(-c d) per channel (Beer–Lambert, c the
/// extinction of the ocean's optics), measured between seabed 4 m and 8 to 14 m away, against
/// the water's colour where the view meets no ground, within 10 % for green and blue (red is
/// gone within a few metres). Once with the ocean's default optics (Jerlov's type II), once
/// with a preset's own extinction.
TEST_F(RenderTest, UnderWaterTheSeabedFadesAsBeerLambertSays) {
    auto measure_seabed_fade = [&](const std::string& scene_json) {
        const Scene scene = scene_from(scene_json);
        const WaterOptics optics = optics_of(scene, BodyRef{BodyKind::ocean, -1});
        render::FrameInfo frame;
        frame.camera.position = {0.0, -6.0, 0.0};
        frame.camera.target = {100.0, -6.0 - 100.0 * std::tan(12.0 * kPi / 180.0), 0.0};
        frame.camera.fov_y_deg = 60.0;
        frame.sun_direction = {-0.2, 0.9, 0.4};
        const int w = 480, h = 360;
        // Without caustics (their mean brightness instead): a pattern of metre-wide cells
        // would not average out over the near seabed's few cells.
        auto renderer = test::renderer_with(
            context(), scene, [](render::RendererInitInfo& init) { init.quality_overrides.caustics = false; });
        ASSERT_TRUE(renderer);
        auto target = render::OffscreenTarget::create(context(), w, h);
        ASSERT_TRUE(target.ok()) << target.error().message;
        auto rendered = (*target)->render(*renderer, frame);
        ASSERT_TRUE(rendered.ok()) << rendered.error().message;
        const render::RgbaImage& img = *rendered;
        ASSERT_TRUE(renderer->stats().camera.under);
        // Mean colour of the seabed by its distance (half-metre bins) and of the water where
        // the view rises (no ground there: the surface from below, which reflects the water).
        std::map<int, std::pair<Rgb, int>> by_distance;
        Rgb water;
        int water_n = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::dvec3 d = test::pixel_ray(frame.camera, w, h, x, y);
                const Rgb c = test::pixel(img, x, y);
                if (d.y > 0.05) {
                    water.r += c.r;
                    water.g += c.g;
                    water.b += c.b;
                    ++water_n;
                    continue;
                }
                if (d.y > -0.02) continue;
                const double distance = 2.0 / -d.y;
                auto& bin = by_distance[static_cast<int>(std::floor(distance * 2.0))];
                bin.first.r += c.r;
                bin.first.g += c.g;
                bin.first.b += c.b;
                ++bin.second;
            }
        ASSERT_GT(water_n, 100);
        water = {water.r / water_n, water.g / water_n, water.b / water_n};
        auto seabed_at = [&](double distance) {
            const auto& [sum, n] = by_distance.at(static_cast<int>(std::floor(distance * 2.0)));
            EXPECT_GT(n, 50) << distance;
            return Rgb{sum.r / n, sum.g / n, sum.b / n};
        };
        const Rgb near = seabed_at(4.0);
        for (double far_distance : {8.0, 11.0, 14.0}) {
            const Rgb far = seabed_at(far_distance);
            const double path = far_distance - 4.0;
            const double measured_g = (far.g - water.g) / (near.g - water.g);
            const double measured_b = (far.b - water.b) / (near.b - water.b);
            const double expected_g = std::exp(-optics.extinction.g * path);
            const double expected_b = std::exp(-optics.extinction.b * path);
            std::printf("seabed %.0f m against 4 m: green %.3f (Beer-Lambert %.3f), blue %.3f (%.3f)\n", far_distance,
                        measured_g, expected_g, measured_b, expected_b);
            EXPECT_NEAR(measured_g / expected_g, 1.0, 0.1);
            EXPECT_NEAR(measured_b / expected_b, 1.0, 0.1);
        }
    };
    for (const char* preset_optics : {"", R"(, "optics": {"extinction": [0.55, 0.12, 0.1]})"}) {
        SCOPED_TRACE(preset_optics);
        measure_seabed_fade(fmt::format(R"({{"version": 1, "water_level": 0, "terrain": {{"flat": {{"height": -8}}}},
            "ocean": {{"waves": [{{"direction": 0, "wavelength": 50, "amplitude": 0.001, "steepness": 0.1}}]{}}}}})",
                                        preset_optics));
    }
}

/// Caustics from the waves above: one long-crested sine wave (4 m long, 8 cm high, no
/// Gerstner steepness) over a flat seabed 6 m down, the sun overhead, seen from under the
/// surface looking down. Light refracted by a surface eta(x) lands at x + D eta'(x) with
/// D = h (1 - 1/n), so the sun's light on the seabed is 1 / (1 + D eta''(x)) of calm
/// water's, eta'' = -k^2 eta for a sine wave: bright under the crests, which focus it, dim
/// under the troughs. The frame with caustics less the frame without (column means along
/// the seabed, the water's extinction along each path taken out) follows that theory,
/// with eta(x) from query_world: one scale fits it with R^2 > 0.9, the scale positive.
TEST_F(RenderTest, CausticsFocusTheSunUnderTheCrestsAsTheSurfacesCurvatureSays) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -6}},
        "ocean": {"waves": [{"direction": 0, "wavelength": 4, "amplitude": 0.08, "steepness": 0}]}})");
    const WaterOptics optics = optics_of(scene, BodyRef{BodyKind::ocean, -1});
    render::FrameInfo frame;
    frame.camera.position = {0.0, -0.5, 0.0};
    frame.camera.target = {0.0, -6.0, 1.0};
    frame.camera.fov_y_deg = 60.0;
    frame.sun_direction = {0.0, 1.0, 0.0};
    frame.time = 1.3;
    const int w = 480, h = 360;
    auto draw = [&](bool caustics) {
        auto renderer = test::renderer_with(
            context(), scene, [&](render::RendererInitInfo& init) { init.quality_overrides.caustics = caustics; });
        EXPECT_TRUE(renderer);
        auto target = render::OffscreenTarget::create(context(), w, h);
        EXPECT_TRUE(target.ok());
        auto rendered = (*target)->render(*renderer, frame);
        EXPECT_TRUE(rendered.ok()) << rendered.error().message;
        return rendered.ok() ? *rendered : render::RgbaImage{};
    };
    const render::RgbaImage with = draw(true), without = draw(false);
    ASSERT_EQ(with.width, static_cast<std::uint32_t>(w));
    ASSERT_EQ(without.width, static_cast<std::uint32_t>(w));
    // Along x in 5 cm bins, from the pixels whose seabed point lies within 0.5 m of z = 0.
    constexpr double kBin = 0.05;
    std::map<int, std::pair<double, int>> bins;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 d = test::pixel_ray(frame.camera, w, h, x, y);
            const double path = -5.5 / d.y;
            const glm::dvec3 p = frame.camera.position + path * d;
            if (std::abs(p.z) > 0.5) continue;
            const double change = test::pixel(with, x, y).g - test::pixel(without, x, y).g;
            auto& bin = bins[static_cast<int>(std::floor(p.x / kBin))];
            bin.first += change / std::exp(-optics.extinction.g * path);
            ++bin.second;
        }
    const double depth_factor = 6.0 * (1.0 - 1.0 / gpu::kWaterRefractiveIndex);
    const double k = 2.0 * kPi / 4.0;
    std::vector<double> measured, theory;
    for (const auto& [i, sum] : bins) {
        if (sum.second < 20) continue;
        const double x = (i + 0.5) * kBin;
        const double eta = query_world_point(scene, frame.time, {x, 0.0}).surface.height;
        measured.push_back(sum.first / sum.second);
        theory.push_back(1.0 / (1.0 - depth_factor * k * k * eta) - 1.0);
    }
    ASSERT_GT(measured.size(), 80u);
    const auto [scale, r2] = test::fit_one_scale(measured, theory);
    std::printf("caustics: %zu bins over %.1f m, gain's swing %.2f to %.2f in theory, fit R^2 %.3f (scale %.3f)\n",
                measured.size(), measured.size() * kBin, 1.0 + *std::min_element(theory.begin(), theory.end()),
                1.0 + *std::max_element(theory.begin(), theory.end()), r2, scale);
    EXPECT_GT(scale, 0.0);
    EXPECT_GT(r2, 0.9);
}

/// A camera level with calm-ish water (a 20 m swell 0.3 m high) at an instant when the
/// surface crosses its near plane: every column of the frame is bright above (the sky and
/// the sea seen from the air) and dark below (the water seen from under it) with one edge
/// between, a dark meniscus at most a few pixels tall, at the row where query_submersion
/// puts the water line on the near plane (within two pixels).
TEST_F(RenderTest, TheWaterLineCrossesTheLensAsOneEdge) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}},
        "ocean": {"waves": [{"direction": 20, "wavelength": 20, "amplitude": 0.3, "steepness": 0.5}]}})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, 0.0, 0.0};
    frame.camera.target = {100.0, 0.0, 0.0};
    frame.camera.fov_y_deg = 50.0;
    // An instant when the surface over the lens stands 5 cm above its centre.
    for (double t = 0.0; t < 10.0; t += 0.01) {
        const double h = query_world_point(scene, t, {frame.camera.near_plane, 0.0}).surface.height;
        if (h > 0.04 && h < 0.06) {
            frame.time = t;
            break;
        }
    }
    ASSERT_GT(frame.time, 0.0);
    const int w = 320, h = 180;
    const auto img = render(scene, frame, w, h);
    EXPECT_TRUE(renderer_->stats().camera.under) << "the eye is 5 cm under";
    // Where the CPU puts the water line on the centre column of the near plane.
    const auto c = render::near_plane_corners(frame.camera, static_cast<double>(w) / h);
    const glm::dvec3 top = 0.5 * (c[2] + c[3]), bottom = 0.5 * (c[0] + c[1]);
    std::array<Submersion, 2> s;
    const std::array<glm::dvec3, 2> ends{top, bottom};
    ASSERT_TRUE(query_submersion(scene, frame.time, ends, s).ok());
    ASSERT_LT(s[0].depth, 0.0);
    ASSERT_GT(s[1].depth, 0.0);
    const double expected_row = h * s[0].depth / (s[0].depth - s[1].depth);
    auto luminance = [&](int x, int y) {
        const Rgb p = test::pixel(img, x, y);
        return 0.3 * p.r + 0.6 * p.g + 0.1 * p.b;
    };
    int worst_band = 0;
    double worst_offset = 0.0;
    for (int x = 0; x < w; x += 4) {
        // Bright above, dark below: the first dark row from the top, the last bright row from
        // the bottom; between them the meniscus.
        int first_dark = h, last_bright = -1;
        for (int y = 0; y < h; ++y)
            if (luminance(x, y) < 0.25) {
                first_dark = y;
                break;
            }
        for (int y = h - 1; y >= 0; --y)
            if (luminance(x, y) > 0.25) {
                last_bright = y;
                break;
            }
        ASSERT_LT(first_dark, h) << "column " << x << " has the view below";
        ASSERT_GE(last_bright, 0) << "column " << x << " has the view above";
        EXPECT_LE(last_bright, first_dark) << "column " << x << ": one edge, no bright row under the water line";
        int dark_rows_above = 0;
        for (int y = 0; y < first_dark; ++y) dark_rows_above += luminance(x, y) < 0.25;
        EXPECT_EQ(dark_rows_above, 0) << "column " << x;
        // The meniscus: the darkest rows at the edge.
        int band = 0;
        for (int y = std::max(first_dark - 4, 0); y < std::min(first_dark + 8, h); ++y) band += luminance(x, y) < 0.08;
        worst_band = std::max(worst_band, band);
        if (x == w / 2 || x == w / 2 - 1) worst_offset = std::max(worst_offset, std::abs(first_dark - expected_row));
    }
    std::printf("water line: at row %.1f of %d by the CPU, the frame's %.1f rows from it; meniscus up to %d rows\n",
                expected_row, h, worst_offset, worst_band);
    EXPECT_LE(worst_offset, 2.0);
    EXPECT_GE(worst_band, 1) << "a dark meniscus";
    EXPECT_LE(worst_band, 4) << "a thin one";
}

}  // namespace
}  // namespace tidewater
