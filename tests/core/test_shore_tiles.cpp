// The shore model in tiles: only the band where the waves feel the bottom is stored,
// and a sample from the tiles is the baked grid's own bilinear sample there, the open
// sea's (within the stated tolerances) beyond it and dry land's inland.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "../baked_scene.hpp"
#include "../shore_model_compare.hpp"
#include "../tiled_coast.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

/// The tiled coast's shore model at `resolution`² with `texels_per_wavelength`, every tile
/// stored or only the band.
std::shared_ptr<const ShoreWaves> bake_coast(int resolution, double texels_per_wavelength, bool every_tile = false) {
    auto scene = test::tiled_coast_scene();
    EXPECT_TRUE(scene.ok());
    ShoreWaveOptions options;
    options.resolution = resolution;
    options.store_every_tile = every_tile;
    options.texels_per_wavelength = texels_per_wavelength;
    auto baked = bake_shore_waves(scene->ocean.waves(), scene->terrain, 0.0, options);
    EXPECT_TRUE(baked.ok()) << baked.error().message;
    return baked.ok() ? *baked : nullptr;
}

/// The tiled coast's model, every wave on the model's grid, baked twice: as a scene bakes
/// it (the band), and with every tile stored (the open sea's and dry land's too), which
/// the band is checked against.
struct CoastModels {
    std::shared_ptr<const ShoreWaves> band, every;
};
const CoastModels& coast_models() {
    static const CoastModels models{bake_coast(512, 0.0), bake_coast(512, 0.0, true)};
    return models;
}

/// The tiled coast's model with its waves in runs: 8 texels a deep-water wavelength (half
/// the default) puts the preset's longest waves on a grid of twice the model's texel.
std::shared_ptr<const ShoreWaves> layered_coast() {
    static const std::shared_ptr<const ShoreWaves> model = bake_coast(512, 8.0);
    return model;
}

std::uint32_t page_of(const ShoreTiles& tiles, int ti, int tj) {
    return tiles.pages[static_cast<std::size_t>(tj) * tiles.tiles_per_side + ti];
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
    ASSERT_EQ(model.layers().size(), 1u) << "every wave on the model's grid";
    const ShoreTiles& tiles = model.shared();
    EXPECT_EQ(model.layers()[0].tiles.pages, tiles.pages) << "the waves are stored where the shared fields are";
    const double k_long = longest_wavenumber(scene->ocean.waves());
    const int n = model.resolution(), m = tiles.tiles_per_side, tile = ShoreTiles::kTile;
    EXPECT_EQ(every.shared().stored_tiles(), static_cast<std::size_t>(m * m));
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
            const std::uint32_t page = page_of(tiles, ti, tj);
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
        stored, m * m, 100.0 * share, open, dry, model.bytes() / 1e6, every.bytes() / 1e6);
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
        const std::uint32_t page = page_of(model.shared(), i / ShoreTiles::kTile, j / ShoreTiles::kTile);
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
    const std::vector<ShoreWaveLayer> runs(model.layers().begin(), model.layers().end());
    auto rebuilt = ShoreWaves::from_tiles(model.grid(), model.shared(), runs, waves);
    ASSERT_TRUE(rebuilt.ok()) << rebuilt.error().message;
    EXPECT_TRUE(test::same_tiles(**rebuilt, model));
    auto refused = [&](const ShoreTiles& shared, const std::vector<ShoreWaveLayer>& layers, std::span<const Wave> w) {
        auto r = ShoreWaves::from_tiles(model.grid(), shared, layers, w);
        return r.ok() ? std::string("accepted") : r.error().message;
    };

    ShoreTiles bad_page = model.shared();
    bad_page.pages[3] = static_cast<std::uint32_t>(bad_page.slot_count());
    EXPECT_NE(refused(bad_page, runs, waves).find("names slot"), std::string::npos);
    ShoreTiles short_pages = model.shared();
    short_pages.pages.pop_back();
    EXPECT_NE(refused(short_pages, runs, waves).find("pages"), std::string::npos);
    EXPECT_NE(refused(model.shared(), runs, waves.subspan(1)).find("waves"), std::string::npos);
    std::vector<ShoreWaveLayer> nan = runs;
    nan[0].tiles.slot_for_writing(nan[0].tiles.slot_count() - 1)[nan[0].tiles.slot_floats() - 1] = std::nanf("");
    EXPECT_NE(refused(model.shared(), nan, waves).find("not finite"), std::string::npos);
    std::vector<ShoreWaveLayer> gap = runs;
    gap[0].first = 1;
    EXPECT_NE(refused(model.shared(), gap, waves).find("expected a run from wave 0"), std::string::npos);
    std::vector<ShoreWaveLayer> wrong_grid = runs;
    wrong_grid[0].grid.resolution /= 2;
    EXPECT_NE(refused(model.shared(), wrong_grid, waves).find("pages"), std::string::npos);
    ShoreTiles constant = model.shared();
    std::fill_n(constant.slot_for_writing(gpu::kShoreOpenSlot), 100, 7.0f);
    std::vector<ShoreWaveLayer> constant_runs = runs;
    std::fill_n(constant_runs[0].tiles.slot_for_writing(gpu::kShoreOpenSlot), 100, 7.0f);
    auto refilled = ShoreWaves::from_tiles(model.grid(), constant, constant_runs, waves);
    ASSERT_TRUE(refilled.ok());
    EXPECT_TRUE(test::same_tiles(**refilled, model));
}

// Over a renderer's budget the model is drawn on every k-th texel: each coarse texel holds
// the fine texel it stands on, coarse tiles are stored only where a fine one under them is,
// and the bytes the renderer sizes the budget by are those of the model it then makes.
TEST(ShoreTiles, ACoarsenedModelHoldsEveryKthTexel) {
    const ShoreWaves& fine = *layered_coast();
    ASSERT_GE(fine.layers().size(), 2u);
    // Each layer's grid and tiles coarsened alike.
    auto layers_of = [](const ShoreWaves& m) {
        std::vector<std::pair<ShoreGrid, const ShoreTiles*>> out{{m.grid(), &m.shared()}};
        for (const ShoreWaveLayer& l : m.layers()) out.push_back({l.grid, &l.tiles});
        return out;
    };
    for (int stride : {2, 3, 5}) {
        const auto coarse = fine.coarsened(stride);
        ASSERT_TRUE(coarse);
        EXPECT_EQ(coarse->coarsened_device_bytes(1), coarse->device_bytes());
        EXPECT_EQ(fine.coarsened_device_bytes(stride), coarse->device_bytes()) << "stride " << stride;
        const auto f = layers_of(fine), c = layers_of(*coarse);
        ASSERT_EQ(c.size(), f.size());
        std::size_t differing = 0, stored = 0, pages = 0;
        for (std::size_t l = 0; l < f.size(); ++l) {
            const auto& [fg, ft] = f[l];
            const auto& [cg, ct] = c[l];
            EXPECT_EQ(cg.resolution, (fg.resolution - 1) / stride + 1);
            EXPECT_NEAR(cg.texel, fg.texel * stride, 1e-12);
            for (int j = 0; j < cg.resolution; ++j)
                for (int i = 0; i < cg.resolution; ++i) {
                    const float* cv = ct->texel(i, j);
                    const float* fv = ft->texel(i * stride, j * stride);
                    differing += !std::equal(cv, cv + ft->stride, fv);
                    const glm::dvec2 cc = cg.corner + cg.texel * glm::dvec2(i + 0.5, j + 0.5);
                    const glm::dvec2 fc = fg.corner + fg.texel * glm::dvec2(i * stride + 0.5, j * stride + 0.5);
                    EXPECT_NEAR(glm::length(cc - fc), 0.0, 1e-9);
                }
            stored += ct->stored_tiles();
            pages += ct->pages.size();
        }
        EXPECT_EQ(differing, 0u) << "stride " << stride;
        std::printf("stride %d: %zu of %zu tiles stored over %zu layers, %.1f MiB (%.1f MiB at full resolution)\n",
                    stride, stored, pages, f.size(), static_cast<double>(coarse->device_bytes()) / 1048576.0,
                    static_cast<double>(fine.device_bytes()) / 1048576.0);
        EXPECT_LT(coarse->device_bytes(), fine.device_bytes());
        EXPECT_GT(stored, 0u);
        EXPECT_LT(stored, pages) << "open sea and dry land left out";
    }
    EXPECT_TRUE(test::same_tiles(*fine.coarsened(1), fine));
}

// The preset's longer waves lie on coarser grids: each run's texel keeps at least the
// asked texels a deep-water wavelength for its shortest wave (and twice that texel would
// not, unless the run's grid would shrink under a tile), the runs cover the waves in order,
// and the model takes less memory than with every wave on the model's grid. Depth and shore
// distance stay the one-grid model's, bit for bit.
TEST(ShoreLayers, LongWavesLieOnCoarserGrids) {
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const ShoreWaves& layered = *layered_coast();
    const ShoreWaves& one = *coast_models().band;
    const auto waves = scene->ocean.waves().waves();
    std::size_t next = 0;
    for (const ShoreWaveLayer& run : layered.layers()) {
        EXPECT_EQ(run.first, next);
        next += run.count;
        const double scale = run.grid.texel / layered.texel();
        EXPECT_NEAR(scale, std::exp2(std::round(std::log2(scale))), 1e-9) << "a power of two";
        EXPECT_EQ(run.grid.corner, layered.corner());
        EXPECT_EQ(run.grid.resolution, (layered.resolution() + static_cast<int>(scale) - 1) / static_cast<int>(scale));
        double shortest = 1e300;
        for (std::size_t w = run.first; w < run.first + run.count; ++w)
            shortest = std::min(shortest, kTwoPi / waves[w].k);
        if (scale > 1.0) {
            EXPECT_LE(8.0 * run.grid.texel, shortest + 1e-9) << "8 texels to its shortest wave";
        }
        const bool finer_grid_small =
            (layered.resolution() + 2 * static_cast<int>(scale) - 1) / (2 * static_cast<int>(scale)) <
            ShoreTiles::kTile;
        EXPECT_TRUE(finer_grid_small || 16.0 * run.grid.texel > shortest) << "as coarse as keeps 8 texels";
        std::printf("run of waves %zu to %zu: %.1f m texels (shortest wave %.1f m), %zu of %zu tiles stored\n",
                    run.first, run.first + run.count - 1, run.grid.texel, shortest, run.tiles.stored_tiles(),
                    run.tiles.pages.size());
    }
    EXPECT_EQ(next, waves.size());
    EXPECT_GE(layered.layers().size(), 2u);
    EXPECT_GT(layered.layers().front().grid.texel, layered.texel()) << "the spectrum's longest waves come first";
    std::printf("layered: %.1f MiB on the GPU, %.1f MiB with every wave on the model's grid\n",
                static_cast<double>(layered.device_bytes()) / 1048576.0,
                static_cast<double>(one.device_bytes()) / 1048576.0);
    EXPECT_LT(layered.device_bytes(), one.device_bytes() * 3 / 4);
    for (int j = 0; j < layered.resolution(); j += 3)
        for (int i = 0; i < layered.resolution(); i += 3) {
            ASSERT_EQ(layered.texel_values(i, j).depth(), one.texel_values(i, j).depth());
            ASSERT_EQ(layered.texel_values(i, j).shore_distance(), one.texel_values(i, j).shore_distance());
        }
}

// The waves from coarser grids are the waves from the model's grid: against the same coast
// on a grid twice as fine, the surface from the runs differs no more (within 10 %) than the
// one-grid model's own does, over the coast's water at three times (the model's texel is
// what limits it: the preset's shortest waves are 2.3 texels long on it).
TEST(ShoreLayers, CoarserGridsKeepTheSurface) {
    auto scene = test::tiled_coast_scene();
    ASSERT_TRUE(scene.ok());
    const auto fine_model = bake_coast(1024, 0.0);
    ASSERT_TRUE(fine_model);
    auto layered = scene->ocean.with_shore(layered_coast());
    auto one = scene->ocean.with_shore(coast_models().band);
    auto fine = scene->ocean.with_shore(fine_model);
    ASSERT_TRUE(layered.ok() && one.ok() && fine.ok());
    std::vector<glm::dvec2> points;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> radius(test::kCoastBeachRadius, 1400.0), angle(0.0, kTwoPi);
    for (int k = 0; k < 4000; ++k) {
        const double r = radius(rng), a = angle(rng);
        points.push_back({r * std::cos(a), r * std::sin(a)});
    }
    std::vector<SurfacePoint> a(points.size()), b(points.size()), f(points.size());
    double sum2 = 0.0, layered2 = 0.0, one2 = 0.0;
    std::size_t wet = 0;
    for (double t : {0.0, 3.7, 11.2}) {
        ASSERT_TRUE(query_surface(*layered, t, points, a).ok());
        ASSERT_TRUE(query_surface(*one, t, points, b).ok());
        ASSERT_TRUE(query_surface(*fine, t, points, f).ok());
        for (std::size_t k = 0; k < points.size(); ++k) {
            if (!(a[k].wet && b[k].wet && f[k].wet)) continue;
            ++wet;
            sum2 += f[k].height * f[k].height;
            layered2 += (a[k].height - f[k].height) * (a[k].height - f[k].height);
            one2 += (b[k].height - f[k].height) * (b[k].height - f[k].height);
        }
    }
    const double count = static_cast<double>(wet);
    const double rms = std::sqrt(sum2 / count), rms_layered = std::sqrt(layered2 / count),
                 rms_one = std::sqrt(one2 / count);
    std::printf(
        "surface over %zu wet points against a grid twice as fine (rms height %.3f m): runs %.3f m, one grid %.3f m\n",
        wet, rms, rms_layered, rms_one);
    EXPECT_GT(wet, 5000u);
    EXPECT_LE(rms_layered, 1.1 * rms_one);
}

}  // namespace
}  // namespace tidewater
