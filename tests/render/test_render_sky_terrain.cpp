// The sky and the terrain on lavapipe under the validation layer: where sky, land and
// water belong, the Preetham sky, the terrain's materials, and the stored reference images.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "render_fixture.hpp"
#include "sky_model.hpp"
#include "tidewater/detail/image_io.hpp"

namespace tidewater {
namespace {

// The default island from its own camera: sky above the horizon, land at the island's
// middle, water offshore; a water pixel is not land-coloured and vice versa.
TEST_F(RenderTest, DefaultSceneHasSkyWaterAndLandWhereTheyBelong) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    render::FrameInfo frame;
    frame.camera.position = scene->camera->position;
    frame.camera.target = scene->camera->target;
    frame.camera.fov_y_deg = scene->camera->fov_y_deg;
    frame.time = 3.0;
    const auto img = render(*scene, frame);
    ASSERT_EQ(img.width, 320);
    EXPECT_TRUE(is_sky(test::block(img, 160, 4))) << "top centre";
    // Land: the island's highest point (seen from a camera above every hill, it cannot be hidden).
    glm::dvec3 hill{0.0, -1e9, 0.0};
    for (int i = -60; i <= 60; ++i)
        for (int j = -60; j <= 60; ++j) {
            const double h = scene->terrain.height_at({i * 10.0, j * 10.0});
            if (h > hill.y) hill = {i * 10.0, h, j * 10.0};
        }
    ASSERT_GT(hill.y, 20.0);
    ASSERT_LT(hill.y, frame.camera.position.y);
    auto p = test::project(frame.camera, 320, 180, hill);
    ASSERT_TRUE(p.has_value()) << "hill " << hill.x << "," << hill.y << "," << hill.z;
    // Two rows under the summit: its own pixel is on the skyline, where the sea that now
    // reaches the horizon shows behind it.
    EXPECT_TRUE(is_land(test::block(img, p->x, p->y + 2, 1))) << "island at " << p->x << "," << p->y + 2;
    // Water: points on a ring 1.1 km from the centre (beyond any coast) that are in view
    // with a clear line of sight over the terrain.
    int water_points = 0;
    const glm::dvec3 eye = frame.camera.position;
    for (int a = 0; a < 72; ++a) {
        const glm::dvec3 w{1100.0 * std::cos(a * kPi / 36.0), 0.0, 1100.0 * std::sin(a * kPi / 36.0)};
        bool clear = true;
        for (int k = 1; k < 200 && clear; ++k) {
            const glm::dvec3 on_ray = eye + (w - eye) * (k / 200.0);
            clear = scene->terrain.height_at({on_ray.x, on_ray.z}) < on_ray.y - 1.0;
        }
        if (!clear) continue;
        const auto q = test::project(frame.camera, 320, 180, w);
        if (!q || q->y < 20) continue;
        const Rgb c = test::block(img, q->x, q->y, 1);
        EXPECT_TRUE(is_water(c)) << "water at " << q->x << "," << q->y << ": " << c.r << " " << c.g << " " << c.b;
        ++water_points;
    }
    EXPECT_GT(water_points, 3);
}

// Looking up at the sky, nothing but sky is drawn.
TEST_F(RenderTest, EmptySkyShowsOnlySky) {
    const Scene scene = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}}, "ocean": "ocean_rolling"})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 0.0};
    frame.camera.target = {0.0, 200.0, -100.0};  // about 62 degrees up: the horizon is off-screen
    frame.sun_direction = {0.0, 0.5, 0.8};       // behind the camera: the sky without the sun disc
    const auto img = render(scene, frame);
    int not_sky = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) not_sky += !is_sky(test::pixel(img, x, y));
    EXPECT_EQ(not_sky, 0);
}

// The terrain reads as land: rock where the ground is steep, green grass on gentle
// slopes above the beach, and sand the swash has wet darker than the dry sand above it,
// the wet band's edge moving with the waves.
TEST_F(RenderTest, TerrainMaterialsFollowSlopeHeightAndWetness) {
    auto look_at = [&](const Scene& scene, glm::dvec3 at, double time) {
        render::FrameInfo frame;
        frame.camera.position = at + glm::dvec3(-30.0, 25.0, 0.5);
        frame.camera.target = at;
        frame.camera.fov_y_deg = 20.0;
        frame.sun_direction = {-0.4, 0.8, 0.3};
        frame.time = time;
        return render(scene, frame);
    };
    auto saturation = [](Rgb c) { return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}); };
    auto luminance = [](Rgb c) { return 0.3 * c.r + 0.6 * c.g + 0.1 * c.b; };
    const std::string ocean =
        R"("ocean": {"waves": [{"direction": 0, "wavelength": 60, "amplitude": 0.2, "steepness": 0.5}]}, "shore": {"enabled": false})";
    // Gentle (slope 0.05) and steep (45 degrees) ground 20 m above the sea.
    const Scene gentle = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 20, "slope": [0.05, 0]}}, )" + ocean + "}");
    const Scene steep = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 20, "slope": [1.0, 0]}}, )" + ocean + "}");
    const Rgb grass = test::block(look_at(gentle, {0.0, 20.0, 0.0}, 0.0), 160, 90, 20);
    const Rgb rock = test::block(look_at(steep, {0.0, 20.0, 0.0}, 0.0), 160, 90, 20);
    EXPECT_GT(grass.g, grass.r + 0.05) << "grass is green";
    EXPECT_LT(saturation(rock), 0.5 * saturation(grass)) << "cliffs are grey rock";
    // A beach rising 2 cm per metre from the sea at x = 0 under a 0.1 m swell 150 m long:
    // the swash runs up R2% = 0.043 sqrt(Hs L0) = 0.28 m (Hs = 0.28 m), above the 0.1 m
    // crests; the sand is soaked up to R and 3 m up it is dry.
    const Scene beach =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 0, "slope": [0.02, 0]}},
        "ocean": {"waves": [{"direction": 0, "wavelength": 150, "amplitude": 0.1, "steepness": 0.5}]}, "shore": {"enabled": false}})");
    const Rgb wet = test::block(look_at(beach, {10.0, 0.2, 0.0}, 0.0), 160, 90, 10);
    const Rgb dry = test::block(look_at(beach, {150.0, 3.0, 0.0}, 0.0), 160, 90, 10);
    EXPECT_GT(dry.r, dry.b + 0.1) << "dry sand is sand-coloured";
    EXPECT_LT(luminance(wet), 0.85 * luminance(dry)) << "wet sand is darker";
    // The wet film's top moves with the waves' period (9.8 s: half of it apart).
    const double moved =
        test::mean_difference(look_at(beach, {8.0, 0.16, 0.0}, 0.0), look_at(beach, {8.0, 0.16, 0.0}, 4.9));
    EXPECT_GT(moved, 0.005) << "the swash line moves";
    std::printf("grass saturation %.3f, rock %.3f; wet sand luminance %.3f of dry; swash frames differ by %.4f\n",
                saturation(grass), saturation(rock), luminance(wet) / luminance(dry), moved);
}

/// The sky's display colour the documented way (sky_model.hpp): Preetham's Yxy, white
/// balance, exposure keeping the hue, saturation, sRGB encoding, the sun's glow.
Rgb expected_sky(glm::dvec3 sun, double turbidity, glm::dvec3 dir) {
    const render::detail::PreethamSky sky = render::detail::preetham_sky(sun, turbidity);
    glm::dvec3 rgb = render::detail::linear_srgb_from_Yxy(render::detail::preetham_Yxy(sky, sun, dir) /
                                                          glm::dvec3(sky.zenith.x, 1.0, 1.0));
    rgb = glm::max(rgb, glm::dvec3(0.0)) * render::detail::sky_white_balance(sky, sun);
    const double luminance = std::max(glm::dot(rgb, glm::dvec3(0.2126, 0.7152, 0.0722)), 1e-6);
    const double shown = 1.0 - std::exp(-render::detail::kSkyExposure * luminance);
    rgb = glm::max(glm::mix(glm::dvec3(shown), rgb * (shown / luminance), render::detail::kSkySaturation),
                   glm::dvec3(0.0));
    auto encode = [](double c) {
        c = std::clamp(c, 0.0, 1.0);
        return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    };
    const double s = std::max(glm::dot(dir, sun), 0.0);
    const glm::dvec3 glow =
        std::pow(s, 900.0) * glm::dvec3(8.0, 7.0, 5.5) + std::pow(s, 12.0) * glm::dvec3(0.25, 0.2, 0.12);
    // An 8-bit target holds at most 1.
    return {std::min(encode(rgb.r) + glow.r, 1.0), std::min(encode(rgb.g) + glow.g, 1.0),
            std::min(encode(rgb.b) + glow.b, 1.0)};
}

// The background is the Preetham sky: pixels toward five directions (from 20 to 75
// degrees up, toward and away from the sun) match the model's colour within 2/255 per
// channel, and it is bluest at the zenith, whitest low down (the clear-sky gradient).
TEST_F(RenderTest, TheSkyIsPreethamsModel) {
    const Scene scene = scene_from(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}}, "ocean": "ocean_rolling"})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 0.0};
    frame.camera.target = {0.0, 10.0 + 1.0, 1.0};  // 45 degrees up toward +z
    frame.camera.fov_y_deg = 70.0;
    frame.sun_direction = glm::normalize(glm::dvec3(0.3, 0.5, 0.8));
    const auto img = render(scene, frame, 320, 320);
    const glm::dvec3 sun = glm::normalize(frame.sun_direction);
    double worst = 0.0;
    for (const glm::dvec3 d : {glm::dvec3(0.0, 0.34, 0.94), glm::dvec3(0.0, 0.71, 0.71), glm::dvec3(0.0, 0.97, 0.26),
                               glm::dvec3(0.45, 0.45, 0.77), glm::dvec3(-0.45, 0.45, 0.77)}) {
        const glm::dvec3 dir = glm::normalize(d);
        const auto at = test::project(frame.camera, img.width, img.height, frame.camera.position + dir * 1000.0);
        ASSERT_TRUE(at.has_value());
        const Rgb got = test::block(img, at->x, at->y, 1), want = expected_sky(sun, frame.sky_turbidity, dir);
        worst = std::max({worst, std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b)});
    }
    std::printf("sky pixels against the Preetham model: worst channel difference %.4f\n", worst);
    EXPECT_LT(worst, 2.0 / 255.0 + 1e-9);
    const Rgb low = expected_sky(sun, 2.5, glm::normalize(glm::dvec3(-0.8, 0.05, -0.2)));
    const Rgb zenith = expected_sky(sun, 2.5, {0.0, 1.0, 0.0});
    EXPECT_GT(zenith.b - zenith.r, 1.5 * (low.b - low.r)) << "bluest overhead";
    EXPECT_GT(low.r + low.g + low.b, zenith.r + zenith.g + zenith.b) << "brightest low down";
}

// Stored references for the default scene and a few views: mean difference under 2%
// and 99% of pixels within 10% (lavapipe rounding differs between LLVM builds).
// TIDEWATER_UPDATE_REFERENCES=1 rewrites them.
TEST_F(RenderTest, MatchesReferenceImages) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    const std::filesystem::path dir = TIDEWATER_REFERENCE_DIR;
    const bool update = std::getenv("TIDEWATER_UPDATE_REFERENCES") != nullptr;
    for (render::DebugView view : {render::DebugView::shaded, render::DebugView::height, render::DebugView::jacobian,
                                   render::DebugView::depth, render::DebugView::normals}) {
        render::FrameInfo frame;
        frame.camera.position = scene->camera->position;
        frame.camera.target = scene->camera->target;
        frame.camera.fov_y_deg = scene->camera->fov_y_deg;
        frame.time = 3.0;
        frame.view = view;
        const auto img = render(*scene, frame);
        const auto path = dir / ("default_" + std::string(render::to_string(view)) + ".png");
        if (update) {
            ASSERT_TRUE(detail::write_png_rgba8(path, img.width, img.height, img.pixels).ok());
            continue;
        }
        ASSERT_TRUE(std::filesystem::exists(path)) << path << " (run with TIDEWATER_UPDATE_REFERENCES=1 to create)";
        auto reference = detail::read_png_rgba8(path);
        ASSERT_TRUE(reference.ok()) << reference.error().message;
        ASSERT_EQ(reference->width, img.width);
        ASSERT_EQ(reference->height, img.height);
        const test::ImageDifference d = test::image_difference(img, *reference);
        EXPECT_LT(d.mean, 0.02) << path;
        EXPECT_LT(d.p99, 0.10) << path;
        std::printf("reference %s: mean difference %.4f, 99th percentile %.4f\n", path.filename().c_str(), d.mean,
                    d.p99);
    }
}

}  // namespace
}  // namespace tidewater
