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

/// The tiled coast's model baked twice: as a scene bakes it (the band), and with every
/// tile stored (the open sea's and dry land's too), which the band is checked against.
struct CoastModels {
    std::shared_ptr<const ShoreWaves> band, every;
};
const CoastModels& coast_models() {
    static const CoastModels models = [] {
        CoastModels out;
        auto scene = test::tiled_coast_scene();
        EXPECT_TRUE(scene.ok());
        for (bool every : {false, true}) {
            ShoreWaveOptions options;
            options.resolution = 512;
            options.store_every_tile = every;
            auto baked = bake_shore_waves(scene->ocean.waves(), scene->terrain, 0.0, options);
            EXPECT_TRUE(baked.ok()) << baked.error().message;
            if (baked.ok()) (every ? out.every : out.band) = *baked;
        }
        return out;
    }();
    return models;
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
    const ShoreWaves& model = *coast_models().band;
    const ShoreWaves& every = *coast_models().every;
    const ShoreTiles& tiles = model.tiles();
    const double k_long = longest_wavenumber(scene->ocean.waves());
    const int n = model.resolution(), m = tiles.tiles_per_side, tile = ShoreTiles::kTile;
    EXPECT_EQ(every.tiles().stored_tiles(), static_cast<std::size_t>(m * m));
    ASSERT_EQ(m, (n + tile - 1) / tile);
    std::size_t stored = 0, open = 0, dry = 0;
    for (int tj = 0; tj < m; ++tj)
        for (int ti = 0; ti < m; ++ti) {
            bool feels = false, near_coast = false;
            // The tile and a tile around it.
            for (int j = std::max(0, (tj - 1) * tile); j < std::min(n, (tj + 2) * tile); ++j)
                for (int i = std::max(0, (ti - 1) * tile); i < std::min(n, (ti + 2) * tile); ++i) {
                    const ShoreTexelView t = every.texel_values(i, j);
                    const double h = t.depth();
                    const bool inside =
                        i >= ti * tile && i <= (ti + 1) * tile && j >= tj * tile && j <= (tj + 1) * tile;
                    if (inside && h > 0.0 && k_long * h < 0.9 * kPi) feels = true;
                    if ((h > 0.0 && k_long * h < 1.1 * kPi) || std::abs(t.shore_distance()) < tile * model.texel())
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
    std::printf(
        "tiled coast: %zu of %d tiles stored (%.0f %%), %zu open sea, %zu dry land; %.1f MB (%.1f MB with every "
        "tile)\n",
        stored, m * m, 100.0 * share, open, dry, tiles.bytes() / 1e6, every.tiles().bytes() / 1e6);
    EXPECT_EQ(tiles.stored_tiles(), stored);
    EXPECT_GT(open, 0u);
    EXPECT_GT(dry, 0u);
    EXPECT_LT(share, 0.6);
}

// In a stored tile a sample is the same as with every tile stored, bit for bit; in the open
// sea within kOpenSea*Tolerance of it; on dry land no wave at all.
TEST(ShoreTiles, SamplesMatchTheModelWithEveryTileStored) {
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const ShoreWaves& model = *coast_models().band;
    const ShoreWaves& every = *coast_models().every;
    const auto waves = scene->ocean.waves().waves();
    const std::size_t nw = waves.size();
    std::vector<LocalWave> local(nw), full(nw);
    std::mt19937_64 rng(3);
    const double lo = model.corner().x, hi = lo + model.resolution() * model.texel();
    std::uniform_real_distribution<double> across(lo - 50.0, hi + 50.0);
    std::size_t counts[3] = {0, 0, 0};
    for (int s = 0; s < 40000; ++s) {
        const glm::dvec2 p{across(rng), across(rng)};
        const int n = model.resolution();
        const detail::GridTaps taps = detail::grid_taps(model.corner(), model.texel(), n, p);
        const int i = static_cast<int>(taps.k00 % n), j = static_cast<int>(taps.k00 / n);
        const std::uint32_t page = page_of(model, i / ShoreTiles::kTile, j / ShoreTiles::kTile);
        const LocalShore got = model.sample(p, local);
        const LocalShore want = every.sample(p, full);
        if (page >= gpu::kShoreFirstStoredSlot) {
            ++counts[0];
            ASSERT_EQ(got.depth, want.depth) << p.x << "," << p.y;
            ASSERT_EQ(got.shore_distance, want.shore_distance);
            ASSERT_EQ(got.breaking, want.breaking);
            ASSERT_EQ(got.steepness_scale, want.steepness_scale);
            for (std::size_t w = 0; w < nw; ++w) {
                ASSERT_EQ(local[w].phase_residual, full[w].phase_residual);
                ASSERT_EQ(local[w].wavevector, full[w].wavevector);
                ASSERT_EQ(local[w].amplitude_factor, full[w].amplitude_factor);
            }
        } else if (page == gpu::kShoreOpenSlot) {
            ++counts[1];
            ASSERT_GT(want.depth, 0.0);
            EXPECT_EQ(want.breaking, 0.0);
            EXPECT_NEAR(want.steepness_scale, 1.0, 1e-12);
            EXPECT_EQ(shore_far_to_infinite(got.depth), kDeepWater);
            EXPECT_EQ(shore_far_to_infinite(got.shore_distance), kDeepWater);
            EXPECT_EQ(got.breaking, 0.0);
            EXPECT_NEAR(got.steepness_scale, 1.0, 1e-12);
            for (std::size_t w = 0; w < nw; ++w) {
                const glm::dvec2 open = waves[w].k * glm::dvec2(waves[w].dir_x, waves[w].dir_z);
                ASSERT_NEAR(full[w].phase_residual, local[w].phase_residual, kOpenSeaPhaseTolerance);
                ASSERT_NEAR(full[w].amplitude_factor, local[w].amplitude_factor, kOpenSeaRelativeTolerance);
                ASSERT_NEAR(full[w].wavevector.x, open.x, kOpenSeaRelativeTolerance * waves[w].k);
                ASSERT_NEAR(full[w].wavevector.y, open.y, kOpenSeaRelativeTolerance * waves[w].k);
                ASSERT_NEAR(local[w].wavevector.x, open.x, 1e-6 * waves[w].k) << "k0 D in float";
                ASSERT_NEAR(local[w].wavevector.y, open.y, 1e-6 * waves[w].k);
            }
        } else {
            ++counts[2];
            ASSERT_LE(want.depth, 0.0);
            EXPECT_EQ(shore_far_to_infinite(got.depth), -kDeepWater);
            for (std::size_t w = 0; w < nw; ++w) {
                ASSERT_EQ(local[w].amplitude_factor, 0.0);
                ASSERT_EQ(full[w].amplitude_factor, 0.0);
            }
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

// Tiles read elsewhere are refused when they do not fit their grid, their waves or hold a
// value that is not finite; the shared slots are written by the model, not trusted.
TEST(ShoreTiles, TilesFromElsewhereAreChecked) {
    const ShoreWaves& model = *coast_models().band;
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const auto waves = scene->ocean.waves().waves();
    auto rebuilt = ShoreWaves::from_tiles(model.grid(), model.tiles(), waves);
    ASSERT_TRUE(rebuilt.ok()) << rebuilt.error().message;
    EXPECT_EQ((*rebuilt)->tiles().texels, model.tiles().texels);

    ShoreTiles bad_page = model.tiles();
    bad_page.pages[3] = static_cast<std::uint32_t>(bad_page.slot_count());
    EXPECT_NE(ShoreWaves::from_tiles(model.grid(), bad_page, waves).error().message.find("names slot"),
              std::string::npos);
    ShoreTiles short_pages = model.tiles();
    short_pages.pages.pop_back();
    EXPECT_NE(ShoreWaves::from_tiles(model.grid(), short_pages, waves).error().message.find("pages"),
              std::string::npos);
    EXPECT_NE(ShoreWaves::from_tiles(model.grid(), model.tiles(), waves.subspan(1)).error().message.find("waves"),
              std::string::npos);
    ShoreTiles nan = model.tiles();
    nan.texels.back() = std::nanf("");
    EXPECT_NE(ShoreWaves::from_tiles(model.grid(), nan, waves).error().message.find("not finite"), std::string::npos);
    ShoreTiles constant = model.tiles();
    std::fill(constant.texels.begin(), constant.texels.begin() + 100, 7.0f);  // the open sea's slot
    auto refilled = ShoreWaves::from_tiles(model.grid(), constant, waves);
    ASSERT_TRUE(refilled.ok());
    EXPECT_EQ((*refilled)->tiles().texels, model.tiles().texels);
}

// Over a renderer's budget the model is drawn on every k-th texel: each coarse texel holds
// the fine texel it stands on, coarse tiles are stored only where a fine one under them is,
// and the bytes the renderer sizes the budget by are those of the model it then makes.
TEST(ShoreTiles, ACoarsenedModelHoldsEveryKthTexel) {
    const ShoreWaves& fine = *coast_models().band;
    const std::size_t floats = fine.tiles().stride;
    for (int stride : {2, 3, 5}) {
        const auto coarse = fine.coarsened(stride);
        ASSERT_TRUE(coarse);
        EXPECT_EQ(coarse->resolution(), (fine.resolution() - 1) / stride + 1);
        EXPECT_NEAR(coarse->texel(), fine.texel() * stride, 1e-12);
        EXPECT_EQ(coarse->coarsened_device_bytes(1), coarse->tiles().device_bytes());
        EXPECT_EQ(fine.coarsened_device_bytes(stride), coarse->tiles().device_bytes()) << "stride " << stride;
        std::size_t differing = 0;
        for (int j = 0; j < coarse->resolution(); ++j)
            for (int i = 0; i < coarse->resolution(); ++i) {
                const float* c = coarse->texel_values(i, j).t;
                const float* f = fine.texel_values(i * stride, j * stride).t;
                differing += !std::equal(c, c + floats, f);
                EXPECT_NEAR(glm::length(coarse->texel_center(i, j) - fine.texel_center(i * stride, j * stride)), 0.0,
                            1e-9);
            }
        EXPECT_EQ(differing, 0u) << "stride " << stride;
        const double fine_share = static_cast<double>(fine.tiles().stored_tiles()) /
                                  static_cast<double>(fine.tiles().pages.size()),
                     coarse_share = static_cast<double>(coarse->tiles().stored_tiles()) /
                                    static_cast<double>(coarse->tiles().pages.size());
        std::printf("stride %d: %zu of %zu tiles stored (%.0f %%; %.0f %% at full resolution), %.1f MiB\n", stride,
                    coarse->tiles().stored_tiles(), coarse->tiles().pages.size(), 100.0 * coarse_share,
                    100.0 * fine_share, static_cast<double>(coarse->tiles().device_bytes()) / 1048576.0);
        EXPECT_LT(coarse->tiles().device_bytes(), fine.tiles().device_bytes());
        EXPECT_GT(coarse->tiles().stored_tiles(), 0u);
        EXPECT_LT(coarse->tiles().stored_tiles(), coarse->tiles().pages.size()) << "open sea and dry land left out";
    }
    EXPECT_EQ(fine.coarsened(1)->tiles().texels, fine.tiles().texels);
}

}  // namespace
}  // namespace tidewater
