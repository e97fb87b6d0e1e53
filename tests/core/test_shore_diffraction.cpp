// Diffraction into a breakwater's shadow against Sommerfeld's solution: a plane wave past
// the tip of a long, thin breakwater on a flat bed. Far behind the tip (the march's
// small-angle limit), the height over the incident is the Fresnel integral's
// |F(v)| = |(1/2 + C(v)) + i (1/2 + S(v))| / sqrt(2), v = y sqrt(2 / (lambda x)) across the
// shadow's edge: 0.5 on the edge, 0.145 at v = -1.5 in the shadow and 1.08 at v = 1.5.
// The rays alone leave the shadow's edge at full height.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "../baked_scene.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/dispersion.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

constexpr double kDepth = 5.0, kDeepWavelength = 20.0, kPixel = 0.5;
// The bed: x from -100 to 100 m, z from -400 to 100 m (centred on z = -150); the
// breakwater's far end, 400 m off, adds under 0.01 to the heights compared.
constexpr double kSizeX = 200.0, kSizeZ = 500.0, kCenterZ = -150.0;

/// The flat bed with land where `land(x, z)` holds, as a raw 16-bit heightmap in `dir`;
/// `diffraction` and the shore model's `resolution` as the scene's.
template <class Land>
Result<Scene> bed(const fs::path& dir, bool diffraction, int resolution, const Land& land) {
    const int nx = static_cast<int>(kSizeX / kPixel) + 1, nz = static_cast<int>(kSizeZ / kPixel) + 1;
    std::vector<std::uint16_t> pixels(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz));
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = -0.5 * kSizeX + i * kPixel, z = kCenterZ - 0.5 * kSizeZ + j * kPixel;
            pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] =
                land(x, z) ? 65535 : 0;
        }
    std::ofstream(dir / "breakwater.raw", std::ios::binary)
        .write(reinterpret_cast<const char*>(pixels.data()), static_cast<std::streamsize>(2 * pixels.size()));
    const std::string json = fmt::format(
        R"({{"version": 1, "name": "breakwater", "water_level": 0,
            "shore": {{"resolution": {}, "texels_per_wavelength": 0, "diffraction": {}}},
            "terrain": {{"heightmap": {{"file": "breakwater.raw", "format": "raw16", "raw": {{"width": {}, "height": {}}},
                         "size": [{}, {}], "height_range": [{}, 2.0], "center": [0, {}]}}}},
            "ocean": {{"waves": [{{"direction": 0, "wavelength": {}, "amplitude": 0.05, "steepness": 0}}]}}}})",
        resolution, diffraction ? "true" : "false", nx, nz, kSizeX, kSizeZ, -kDepth, kCenterZ, kDeepWavelength);
    return test::baked(parse_scene(json, (dir / "breakwater.json").string(), dir));
}

/// A breakwater 2 m thick along x = 0 from its tip (z = 0) to the bed's edge.
Result<Scene> breakwater(const fs::path& dir, bool diffraction) {
    return bed(dir, diffraction, 1024, [](double x, double z) { return std::abs(x) <= 1.0 && z <= 0.0; });
}

/// An islet 80 m square at (0, -150) on the shore model of `resolution` texels a side.
Result<Scene> islet(const fs::path& dir, bool diffraction, int resolution) {
    return bed(dir, diffraction, resolution,
               [](double x, double z) { return std::abs(x) <= 40.0 && std::abs(z - kCenterZ) <= 40.0; });
}

/// Height over the incident height at `p` (crest to trough over a period).
double height_ratio(const Scene& scene, glm::dvec2 p, double period, double incident) {
    double lo = 1e9, hi = -1e9;
    for (int s = 0; s < 64; ++s) {
        const double y = query_world_point(scene, period * s / 64.0, p).surface.height;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    return (hi - lo) / incident;
}

TEST(ShoreDiffraction, ABreakwatersShadowFillsAsSommerfeldSays) {
    const fs::path dir = fs::temp_directory_path() / fmt::format("tidewater_breakwater_{}", ::getpid());
    fs::create_directories(dir);
    auto marched = breakwater(dir, true);
    auto rays = breakwater(dir, false);
    fs::remove_all(dir);
    ASSERT_TRUE(marched.ok()) << marched.error().message;
    ASSERT_TRUE(rays.ok()) << rays.error().message;
    const double omega = deep_water_omega(kDeepWavelength), period = kTwoPi / omega;
    const double wavelength = kTwoPi / wavenumber_at_depth(omega, kDepth);
    const double incident = 2.0 * 0.05 * shoaling_coefficient(omega, kDepth);
    // Fresnel's |F(v)| at v = -1.5, 0, 1.5 (tables of C and S).
    const double expected[] = {0.145, 0.5, 1.079};
    double worst = 0.0, rays_edge = 0.0;
    for (double x : {60.0, 80.0}) {
        for (int k = 0; k < 3; ++k) {
            const double v = -1.5 + 1.5 * k, z = v * std::sqrt(0.5 * wavelength * x);
            const double got = height_ratio(*marched, {x, z}, period, incident);
            std::printf("behind the tip by %.0f m, v = %+.1f (z = %+.1f m): H/H0 %.3f (Sommerfeld %.3f)\n", x, v, z,
                        got, expected[k]);
            worst = std::max(worst, std::abs(got - expected[k]));
            if (k == 1) rays_edge = std::max(rays_edge, height_ratio(*rays, {x, z}, period, incident));
        }
    }
    std::printf("largest difference from Sommerfeld %.3f; the rays alone on the shadow's edge: %.3f\n", worst,
                rays_edge);
    EXPECT_LT(worst, 0.05);
    EXPECT_GT(rays_edge, 0.8);
}

// A wave the shore model's grid cannot resolve is left to the rays: round an islet on a
// 16^2 model of the bed (31 m texels against the wave's 18.5 m local wavelength) the march
// would have under 2 points a wavelength at its finest spacing (half a texel), so the bake
// with diffraction is the rays' alone, to the bit; on a 64^2 model (7.8 m texels, 4.7
// points) the march has its share and changes the heights round the islet.
TEST(ShoreDiffraction, AWaveShorterThanTheGridsTexelIsLeftToTheRays) {
    const fs::path dir = fs::temp_directory_path() / fmt::format("tidewater_islet_{}", ::getpid());
    fs::create_directories(dir);
    auto marched = islet(dir, true, 16), rays = islet(dir, false, 16);
    auto marched_finer = islet(dir, true, 64), rays_finer = islet(dir, false, 64);
    fs::remove_all(dir);
    for (const auto* s : {&marched, &rays, &marched_finer, &rays_finer}) ASSERT_TRUE(s->ok()) << s->error().message;
    double coarse = 0.0, finer = 0.0;
    for (double x : {-60.0, 0.0, 30.0, 60.0})
        for (double z : {-300.0, -230.0, -70.0, 0.0, 80.0}) {
            const double t = 3.0;
            coarse = std::max(coarse, std::abs(query_world_point(*marched, t, {x, z}).surface.height -
                                               query_world_point(*rays, t, {x, z}).surface.height));
            finer = std::max(finer, std::abs(query_world_point(*marched_finer, t, {x, z}).surface.height -
                                             query_world_point(*rays_finer, t, {x, z}).surface.height));
        }
    std::printf("largest height difference, marched against rays alone: 16^2 model %.3g m, 64^2 model %.3g m\n", coarse,
                finer);
    EXPECT_EQ(coarse, 0.0);
    EXPECT_GT(finer, 1e-3);
}

}  // namespace
}  // namespace tidewater
