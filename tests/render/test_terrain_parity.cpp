// The terrain's GLSL twin against its C++ one (lavapipe, validation on): probe shaders
// swapped in by hot reload write, for every terrain fragment, its world x and z and what
// frame.glsl's terrain_height_at gives there; Terrain::height_at must give the same,
// inside the heightmap and beyond its edge, where both fade to the seabed.
#include <cmath>
#include <cstdio>

#include "phase_cells.hpp"
#include "probe_spirv/sky_nan.h"
#include "probe_spirv/terrain_probe_height.h"
#include "probe_spirv/terrain_probe_x.h"
#include "probe_spirv/terrain_probe_z.h"
#include "probe_spirv/water_none.h"
#include "render_fixture.hpp"

namespace tidewater {
namespace {

constexpr int kPixels = 257;                         // a side, 2 m apart
const glm::dvec2 kCenter{100.0, -50.0};              // m: off the origin, so the rect's offset counts
constexpr double kHalf = 0.5 * (kPixels - 1) * 2.0;  // m from the centre to the outermost pixel centres

/// Hills from -20 m to 30 m on a 512 m heightmap centred at kCenter (edge fade: 32 m to -20 m).
Scene hills_scene() {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = kPixels;
    image->pixels.resize(static_cast<std::size_t>(kPixels) * kPixels);
    const double lo = -20.0, hi = 30.0;
    for (int j = 0; j < kPixels; ++j)
        for (int i = 0; i < kPixels; ++i) {
            const double x = 2.0 * i, z = 2.0 * j;
            const double h = 5.0 + 12.0 * std::sin(x / 37.0) * std::cos(z / 53.0) + 6.0 * std::sin((x + z) / 23.0);
            image->pixels[static_cast<std::size_t>(j) * kPixels + i] =
                static_cast<std::uint16_t>(std::lround((h - lo) / (hi - lo) * 65535.0));
        }
    auto parsed = parse_scene(R"({"version": 1, "water_level": -100, "terrain": {"flat": {"height": -5}},
        "ocean": "pool_calm", "shore": {"enabled": false}})",
                              "hills");
    EXPECT_TRUE(parsed.ok()) << parsed.error().message;
    Scene scene = std::move(parsed).value();
    HeightmapTerrain map;
    map.size = glm::dvec2(2.0 * kHalf);
    map.center = kCenter;
    map.min_height = lo;
    map.max_height = hi;
    map.image = image;
    scene.terrain = Terrain(map);
    return scene;
}

render::Renderer::ShaderSpirv probe(const std::uint32_t* terrain, std::size_t bytes) {
    auto words = [](const std::uint32_t* w, std::size_t b) { return std::vector<std::uint32_t>(w, w + b / 4); };
    return {{"terrain.frag", words(terrain, bytes)},
            {"sky.frag", words(k_sky_nan, sizeof(k_sky_nan))},
            {"water.frag", words(k_water_none, sizeof(k_water_none))}};
}

/// The value each pixel's RGB bytes hold (terrain_probe.frag's fixed point over
/// [-range, range)), NaN where the sky probe left white.
std::vector<double> values_of(const render::RgbaImage& img, double range) {
    std::vector<double> out(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
    for (std::size_t k = 0; k < out.size(); ++k) {
        const std::uint8_t* p = img.pixels.data() + 4 * k;
        const std::uint32_t code = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                                   static_cast<std::uint32_t>(p[2]) << 16;
        out[k] = code == 0xffffffu ? std::nan("") : static_cast<double>(code) / 16777214.0 * 2.0 * range - range;
    }
    return out;
}

// Four views: across the +x edge, over the +x +z corner (both axes fade), across the -z
// edge from inside, and straight down inside. Every terrain fragment's GPU height is
// Terrain::height_at at the same point within 5 mm (16-bit heights, 8-bit filter weights).
TEST_F(RenderTest, TerrainHeightOnTheDeviceIsTerrainHeightAt) {
    const Scene scene = hills_scene();
    ASSERT_TRUE(renderer_->set_scene(scene).ok());
    constexpr int kW = 256, kH = 160;
    auto t = render::OffscreenTarget::create(context(), kW, kH);
    ASSERT_TRUE(t.ok()) << t.error().message;
    target_ = std::move(t).value();
    const std::pair<glm::dvec3, glm::dvec3> views[] = {
        {{kCenter.x + 200.0, 70.0, kCenter.y}, {kCenter.x + 300.0, -20.0, kCenter.y + 10.0}},
        {{kCenter.x + 220.0, 80.0, kCenter.y + 220.0}, {kCenter.x + 290.0, -20.0, kCenter.y + 290.0}},
        {{kCenter.x, 60.0, kCenter.y - 180.0}, {kCenter.x + 20.0, -10.0, kCenter.y - 290.0}},
        {{kCenter.x, 120.0, kCenter.y}, {kCenter.x + 60.0, 0.0, kCenter.y + 60.0}}};
    const Terrain& terrain = scene.terrain;
    std::size_t inside = 0, beyond = 0;
    double worst_inside = 0.0, worst_beyond = 0.0;
    for (const auto& [eye, at] : views) {
        render::FrameInfo frame;
        frame.camera.position = eye;
        frame.camera.target = at;
        frame.camera.fov_y_deg = 60.0;
        std::vector<double> field[3];
        const std::pair<const std::uint32_t*, std::size_t> probes[3] = {
            {k_terrain_probe_x, sizeof(k_terrain_probe_x)},
            {k_terrain_probe_z, sizeof(k_terrain_probe_z)},
            {k_terrain_probe_height, sizeof(k_terrain_probe_height)}};
        for (int f = 0; f < 3; ++f) {
            ASSERT_TRUE(renderer_->reload_shaders(probe(probes[f].first, probes[f].second)).ok());
            auto img = target_->render(*renderer_, frame);
            ASSERT_TRUE(img.ok()) << img.error().message;
            field[f] = values_of(*img, f == 2 ? 128.0 : 2048.0);
        }
        // The render origin: the camera snapped to the phase-cell grid (frame_constants.cpp).
        const glm::dvec2 origin{std::floor(eye.x / render::detail::kPhaseCellSize) * render::detail::kPhaseCellSize,
                                std::floor(eye.z / render::detail::kPhaseCellSize) * render::detail::kPhaseCellSize};
        for (std::size_t k = 0; k < field[0].size(); ++k) {
            if (!std::isfinite(field[0][k]) || !std::isfinite(field[1][k]) || !std::isfinite(field[2][k])) continue;
            const glm::dvec2 p = origin + glm::dvec2(field[0][k], field[1][k]);
            const double error = std::abs(field[2][k] - terrain.height_at(p));
            const glm::dvec2 off = glm::abs(p - kCenter);
            if (std::max(off.x, off.y) > kHalf + 0.5) {
                ++beyond;
                worst_beyond = std::max(worst_beyond, error);
            } else {
                ++inside;
                worst_inside = std::max(worst_inside, error);
            }
        }
    }
    std::printf(
        "terrain_height_at against Terrain::height_at: %zu fragments inside, worst %.2e m; %zu beyond the "
        "edge, worst %.2e m\n",
        inside, worst_inside, beyond, worst_beyond);
    EXPECT_GT(inside, 20000u);
    EXPECT_GT(beyond, 20000u);
    EXPECT_LT(worst_inside, 5e-3);
    EXPECT_LT(worst_beyond, 5e-3);
}

}  // namespace
}  // namespace tidewater
