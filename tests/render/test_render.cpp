// Rendering on lavapipe under the validation layer: semantic image checks that
// do not depend on stored references, reference-image comparisons, bad input.
#include <algorithm>
#include <atomic>
#include <future>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "../core/test_helpers.hpp"
#include "render_helpers.hpp"
#include "../baked_scene.hpp"
#include "../bowl_terrain.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/render/standalone.hpp"
#include "tidewater/scene_floaters.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "sky_model.hpp"
#include "vk_util.hpp"
#include "vulkan_fixture.hpp"
#include "tidewater/detail/image_write.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

using test::Rgb;

class RenderTest : public test::VulkanTest {
protected:
    void SetUp() override {
        VulkanTest::SetUp();
        render::RendererInitInfo init;
        init.device = context();
        init.color_format = render::OffscreenTarget::kColorFormat;
        init.depth_format = render::OffscreenTarget::kDepthFormat;
        init.wireframe = init.device.enabled_features.fillModeNonSolid;
        auto r = render::Renderer::create(init);
        ASSERT_TRUE(r.ok()) << r.error().message;
        renderer_ = std::move(r).value();
    }
    void release() override {
        target_.reset();
        renderer_.reset();
    }
    render::RgbaImage render(const Scene& scene, const render::FrameInfo& frame, std::uint32_t w = 320, std::uint32_t h = 180) {
        EXPECT_TRUE(renderer_->set_scene(scene).ok());
        if (!target_ || width_ != w || height_ != h) {
            auto t = render::OffscreenTarget::create(context(), w, h);
            EXPECT_TRUE(t.ok()) << t.error().message;
            target_ = std::move(t).value();
            width_ = w;
            height_ = h;
        }
        auto img = target_->render(*renderer_, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        // TIDEWATER_TEST_IMAGE_DIR keeps every frame a test renders, for looking at failures.
        if (const char* dir = std::getenv("TIDEWATER_TEST_IMAGE_DIR"); dir && img.ok()) {
            const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
            const auto path = std::filesystem::path(dir) / (std::string(info->name()) + "_" + std::to_string(dumped_++) + ".png");
            EXPECT_TRUE(detail::write_png_rgba8(path, img->width, img->height, img->pixels).ok());
        }
        return img.ok() ? std::move(img).value() : render::RgbaImage{};
    }
    static Scene scene_from(const std::string& json) {
        auto s = test::baked(parse_scene(json, "test scene"));
        EXPECT_TRUE(s.ok()) << s.error().message;
        return s.ok() ? std::move(s).value() : Scene{};
    }
    /// A frame through a renderer and target of their own at `samples` per pixel, the
    /// water shaded at every sample when `water_per_sample`.
    render::RgbaImage render_multisampled(const Scene& scene, const render::FrameInfo& frame, std::uint32_t w, std::uint32_t h,
                                          VkSampleCountFlagBits samples, bool water_per_sample = false) {
        render::RendererInitInfo init;
        init.device = context();
        init.samples = samples;
        init.shade_water_per_sample = water_per_sample;
        init.wireframe = false;
        auto r = render::Renderer::create(init);
        EXPECT_TRUE(r.ok()) << r.error().message;
        if (!r.ok()) return {};
        EXPECT_TRUE((*r)->set_scene(scene).ok());
        auto t = render::OffscreenTarget::create(context(), w, h, samples);
        EXPECT_TRUE(t.ok()) << t.error().message;
        if (!t.ok()) return {};
        auto img = (*t)->render(**r, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        if (const char* dir = std::getenv("TIDEWATER_TEST_IMAGE_DIR"); dir && img.ok()) {
            const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
            const auto path = std::filesystem::path(dir) / (std::string(info->name()) + "_" + std::to_string(dumped_++) + "_msaa.png");
            EXPECT_TRUE(detail::write_png_rgba8(path, img->width, img->height, img->pixels).ok());
        }
        return img.ok() ? std::move(img).value() : render::RgbaImage{};
    }
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<render::OffscreenTarget> target_;
    std::uint32_t width_ = 0, height_ = 0;
    int dumped_ = 0;
};

bool is_sky(Rgb c) { return c.b > c.r + 0.1 && c.b > 0.45; }
bool is_water(Rgb c) { return c.b > c.r && c.g > c.r; }
bool is_land(Rgb c) { return c.g > c.b && c.r > 0.08; }  // grass, sand and rock have more green than blue

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

// Waves break along the coast and not offshore: in the breaking view, water 10 to 30 m off
// the coast (found from the shore model along rays from the centre) shows breaking and
// water 1.1 km out shows none.
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

// Looking up at the sky, nothing but sky is drawn.
TEST_F(RenderTest, EmptySkyShowsOnlySky) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}}, "ocean": "ocean_rolling"})");
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

// Submerged terrain shows through 1 m of water (bright, with its caustic texture) and not
// through 60 m (dark and featureless).
TEST_F(RenderTest, ShallowWaterShowsTheBottomDeepWaterDoesNot) {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 12.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.sun_direction = {0.0, 0.8, 0.6};  // behind the camera: no glitter in view
    const std::string calm = R"("ocean": {"waves": [{"direction": 0, "wavelength": 8, "amplitude": 0.02, "steepness": 0.3}]})";
    const auto shallow = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -1}}, )" + calm + "}"), frame);
    const auto deep = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -60}}, )" + calm + "}"), frame);
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
        "ocean": {"waves": [{"direction": 90, "wavelength": 20, "amplitude": )" + std::to_string(a) + R"(, "steepness": 1}]}})"), frame);
    const auto calm = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -80}},
        "ocean": {"waves": [{"direction": 90, "wavelength": 20, "amplitude": 0.3, "steepness": 0.3}]}})"), frame);
    EXPECT_GT(white_fraction(steep), 0.02);
    EXPECT_LT(white_fraction(calm), 0.001);
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
    const std::string ocean = R"("ocean": {"waves": [{"direction": 0, "wavelength": 60, "amplitude": 0.2, "steepness": 0.5}]}, "shore": {"enabled": false})";
    // Gentle (slope 0.05) and steep (45 degrees) ground 20 m above the sea.
    const Scene gentle = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 20, "slope": [0.05, 0]}}, )" + ocean + "}");
    const Scene steep = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 20, "slope": [1.0, 0]}}, )" + ocean + "}");
    const Rgb grass = test::block(look_at(gentle, {0.0, 20.0, 0.0}, 0.0), 160, 90, 20);
    const Rgb rock = test::block(look_at(steep, {0.0, 20.0, 0.0}, 0.0), 160, 90, 20);
    EXPECT_GT(grass.g, grass.r + 0.05) << "grass is green";
    EXPECT_LT(saturation(rock), 0.5 * saturation(grass)) << "cliffs are grey rock";
    // A beach rising 2 cm per metre from the sea at x = 0 under a 0.1 m swell 150 m long:
    // the swash runs up R2% = 0.043 sqrt(Hs L0) = 0.28 m (Hs = 0.28 m), above the 0.1 m
    // crests; the sand is soaked up to R and 3 m up it is dry.
    const Scene beach = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": 0, "slope": [0.02, 0]}},
        "ocean": {"waves": [{"direction": 0, "wavelength": 150, "amplitude": 0.1, "steepness": 0.5}]}, "shore": {"enabled": false}})");
    const Rgb wet = test::block(look_at(beach, {10.0, 0.2, 0.0}, 0.0), 160, 90, 10);
    const Rgb dry = test::block(look_at(beach, {150.0, 3.0, 0.0}, 0.0), 160, 90, 10);
    EXPECT_GT(dry.r, dry.b + 0.1) << "dry sand is sand-coloured";
    EXPECT_LT(luminance(wet), 0.85 * luminance(dry)) << "wet sand is darker";
    // The wet film's top moves with the waves' period (9.8 s: half of it apart).
    const double moved = test::mean_difference(look_at(beach, {8.0, 0.16, 0.0}, 0.0), look_at(beach, {8.0, 0.16, 0.0}, 4.9));
    EXPECT_GT(moved, 0.005) << "the swash line moves";
    std::printf("grass saturation %.3f, rock %.3f; wet sand luminance %.3f of dry; swash frames differ by %.4f\n", saturation(grass),
                saturation(rock), luminance(wet) / luminance(dry), moved);
}

/// The sky's display colour the documented way (sky_model.hpp): Preetham's Yxy, white
/// balance, exposure keeping the hue, saturation, sRGB encoding, the sun's glow.
Rgb expected_sky(glm::dvec3 sun, double turbidity, glm::dvec3 dir) {
    const render::detail::PreethamSky sky = render::detail::preetham_sky(sun, turbidity);
    glm::dvec3 rgb = render::detail::linear_srgb_from_Yxy(render::detail::preetham_Yxy(sky, sun, dir) / glm::dvec3(sky.zenith.x, 1.0, 1.0));
    rgb = glm::max(rgb, glm::dvec3(0.0)) * render::detail::sky_white_balance(sky, sun);
    const double luminance = std::max(glm::dot(rgb, glm::dvec3(0.2126, 0.7152, 0.0722)), 1e-6);
    const double shown = 1.0 - std::exp(-render::detail::kSkyExposure * luminance);
    rgb = glm::max(glm::mix(glm::dvec3(shown), rgb * (shown / luminance), render::detail::kSkySaturation), glm::dvec3(0.0));
    auto encode = [](double c) {
        c = std::clamp(c, 0.0, 1.0);
        return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    };
    const double s = std::max(glm::dot(dir, sun), 0.0);
    const glm::dvec3 glow = std::pow(s, 900.0) * glm::dvec3(8.0, 7.0, 5.5) + std::pow(s, 12.0) * glm::dvec3(0.25, 0.2, 0.12);
    // An 8-bit target holds at most 1.
    return {std::min(encode(rgb.r) + glow.r, 1.0), std::min(encode(rgb.g) + glow.g, 1.0), std::min(encode(rgb.b) + glow.b, 1.0)};
}

// The background is the Preetham sky: pixels toward five directions (from 20 to 75
// degrees up, toward and away from the sun) match the model's colour within 2/255 per
// channel, and it is bluest at the zenith, whitest low down (the clear-sky gradient).
TEST_F(RenderTest, TheSkyIsPreethamsModel) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}}, "ocean": "ocean_rolling"})");
    render::FrameInfo frame;
    frame.camera.position = {0.0, 10.0, 0.0};
    frame.camera.target = {0.0, 10.0 + 1.0, 1.0};  // 45 degrees up toward +z
    frame.camera.fov_y_deg = 70.0;
    frame.sun_direction = glm::normalize(glm::dvec3(0.3, 0.5, 0.8));
    const auto img = render(scene, frame, 320, 320);
    const glm::dvec3 sun = glm::normalize(frame.sun_direction);
    double worst = 0.0;
    for (const glm::dvec3 d : {glm::dvec3(0.0, 0.34, 0.94), glm::dvec3(0.0, 0.71, 0.71), glm::dvec3(0.0, 0.97, 0.26), glm::dvec3(0.45, 0.45, 0.77),
                               glm::dvec3(-0.45, 0.45, 0.77)}) {
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
            m.r += p.r / img.width; m.g += p.g / img.width; m.b += p.b / img.width;
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
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -300}}, "ocean": "ocean_rolling"})");
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
    std::printf("open-sea whitecap coverage %.4f against Monahan's %.4f (ratio %.2f)\n", coverage, expected, coverage / expected);
    EXPECT_GT(coverage, 0.5 * expected);
    EXPECT_LT(coverage, 2.0 * expected);
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
        const auto& ref = reference->pixels;
        double sum = 0.0;
        std::vector<int> diffs;
        for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
            int d = 0;
            for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(img.pixels[i + k]) - int(ref[i + k])));
            diffs.push_back(d);
            sum += d;
        }
        std::sort(diffs.begin(), diffs.end());
        const double mean = sum / diffs.size() / 255.0;
        const double p99 = diffs[diffs.size() * 99 / 100] / 255.0;
        EXPECT_LT(mean, 0.02) << path;
        EXPECT_LT(p99, 0.10) << path;
        std::printf("reference %s: mean difference %.4f, 99th percentile %.4f\n", path.filename().c_str(), mean, p99);
    }
}

// No cracks between water patches: looking down on open ocean (no horizon in view), every
// pixel is water. In the depth view 200 m of water is pure red and the sky is pale, so
// any pixel that is not red would be a hole in the surface.
TEST_F(RenderTest, WaterSurfaceHasNoCracks) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}}, "ocean": "ocean_rolling"})");
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
    const auto inside_a = frame_at(60.00), inside_b = frame_at(60.04);   // within one origin cell
    const auto cross_a = frame_at(127.98), cross_b = frame_at(128.02);   // across the boundary at 128 m
    const double within = test::mean_difference(inside_a, inside_b), across = test::mean_difference(cross_a, cross_b);
    std::printf("mean change for a 4 cm move: %.4f within a cell, %.4f across a cell boundary\n", within, across);
    EXPECT_LT(within, 0.02);
    EXPECT_LT(across, 0.02);
    EXPECT_LT(across, 3.0 * within + 0.005) << "crossing the origin grid adds no visible jump";
}

// A failed Vulkan call reaches the host as device_error with its VkResult as a field,
// not only inside the message.
TEST(VulkanErrors, KeepTheVkResult) {
    const Error e = render::detail::vk_error(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
    EXPECT_EQ(e.code, ErrorCode::device_error);
    EXPECT_EQ(e.vk_result, static_cast<std::int32_t>(VK_ERROR_DEVICE_LOST));
    EXPECT_NE(e.message.find("vkQueueSubmit"), std::string::npos);
    EXPECT_NE(e.message.find("VK_ERROR_DEVICE_LOST"), std::string::npos);
    EXPECT_EQ(Error{}.vk_result, 0);
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

// An editor's terrain edit: a worker thread re-bakes while the last good scene keeps
// drawing, and the new one is swapped in between frames.
TEST_F(RenderTest, AReBakeOnAWorkerThreadIsSwappedInBetweenFrames) {
    auto first = test::baked(default_scene());
    ASSERT_TRUE(first);
    auto current = std::make_shared<const Scene>(*first);
    ASSERT_TRUE(renderer_->set_scene(*current).ok());
    // The edit: a knoll 30 m high raised in the open sea in front of the camera.
    Scene edited = *current;
    auto island = std::get<IslandTerrain>(edited.terrain.shape());
    island.knolls.push_back({{640.0, 330.0}, 120.0, 30.0});
    edited.terrain = Terrain(island);
    render::FrameInfo frame;
    frame.camera.position = {900.0, 300.0, 500.0};
    frame.camera.target = {120.0, 0.0, 20.0};
    const auto before = render(*current, frame);
    SceneBakeOptions options;
    options.previous = current;
    std::atomic<bool> finished{false};
    auto job = std::async(std::launch::async, [&] {
        auto baked = bake_scene(edited, options);
        finished = true;
        return baked;
    });
    int frames_while_baking = 0;
    while (!finished) {  // the last good scene keeps drawing
        auto img = target_->render(*renderer_, frame);
        ASSERT_TRUE(img.ok()) << img.error().message;
        ++frames_while_baking;
    }
    auto rebaked = job.get();
    ASSERT_TRUE(rebaked) << rebaked.error().message;
    EXPECT_EQ((*rebaked)->bake->reused.rivers, current->rivers.size()) << "the brook and rill are not in the edit";
    ASSERT_TRUE(renderer_->set_scene(**rebaked).ok());  // between frames
    const auto after = render(**rebaked, frame);
    std::printf("%d frame(s) drawn while the worker re-baked in %.2f s\n", frames_while_baking, (*rebaked)->bake->seconds);
    EXPECT_GT(test::mean_difference(before, after), 0.01) << "the new knoll is drawn";
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
                    for (int i = 0; i < 4; ++i) sum += big.pixels[(static_cast<std::size_t>(4 * y + j) * static_cast<std::size_t>(big.width) + static_cast<std::size_t>(4 * x + i)) * 4 + static_cast<std::size_t>(c)];
                out.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>((sum + 8) / 16);
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
const int kFarBandTop = static_cast<int>(std::ceil(180.0 - 180.0 * std::tan(7.6 * kPi / 180.0) / std::tan(25.0 * kPi / 180.0))) + 1;

/// Mean |a - b| per channel over rows [y0, y1), 0..1.
double band_difference(const render::RgbaImage& a, const render::RgbaImage& b, int y0, int y1) {
    double sum = 0.0;
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(a.height, y1); ++y)
        for (int x = 0; x < a.width; ++x)
            for (std::size_t c = 0; c < 3; ++c) {
                const std::size_t k = (static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) + static_cast<std::size_t>(x)) * 4 + c;
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
                        row[j] += big.pixels[(static_cast<std::size_t>(4 * y + j) * static_cast<std::size_t>(big.width) + static_cast<std::size_t>(4 * x + i)) * 4 + c] / (4.0 * 255.0);
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
        std::printf("from %.0f m: what one shading per pixel cannot place of the 4x frame (its sub-rows' spread) %.4f, %.4f less a gradient\n",
                    height, spread_floor, detrended_floor);

        frame.time += 1.0 / 60.0;
        const auto small_next = render(*scene, frame, 640, 360);
        const auto truth_next = box_filter_4x(render(*scene, frame, 2560, 1440));
        const double flicker = band_difference(small, small_next, kFarBandTop, kFarBandTop + 30);
        const double truth_flicker = band_difference(truth, truth_next, kFarBandTop, kFarBandTop + 30);
        std::printf("from %.0f m: far band 1x vs 4x %.4f; frame to frame %.4f (supersampled %.4f)\n", height, alias, flicker, truth_flicker);
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
    std::printf("far band foam: %.4f at 1x, %.4f at 4x box-filtered (%.2f); %.4f 1/60 s later\n", small, truth, small / truth, next);
    EXPECT_GT(truth, 0.01) << "the open sea has whitecaps out there";
    EXPECT_GT(small, 0.85 * truth);
    EXPECT_LT(small, 1.15 * truth);
    EXPECT_NEAR(next, small, 0.1 * small);
}

// Floating bodies (FrameInfo::floats) are drawn where SceneFloaters puts them: from 80 m
// straight above a tug on a calm pool, the pixels under its deck carry its red paint and
// those 30 m beside it are water; a barrel drifting 40 m off shows its orange. Under the
// validation layer. A body without a hull is refused, naming it.
TEST_F(RenderTest, FloatingBodiesAreDrawnWhereTheyFloat) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm",
        "boats": [{"name": "tug", "path": [[-400, 0], [400, 0]], "speed": 5.0, "length": 20.0, "beam": 6.0, "draft": 1.5}],
        "floats": [{"name": "barrel", "at": [100, 40], "radius": 1.0, "height": 1.5, "mass": 1500, "color": [0.9, 0.45, 0.05]}]})");
    auto floaters = SceneFloaters::create(std::make_shared<const Scene>(scene), 20.0);  // the tug's centre at x = -300
    ASSERT_TRUE(floaters) << floaters.error().message;
    const std::vector<render::FloatDraw> draws = render::float_draws(*floaters);
    render::FrameInfo frame;
    frame.time = 20.0;
    frame.floats = draws;
    auto look_down_at = [&](glm::dvec3 at) {
        frame.camera.position = at + glm::dvec3(0.0, 80.0, 0.0);
        frame.camera.target = at + glm::dvec3(0.0, 0.0, 1.0);  // image up is +z, image right is -x
        frame.camera.fov_y_deg = 60.0;
    };
    auto red = [](Rgb c) { return c.r > 1.8 * c.g && c.r > 1.8 * c.b; };
    const glm::dvec3 tug = floaters->pose(0).position;
    look_down_at(tug);
    const auto img = render(scene, frame, 320, 320);
    // 80 m up with a 60 degree field: 320 pixels span 92 m, 3.5 pixels a metre.
    int painted = 0, beside = 0;
    for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
            painted += red(test::pixel(img, 160 + dx, 160 + dy));
            beside += red(test::pixel(img, 160 + dx, 160 + 105 + dy)) + red(test::pixel(img, 160 + dx, 160 - 105 + dy));
        }
    const Rgb deck = test::pixel(img, 160, 160), water = test::pixel(img, 160, 265);
    std::printf("tug at (%.1f, %.3f, %.1f): %d of 81 pixels under its deck red (%.2f %.2f %.2f), %d of 162 beside it (water %.2f %.2f %.2f)\n",
                tug.x, tug.y, tug.z, painted, deck.r, deck.g, deck.b, beside, water.r, water.g, water.b);
    EXPECT_GT(painted, 70);
    EXPECT_EQ(beside, 0);
    const glm::dvec3 barrel = floaters->pose(1).position;
    look_down_at(barrel);
    const auto barrel_img = render(scene, frame, 320, 320);
    const Rgb top = test::pixel(barrel_img, 160, 160);
    std::printf("barrel at (%.1f, %.3f, %.1f): %.2f %.2f %.2f\n", barrel.x, barrel.y, barrel.z, top.r, top.g, top.b);
    EXPECT_GT(top.r, 1.5 * top.g);
    EXPECT_GT(top.g, 2.0 * top.b);
    render::FloatDraw missing;
    frame.floats = std::span<const render::FloatDraw>(&missing, 1);
    auto refused = target_->render(*renderer_, frame);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("FrameInfo::floats[0]"), std::string::npos) << refused.error().message;
}

// Boat wakes are drawn where the CPU puts them: a tug at 5 m/s on a calm pool seen from
// 300 m up (1 degree off the vertical), the wake view (the wakes' share of the height).
// Inside Kelvin's wedge behind the boat most pixels show the wake; ahead of the boat and
// outside 25 degrees of its track (beyond 40 m of the bow) almost none do; under the image centre the drawn wake
// is the CPU query's wake column within 2 cm (8-bit colour, rest against fixed point).
// The shaded view shows the stern's churned foam behind the boat.
TEST_F(RenderTest, BoatWakesAreDrawnInKelvinsWedge) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm",
        "boats": [{"name": "tug", "path": [[-400, 0], [400, 0]], "speed": 5.0, "length": 20.0, "beam": 6.0, "draft": 1.5}]})");
    render::FrameInfo frame;
    frame.time = 100.0;  // the tug's bow shoulders are at x = 105
    const glm::dvec3 centre{-60.0, 0.0, 20.0};
    frame.camera.position = centre + glm::dvec3(0.0, 300.0, 0.0);
    frame.camera.target = frame.camera.position + glm::dvec3(0.0, -300.0, 5.0);
    frame.camera.fov_y_deg = 60.0;
    frame.view = render::DebugView::wake;
    const auto img = render(scene, frame, 320, 320);
    // Image axes from above: find the world point under each pixel on the plane y = 0.
    const glm::dmat4 view = glm::lookAt(frame.camera.position, frame.camera.target, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 proj = glm::perspective(frame.camera.fov_y_deg * kPi / 180.0, 1.0, 0.3, 1000.0);
    const glm::dmat4 inv = glm::inverse(proj * view);
    auto ground = [&](int x, int y) {
        const glm::dvec2 ndc{(x + 0.5) / 160.0 - 1.0, 1.0 - (y + 0.5) / 160.0};
        glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), b = inv * glm::dvec4(ndc, 1.0, 1.0);
        const glm::dvec3 p = glm::dvec3(a) / a.w, q = glm::dvec3(b) / b.w;
        return p + (q - p) * (p.y / (p.y - q.y));
    };
    auto wake_of = [](Rgb c) { return 2.0 * (c.r < 0.99 ? c.r / 1.5 : 1.0 - c.b / 1.5) - 1.0; };  // heat_color inverted
    int inside = 0, inside_drawn = 0, outside = 0, outside_drawn = 0;
    const glm::dvec2 apex{105.0, 0.0};
    for (int y = 0; y < 320; y += 4)
        for (int x = 0; x < 320; x += 4) {
            const glm::dvec3 w = ground(x, y);
            const glm::dvec2 rel = glm::dvec2(w.x, w.z) - apex;
            const double behind = -rel.x, angle = std::atan2(std::abs(rel.y), behind) * 180.0 / kPi;
            const bool drawn = std::abs(wake_of(test::pixel(img, x, y))) > 0.02;
            if (behind > 20.0 && angle < 15.0) {
                ++inside;
                inside_drawn += drawn;
            } else if (glm::length(rel) > 40.0 && (behind < -10.0 || angle > 25.0)) {  // beyond the bow's near field
                ++outside;
                outside_drawn += drawn;
            }
        }
    const glm::dvec3 under = ground(160, 160);
    const WorldPoint cpu = query_world_point(scene, frame.time, {under.x, under.z});
    const double gpu = 0.25 * (wake_of(test::pixel(img, 159, 159)) + wake_of(test::pixel(img, 160, 159)) + wake_of(test::pixel(img, 159, 160)) +
                               wake_of(test::pixel(img, 160, 160)));
    std::printf("wake drawn on %d of %d pixels inside the wedge, %d of %d outside; under the centre %.4f m drawn, %.4f m queried\n",
                inside_drawn, inside, outside_drawn, outside, gpu, cpu.surface.wake);
    EXPECT_GT(inside_drawn, inside / 2);
    EXPECT_LT(outside_drawn, outside / 50 + 1);
    EXPECT_GT(std::abs(cpu.surface.wake), 0.03) << "the centre is on a wave of the wake";
    EXPECT_NEAR(gpu, cpu.surface.wake, 0.02);
    frame.view = render::DebugView::shaded;
    frame.camera.position = {200.0, 60.0, 120.0};
    frame.camera.target = {20.0, 0.0, 0.0};
    const auto shaded = render(scene, frame, 320, 180);
    const auto calm = render(scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm"})"),
                             frame, 320, 180);
    int white = 0;
    auto is_white = [](Rgb c) { return c.r > 0.75 && c.g > 0.75 && c.b > 0.75; };
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) white += is_white(test::pixel(shaded, x, y)) && !is_white(test::pixel(calm, x, y));
    std::printf("shaded: %d white pixels of churned foam; %.4f from the calm pool\n", white, test::mean_difference(shaded, calm));
    EXPECT_GT(white, 20);  // the calm pool has none
    EXPECT_GT(test::mean_difference(shaded, calm), 0.002);
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
            if (gradient > 0.1) { edge_sum += change; ++edges; } else { flat_sum += change; ++flats; }
        }
    const double edge_change = edge_sum / std::max(edges, 1), flat_change = flat_sum / std::max(flats, 1);
    const double same = test::mean_difference(single, multi);
    std::printf("4x MSAA against 1 sample: %.4f overall; %.4f on %d edge pixels, %.4f elsewhere\n", same, edge_change, edges, flat_change);
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
    EXPECT_NE(single_sampled.error().message.find("shade_water_per_sample needs a multisampled target"), std::string::npos)
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

// Hot reload refuses what is not SPIR-V, naming the shader, and the frame still draws.
TEST_F(RenderTest, ReloadingShadersRefusesWhatIsNotSpirv) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame;
    frame.camera.position = {900.0, 300.0, 500.0};
    frame.camera.target = {120.0, 0.0, 20.0};
    const auto before = render(*scene, frame);
    auto refused = renderer_->reload_shaders({{"water.frag", {1u, 2u, 3u}}});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("water.frag is not SPIR-V"), std::string::npos) << refused.error().message;
    const auto after = render(*scene, frame);
    EXPECT_LT(test::mean_difference(before, after), 1e-9) << "the built-in pipelines keep drawing";
}

TEST_F(RenderTest, UnsupportedFormatAndMissingDeviceAreNamed) {
    render::RendererInitInfo init;
    init.device = context();
    init.color_format = VK_FORMAT_R64G64B64A64_SFLOAT;
    auto r = render::Renderer::create(init);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::unsupported);
    EXPECT_NE(r.error().message.find("colour format"), std::string::npos) << r.error().message;
    render::StandaloneOptions options;
    options.device_name_contains = "NoSuchGPU";
    auto none = render::StandaloneDevice::create(options);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::no_device);
    EXPECT_NE(none.error().message.find("llvmpipe"), std::string::npos) << "lists what was found: " << none.error().message;
    EXPECT_NE(none.error().message.find("NoSuchGPU"), std::string::npos);
}

TEST_F(RenderTest, BadFrameInputIsAnError) {
    const Scene scene = scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}}, "ocean": "pool_calm"})");
    ASSERT_TRUE(renderer_->set_scene(scene).ok());
    auto t = render::OffscreenTarget::create(context(), 64, 64);
    ASSERT_TRUE(t.ok());
    target_ = std::move(t).value();
    render::FrameInfo frame;
    frame.time = std::nan("");
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    frame.time = 0.0;
    frame.camera.target = frame.camera.position;
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    frame.camera = render::Camera{};
    frame.camera.fov_y_deg = 0.0;
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    EXPECT_FALSE(render::OffscreenTarget::create(context(), 0, 64).ok());
    EXPECT_FALSE(render::OffscreenTarget::create(context(), 100000, 64).ok());
}

// Lakes and rivers (issue: rivers and lakes).

/// A river on a plane falling 4 m per km, bending and widening into a calm sea at x = 2500
/// (a rolling sea would bare the 0.4% beach in its troughs far from the mouth).
const char* kRiverScene = R"({ "version": 1, "name": "river", "water_level": 0.0,
  "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } }, "ocean": "pool_calm", "shore": { "enabled": false },
  "rivers": [ { "name": "bend", "path": [[-1500, 0], [-600, 120], [200, -80], [1200, 60], [2900, 40]],
                "width": [40, 44, 50, 60, 70], "discharge": 60.0, "manning": 0.032 } ] })";

// The river is drawn where it runs, at its falling surface, and nothing wet shows on the
// dry land beside it (which stands above the river's surface).
TEST_F(RenderTest, RiverIsDrawnWhereItRunsAndTheLandBesideItIsDry) {
    const Scene scene = scene_from(kRiverScene);
    render::FrameInfo frame;
    frame.camera.position = {600.0, 160.0, -320.0};
    frame.camera.target = {900.0, 0.0, 40.0};
    frame.time = 2.0;
    const auto img = render(scene, frame, 480, 270);
    const auto& path = scene.rivers[0].path;
    int river_points = 0, land_points = 0;
    for (int k = 0; k <= 40; ++k) {
        // Along the reach from (200, -80) to (1200, 60): the centreline and 120 m beside it.
        const glm::dvec2 a = path[2], b = path[3];
        const glm::dvec2 c = a + (b - a) * (k / 40.0);
        const glm::dvec2 t = glm::normalize(b - a), left{-t.y, t.x};
        const WorldPoint on = query_world_point(scene, frame.time, c);
        ASSERT_EQ(on.body.kind, BodyKind::river) << k;
        if (auto q = test::project(frame.camera, 480, 270, {c.x, on.surface.height, c.y})) {
            const Rgb col = test::block(img, q->x, q->y, 1);
            EXPECT_TRUE(is_water(col)) << "river at " << q->x << "," << q->y << ": " << col.r << " " << col.g << " " << col.b;
            ++river_points;
        }
        for (double side : {-120.0, 120.0}) {
            const glm::dvec2 d = c + left * side;
            ASSERT_EQ(query_world_point(scene, frame.time, d).body.kind, BodyKind::none);
            if (auto q = test::project(frame.camera, 480, 270, {d.x, scene.terrain.height_at(d), d.y})) {
                const Rgb col = test::block(img, q->x, q->y, 1);
                EXPECT_TRUE(is_land(col)) << "dry land at " << q->x << "," << q->y << ": " << col.r << " " << col.g << " " << col.b;
                ++land_points;
            }
        }
    }
    EXPECT_GT(river_points, 20);
    EXPECT_GT(land_points, 50);
}

// Where the river meets the sea the water is continuous: along the river's axis through its
// mouth every pixel is water, and neighbouring pixels differ by no more than the waves do.
TEST_F(RenderTest, RiverMeetsTheSeaWithoutASeam) {
    const Scene scene = scene_from(kRiverScene);
    render::FrameInfo frame;
    frame.camera.position = {2200.0, 120.0, -260.0};
    frame.camera.target = {2500.0, 0.0, 40.0};
    frame.time = 4.0;
    const auto img = render(scene, frame, 480, 270);
    int samples = 0;
    double worst_step = 0.0;
    std::optional<Rgb> last;
    for (int k = 0; k <= 120; ++k) {
        const glm::dvec2 p{2300.0 + 400.0 * k / 120.0, 40.0};
        const WorldPoint w = query_world_point(scene, frame.time, p);
        ASSERT_NE(w.body.kind, BodyKind::none) << p.x;
        const auto q = test::project(frame.camera, 480, 270, {p.x, w.surface.height, p.y});
        if (!q) continue;
        const Rgb col = test::block(img, q->x, q->y, 1);
        EXPECT_TRUE(is_water(col)) << "at x = " << p.x << " (" << q->x << "," << q->y << "): " << col.r << " " << col.g << " " << col.b;
        if (last) worst_step = std::max({worst_step, std::abs(col.r - last->r), std::abs(col.g - last->g), std::abs(col.b - last->b)});
        last = col;
        ++samples;
    }
    EXPECT_GT(samples, 60);
    EXPECT_LT(worst_step, 0.2);
}

// A lake at 30 m in a bowl of an inland scene (no ocean): water inside its waterline
// (r = 245 m), dry slopes outside it; the floor at 10 m would hide water at any lower level.
TEST_F(RenderTest, LakeSitsAtItsLevelInTheHills) {
    auto parsed = parse_scene(R"({ "version": 1, "name": "hills", "terrain": { "flat": { "height": 0.0 } },
      "lakes": [ { "name": "bowl", "level": 30.0, "at": [0, 0] } ] })", "lake.json");
    ASSERT_TRUE(parsed) << parsed.error().message;
    parsed->terrain = test::bowl_terrain();
    auto scene = test::baked(*parsed);
    ASSERT_TRUE(scene) << scene.error().message;
    render::FrameInfo frame;
    frame.camera.position = {-420.0, 260.0, -420.0};
    frame.camera.target = {0.0, 30.0, 0.0};
    frame.time = 1.0;
    const auto img = render(*scene, frame, 480, 270);
    int water = 0, land = 0;
    for (int a = 0; a < 24; ++a) {
        const glm::dvec2 dir{std::cos(a * kPi / 12.0), std::sin(a * kPi / 12.0)};
        for (double r : {0.0, 120.0, 220.0}) {
            const glm::dvec2 p = dir * r;
            if (auto q = test::project(frame.camera, 480, 270, {p.x, 30.0, p.y})) {
                const Rgb col = test::block(img, q->x, q->y, 1);
                EXPECT_TRUE(is_water(col)) << "lake at r = " << r << ": " << col.r << " " << col.g << " " << col.b;
                ++water;
            }
        }
        const glm::dvec2 p = dir * 285.0;  // the slope 8 m above the lake
        if (auto q = test::project(frame.camera, 480, 270, {p.x, scene->terrain.height_at(p), p.y})) {
            const Rgb col = test::block(img, q->x, q->y, 1);
            EXPECT_TRUE(is_land(col)) << "slope at angle " << a << ": " << col.r << " " << col.g << " " << col.b;
            ++land;
        }
    }
    EXPECT_GT(water, 40);
    EXPECT_GT(land, 12);

    // The lake draws with its own shore model: in the shore view its water shows the
    // distance to its beach (about 245 m at the centre, under 30 m near the rim), not the
    // open water's "no shore" everywhere.
    frame.view = render::DebugView::shore;
    const auto shore_img = render(*scene, frame, 480, 270);
    const auto centre = test::project(frame.camera, 480, 270, {0.0, 30.0, 0.0});
    ASSERT_TRUE(centre);
    const Rgb middle = test::block(shore_img, centre->x, centre->y, 1);
    int rim_pixels = 0;
    for (int a = 0; a < 24; ++a) {
        const glm::dvec2 p = glm::dvec2(std::cos(a * kPi / 12.0), std::sin(a * kPi / 12.0)) * 225.0;
        const auto q = test::project(frame.camera, 480, 270, {p.x, 30.0, p.y});
        if (!q) continue;
        const Rgb rim = test::block(shore_img, q->x, q->y, 1);
        const double diff = std::max({std::abs(rim.r - middle.r), std::abs(rim.g - middle.g), std::abs(rim.b - middle.b)});
        EXPECT_GT(diff, 0.25) << "rim at angle " << a << " looks like the middle: " << rim.r << " " << rim.g << " " << rim.b;
        ++rim_pixels;
    }
    EXPECT_GT(rim_pixels, 12);

    // And with its preset's ripples (0.6 m): seen from 6 m above the water, where a pixel
    // resolves them, the same lake without them shades differently. (From afar they only
    // widen the glitter: the far field is filtered.)
    frame.view = render::DebugView::normals;
    frame.camera.position = {-20.0, 36.0, -20.0};
    frame.camera.target = {0.0, 30.0, 0.0};
    const auto rippled = render(*scene, frame, 480, 270);
    Scene calm = *scene;
    WaterProfile profile = calm.lakes[0].body.profile();
    ASSERT_GT(profile.ripples.amplitude, 0.0) << "the default lake preset has ripples";
    profile.ripples.amplitude = 0.0;
    auto still = WaterBody::create(profile, calm.lakes[0].body.level(), "bowl");
    ASSERT_TRUE(still);
    auto shored = still->with_shore(calm.lakes[0].body.shore());  // the same waves: the same shore model
    ASSERT_TRUE(shored);
    calm.lakes[0].body = std::move(shored).value();
    ASSERT_TRUE(calm.baked());
    const auto smooth = render(calm, frame, 480, 270);
    int differ = 0, lake_pixels = 0;
    for (int y = 210; y < 270; y += 6)  // the bottom rows: water within about 10 m
        for (int x = 8; x < 480; x += 16) {
            const Rgb a = test::pixel(rippled, x, y), b = test::pixel(smooth, x, y);
            differ += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 0.01 ? 1 : 0;
            ++lake_pixels;
        }
    EXPECT_GT(differ, lake_pixels / 2) << differ << " of " << lake_pixels << " lake pixels change with the ripples";
}

}  // namespace
}  // namespace tidewater
