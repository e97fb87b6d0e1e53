// The shore model in tiles: only the band where the waves feel the bottom is stored,
// and a sample from the tiles is the baked grid's own bilinear sample there, the open
// sea's (within the stated tolerances) beyond it and dry land's inland.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "../baked_scene.hpp"
#include "../tiled_coast.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

/// The tiled coast's fields over the whole extent, as its bake makes them before cutting.
const ShoreWaveFields& coast_fields() {
    static const ShoreWaveFields fields = [] {
        auto scene = test::tiled_coast_scene();
        EXPECT_TRUE(scene.ok());
        ShoreWaveOptions options;
        options.resolution = 512;
        auto baked = bake_shore_wave_fields(scene->ocean.waves(), scene->terrain, 0.0, options);
        EXPECT_TRUE(baked.ok()) << baked.error().message;
        return baked.ok() ? std::move(baked).value() : ShoreWaveFields{};
    }();
    return fields;
}

const ShoreWaves& coast_model() {
    static const std::shared_ptr<const ShoreWaves> model = [] {
        auto scene = test::tiled_coast_scene();
        return ShoreWaves::from_baked_fields(coast_fields(), scene->ocean.waves().waves());
    }();
    return *model;
}

std::uint32_t page_of(const ShoreWaves& model, int ti, int tj) {
    return model.tiles().pages[static_cast<std::size_t>(tj) * model.tiles().tiles_per_side + ti];
}

/// The longest wave's wavenumber: where k h < pi for it, some wave feels the bottom.
double longest_wavenumber(const WaveSet& set) {
    double k = 1e30;
    for (const Wave& w : set.waves()) k = std::min(k, w.k);
    return k;
}

// Tiles are stored where any wave feels the bottom (k h < 0.9 pi for the longest) and
// only near the coast (within a tile of water where k h < 1.1 pi, or of the shoreline).
TEST(ShoreTiles, OnlyTheCoastalBandIsStored) {
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const ShoreWaves& model = coast_model();
    const ShoreWaveFields& f = coast_fields();
    const ShoreTiles& tiles = model.tiles();
    const double k_long = longest_wavenumber(scene->ocean.waves());
    const int n = f.resolution, m = tiles.tiles_per_side, tile = ShoreTiles::kTile;
    ASSERT_EQ(m, (n + tile - 1) / tile);
    std::size_t stored = 0, open = 0, dry = 0;
    for (int tj = 0; tj < m; ++tj)
        for (int ti = 0; ti < m; ++ti) {
            bool feels = false, near_coast = false;
            // The tile and a tile around it.
            for (int j = std::max(0, (tj - 1) * tile); j < std::min(n, (tj + 2) * tile); ++j)
                for (int i = std::max(0, (ti - 1) * tile); i < std::min(n, (ti + 2) * tile); ++i) {
                    const std::size_t k = static_cast<std::size_t>(j) * n + i;
                    const double h = f.depth[k];
                    const bool inside =
                        i >= ti * tile && i <= (ti + 1) * tile && j >= tj * tile && j <= (tj + 1) * tile;
                    if (inside && h > 0.0 && k_long * h < 0.9 * kPi) feels = true;
                    if ((h > 0.0 && k_long * h < 1.1 * kPi) || std::abs(f.shore_distance[k]) < tile * f.texel)
                        near_coast = true;
                }
            const std::uint32_t page = page_of(model, ti, tj);
            const bool is_stored = page >= gpu::kShoreFirstStoredSlot;
            stored += is_stored, open += page == gpu::kShoreOpenSlot, dry += page == gpu::kShoreDrySlot;
            if (feels) {
                EXPECT_TRUE(is_stored) << "tile " << ti << "," << tj << " where the waves feel the bottom";
            }
            if (is_stored) {
                EXPECT_TRUE(near_coast) << "tile " << ti << "," << tj << " far from the coast";
            }
        }
    const double share = static_cast<double>(stored) / static_cast<double>(m * m);
    std::printf("tiled coast: %zu of %d tiles stored (%.0f %%), %zu open sea, %zu dry land; %.1f of %.1f MB\n", stored,
                m * m, 100.0 * share, open, dry, tiles.bytes() / 1e6,
                static_cast<double>(n) * n * ShoreWaves::query_texel_stride(model.wave_count()) * 4.0 / 1e6);
    EXPECT_EQ(tiles.stored_tiles(), stored);
    EXPECT_GT(open, 0u);
    EXPECT_GT(dry, 0u);
    EXPECT_LT(share, 0.6);
}

// In a stored tile a sample is the baked grid's bilinear sample, bit for bit; in the open
// sea within kOpenSea*Tolerance of the waves as they are; on dry land no wave at all.
TEST(ShoreTiles, SamplesMatchTheBakedGrid) {
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const ShoreWaves& model = coast_model();
    const ShoreWaveFields& f = coast_fields();
    const auto waves = scene->ocean.waves().waves();
    const std::size_t nw = waves.size();
    std::vector<LocalWave> local(nw);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> across(f.corner.x - 50.0, f.corner.x + f.resolution * f.texel + 50.0);
    std::size_t counts[3] = {0, 0, 0};
    for (int s = 0; s < 40000; ++s) {
        const glm::dvec2 p{across(rng), across(rng)};
        const detail::GridTaps taps = detail::grid_taps(f.corner, f.texel, f.resolution, p);
        const int i = static_cast<int>(taps.k00 % f.resolution), j = static_cast<int>(taps.k00 / f.resolution);
        const std::uint32_t page = page_of(model, i / ShoreTiles::kTile, j / ShoreTiles::kTile);
        const LocalShore got = model.sample(p, local);
        if (page >= gpu::kShoreFirstStoredSlot) {
            ++counts[0];
            ASSERT_EQ(got.depth, taps(f.depth)) << p.x << "," << p.y;
            ASSERT_EQ(got.shore_distance, taps(f.shore_distance));
            ASSERT_EQ(got.breaking, taps(f.breaking));
            ASSERT_EQ(got.steepness_scale, taps(f.steepness_scale));
            for (std::size_t w = 0; w < nw; ++w) {
                ASSERT_EQ(local[w].phase_residual, taps(f.phase_residual[w]));
                ASSERT_EQ(local[w].wavevector.x, taps(f.wavevector_x[w]));
                ASSERT_EQ(local[w].wavevector.y, taps(f.wavevector_z[w]));
                if (got.depth > 0.0) {
                    ASSERT_EQ(local[w].amplitude_factor, taps(f.amplitude_factor[w]));
                }
            }
        } else if (page == gpu::kShoreOpenSlot) {
            ++counts[1];
            ASSERT_GT(taps(f.depth), 0.0);
            EXPECT_EQ(shore_far_to_infinite(got.depth), kDeepWater);
            EXPECT_EQ(shore_far_to_infinite(got.shore_distance), kDeepWater);
            EXPECT_EQ(got.breaking, 0.0);
            EXPECT_NEAR(got.steepness_scale, 1.0, 1e-12);
            for (std::size_t w = 0; w < nw; ++w) {
                const glm::dvec2 open = waves[w].k * glm::dvec2(waves[w].dir_x, waves[w].dir_z);
                ASSERT_NEAR(taps(f.phase_residual[w]), local[w].phase_residual, kOpenSeaPhaseTolerance);
                ASSERT_NEAR(taps(f.amplitude_factor[w]), local[w].amplitude_factor, kOpenSeaRelativeTolerance);
                ASSERT_NEAR(taps(f.wavevector_x[w]), open.x, kOpenSeaRelativeTolerance * waves[w].k);
                ASSERT_NEAR(taps(f.wavevector_z[w]), open.y, kOpenSeaRelativeTolerance * waves[w].k);
                ASSERT_NEAR(local[w].wavevector.x, open.x, 1e-6 * waves[w].k) << "k0 D in float";
                ASSERT_NEAR(local[w].wavevector.y, open.y, 1e-6 * waves[w].k);
            }
        } else {
            ++counts[2];
            ASSERT_LE(taps(f.depth), 0.0);
            EXPECT_EQ(shore_far_to_infinite(got.depth), -kDeepWater);
            for (std::size_t w = 0; w < nw; ++w) ASSERT_EQ(local[w].amplitude_factor, 0.0);
        }
    }
    std::printf("samples: %zu in stored tiles, %zu open sea, %zu dry land\n", counts[0], counts[1], counts[2]);
    EXPECT_GT(counts[0], 1000u);
    EXPECT_GT(counts[1], 1000u);
    EXPECT_GT(counts[2], 100u);
}

// Queries report what the tiles do not store as the terrain says: a world query far
// offshore and far inland gives the depth from the ground, a body query infinity.
TEST(ShoreTiles, QueriesBeyondTheBandReportTheGround) {
    auto scene = test::baked(test::tiled_coast_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const std::vector<glm::dvec2> points{{0.0, 1900.0}, {100.0, 0.0}, {0.0, 1000.0}};
    std::vector<SurfacePoint> body(points.size());
    ASSERT_TRUE(query_surface(scene->ocean, 0.0, points, body).ok());
    EXPECT_EQ(body[0].depth, kDeepWater) << "open sea";
    EXPECT_EQ(body[1].depth, -kDeepWater) << "the island's heart";
    EXPECT_FALSE(body[1].wet);
    EXPECT_TRUE(std::isfinite(body[2].depth)) << "in the band";
    EXPECT_NEAR(body[2].depth, -test::tiled_coast_height(1000.0), 0.5);
    std::vector<WorldPoint> world(points.size());
    ASSERT_TRUE(query_world(*scene, 0.0, points, world).ok());
    EXPECT_NEAR(world[0].surface.depth, -test::tiled_coast_height(1900.0), 0.5);
    EXPECT_NEAR(world[2].surface.depth, body[2].depth, 1e-9);
}

}  // namespace
}  // namespace tidewater
