// A terrain edit under the water, re-baked where it reaches: each wave re-marched in a
// window round the edit and downstream of it, the fields baked again there; against a
// full bake of the edited terrain, and falling back to one where the water does not stay.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../island_heightmap.hpp"
#include "../shore_model_compare.hpp"
#include "shore/fast_marching.hpp"
#include "shore/shore_edit_region.hpp"
#include "shore/shore_marches.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

using test::island_pixels;
using test::island_scene;

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The largest difference between two layouts of the same tiles, per kind of row: a
/// wave run's residuals (rad), amplitude factors, wavevectors (rad/m), and the shared
/// layer's depth (m), breaking and steepness scale.
struct RowDifferences {
    double residual = 0.0, amplitude = 0.0, wavevector = 0.0, depth = 0.0, breaking = 0.0, steepness = 0.0,
           distance = 0.0;
    std::size_t amplitudes_over = 0;  ///< amplitude factors apart by more than kAmplitudeApart
};
constexpr float kAmplitudeApart = 3e-3f;
void widen(double& to, float a, float b) {
    to = std::max(to, static_cast<double>(std::abs(a - b)));
}
/// Over every slot, or (kept_only) only the slots `local` shares with `kept_from`.
RowDifferences differences(const ShoreWaves& a, const ShoreWaves& b, const ShoreWaves* local = nullptr,
                           const ShoreWaves* kept_from = nullptr) {
    RowDifferences d;
    auto slots = [&](const ShoreTiles& x, const ShoreTiles& y, const ShoreTiles* l, const ShoreTiles* k,
                     const auto& each) {
        EXPECT_EQ(x.pages, y.pages);
        EXPECT_EQ(x.slot_count(), y.slot_count());
        for (std::size_t s = gpu::kShoreFirstStoredSlot; s < std::min(x.slot_count(), y.slot_count()); ++s) {
            if (l && l->slots[s] != k->slots[s]) continue;
            for (std::size_t t = 0; t < ShoreTiles::kSlotTexels; ++t)
                each(x.slot(s) + t * x.stride, y.slot(s) + t * y.stride);
        }
    };
    slots(a.shared(), b.shared(), local ? &local->shared() : nullptr, kept_from ? &kept_from->shared() : nullptr,
          [&](const float* x, const float* y) {
              widen(d.depth, x[0], y[0]);
              widen(d.breaking, x[1], y[1]);
              widen(d.steepness, x[2], y[2]);
              widen(d.distance, x[3], y[3]);
          });
    for (std::size_t l = 0; l < a.layers().size(); ++l) {
        const std::size_t nw = a.layers()[l].count;
        slots(a.layers()[l].tiles, b.layers()[l].tiles, local ? &local->layers()[l].tiles : nullptr,
              kept_from ? &kept_from->layers()[l].tiles : nullptr, [&](const float* x, const float* y) {
                  for (std::size_t w = 0; w < nw; ++w) {
                      widen(d.residual, x[w], y[w]);
                      widen(d.amplitude, x[nw + w], y[nw + w]);
                      d.amplitudes_over += std::abs(x[nw + w] - y[nw + w]) > kAmplitudeApart ? 1 : 0;
                      widen(d.wavevector, x[2 * nw + w], y[2 * nw + w]);
                      widen(d.wavevector, x[3 * nw + w], y[3 * nw + w]);
                  }
              });
    }
    return d;
}
void print(const char* what, const RowDifferences& d) {
    std::printf(
        "%s: residual %.2e rad, amplitude %.2e, wavevector %.2e rad/m, depth %.2e m, breaking %.2e, "
        "steepness %.2e, shore distance %.2e m\n",
        what, d.residual, d.amplitude, d.wavevector, d.depth, d.breaking, d.steepness, d.distance);
}

std::size_t slots_shared(const ShoreWaves& a, const ShoreWaves& b, std::size_t* total) {
    std::size_t same = 0;
    *total = 0;
    auto count = [&](const ShoreTiles& x, const ShoreTiles& y) {
        for (std::size_t s = gpu::kShoreFirstStoredSlot; s < x.slot_count(); ++s) {
            same += x.slots[s] == y.slots[s];
            ++*total;
        }
    };
    count(a.shared(), b.shared());
    for (std::size_t l = 0; l < a.layers().size(); ++l) count(a.layers()[l].tiles, b.layers()[l].tiles);
    return same;
}

/// `edited` re-baked from a bake of `original` with the rays alone (no diffraction) and
/// baked in full: the three bakes, what the two models differ by (printed under `what`)
/// and how many of the first bake's slots the re-bake kept. Empty bakes on a failure.
struct RaysStroke {
    std::shared_ptr<const Scene> first, local, full;
    RowDifferences effect, error, kept;
    std::size_t same = 0, total = 0;
};
RaysStroke rays_stroke(Scene original, Scene edited, const char* what) {
    RaysStroke out;
    original.shore.diffraction = edited.shore.diffraction = false;
    auto first = bake_scene(original);
    EXPECT_TRUE(first.ok()) << first.error().message;
    if (!first.ok()) return out;
    SceneBakeOptions options;
    options.previous = *first;
    const auto t0 = std::chrono::steady_clock::now();
    auto local = bake_scene(edited, options);
    const double local_s = seconds_since(t0);
    EXPECT_TRUE(local.ok()) << local.error().message;
    const auto t1 = std::chrono::steady_clock::now();
    auto full = bake_scene(edited);
    const double full_s = seconds_since(t1);
    EXPECT_TRUE(full.ok()) << full.error().message;
    if (!local.ok() || !full.ok()) return out;
    out.first = *first;
    out.local = *local;
    out.full = *full;
    const ShoreWaves &old_model = *out.first->bake->ocean_shore, &local_model = *out.local->bake->ocean_shore,
                     &full_model = *out.full->bake->ocean_shore;
    out.effect = differences(old_model, full_model);
    out.error = differences(local_model, full_model);
    out.kept = differences(local_model, full_model, &local_model, &old_model);
    std::printf("%s:\n", what);
    print("  its effect (full bakes before and after)", out.effect);
    print("  re-baked where it reaches, against a full bake", out.error);
    print("  in the slots it kept", out.kept);
    out.same = slots_shared(local_model, old_model, &out.total);
    std::printf("  %zu of %zu stored slots kept; %.3f s re-baked where it reaches, %.3f s in full\n", out.same,
                out.total, local_s, full_s);
    return out;
}

/// The rays' re-bake within the re-march's tolerance (kOpenSeaPhaseTolerance, 1e-3 rad)
/// and what it does to the wavevector's differences and the amplitudes; the depths and
/// shore distances exact. In the slots it kept the full bake's phase moved by under the
/// tolerance too.
void expect_within_rays_tolerance(const RaysStroke& r) {
    EXPECT_LT(r.error.residual, kOpenSeaPhaseTolerance);
    EXPECT_LT(r.error.amplitude, 1e-3);
    EXPECT_LT(r.error.wavevector, 1e-4);
    EXPECT_LT(r.error.breaking, 1e-3);
    EXPECT_LT(r.error.steepness, 1e-3);
    EXPECT_EQ(r.error.depth, 0.0);
    EXPECT_EQ(r.error.distance, 0.0);
    EXPECT_LT(r.kept.residual, kOpenSeaPhaseTolerance);
    EXPECT_LT(r.kept.amplitude, 1e-3);
}

/// A shoal 2 m high, 40 m round, at `at` (by default 95 m off the shore in 4.75 m of
/// water), re-baked where it reaches on the test island with its distance field at
/// `distance_resolution` (0: the model's grid), against full bakes before and after. The
/// rays alone: a diffracted wave changes downstream of the stroke to the model's end.
void check_seabed_stroke(int distance_resolution, glm::dvec2 at = {350.0, 350.0}) {
    Scene scene = island_scene(island_pixels()), shoal = island_scene(island_pixels(at, 2.0));
    scene.shore.distance_resolution = shoal.shore.distance_resolution = distance_resolution;
    const RaysStroke r = rays_stroke(scene, shoal, "a 2 m shoal");
    ASSERT_NE(r.local, nullptr);
    EXPECT_TRUE(r.local->bake->reused.ocean_shore_water_edit);
    EXPECT_FALSE(r.local->bake->reused.ocean_shore_land_edit);
    // The shoal changes the waves by far more than the re-bake's error.
    const RowDifferences& effect = r.effect;
    const std::size_t same = r.same, total = r.total;
    EXPECT_GT(effect.residual, 0.05);
    EXPECT_GT(effect.amplitude, 0.02);
    EXPECT_GT(effect.depth, 1.5);
    expect_within_rays_tolerance(r);
    // Most of the model is the previous bake's memory; the shoal's slots are new.
    EXPECT_GT(same, total / 2);
    EXPECT_LT(same, total);
    const ShoreField &old_line = *r.first->bake->shoreline, &new_line = *r.local->bake->shoreline;
    EXPECT_EQ(&old_line.signed_distance.values(), &new_line.signed_distance.values());
    EXPECT_TRUE(new_line.depth == r.full->bake->shoreline->depth);
}

TEST(ShoreWaterEdit, AStrokeOnTheSeabedIsReBakedWhereItReaches) {
    check_seabed_stroke(0);
}

// The model's grid then holds the shoreline's normals resampled, which the edit reads
// where its rows need them.
TEST(ShoreWaterEdit, AStrokeOnTheSeabedUnderAFinerDistanceFieldIsReBakedWhereItReaches) {
    check_seabed_stroke(512);
}

TEST(ShoreWaterEdit, AStrokeOnTheSeabedUnderDiffractedWavesIsBakedInFullWithoutItsMarches) {
    auto first = bake_scene(island_scene(island_pixels()));
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_EQ((*first)->bake->ocean_marches, nullptr);  // not asked for
    SceneBakeOptions options;
    options.previous = *first;
    const Scene shoal = island_scene(island_pixels({350.0, 350.0}, 2.0));
    ASSERT_TRUE(shoal.shore.diffraction);
    auto edited = bake_scene(shoal, options);
    ASSERT_TRUE(edited.ok()) << edited.error().message;
    EXPECT_FALSE((*edited)->bake->reused.ocean_shore_water_edit);
    auto full = bake_scene(shoal);
    ASSERT_TRUE(full.ok()) << full.error().message;
    EXPECT_TRUE(test::same_tiles(*(*edited)->bake->ocean_shore, *(*full)->bake->ocean_shore));
}

/// A stroke re-baked from `previous` (baked keeping its marches) against a full bake of
/// `edited`: within the march's tolerance where it re-baked, the previous bake's elsewhere.
std::shared_ptr<const Scene> check_diffracted_stroke(const std::shared_ptr<const Scene>& previous, const Scene& edited,
                                                     const char* what) {
    SceneBakeOptions options;
    options.previous = previous;
    options.keep_marches = true;
    const auto t0 = std::chrono::steady_clock::now();
    auto local = bake_scene(edited, options);
    const double local_s = seconds_since(t0);
    EXPECT_TRUE(local.ok()) << local.error().message;
    if (!local.ok()) return nullptr;
    EXPECT_TRUE((*local)->bake->reused.ocean_shore_water_edit);
    EXPECT_NE((*local)->bake->ocean_marches, nullptr);
    const auto t1 = std::chrono::steady_clock::now();
    auto full = bake_scene(edited);
    const double full_s = seconds_since(t1);
    EXPECT_TRUE(full.ok()) << full.error().message;
    if (!full.ok()) return nullptr;
    const ShoreWaves &old_model = *previous->bake->ocean_shore, &local_model = *(*local)->bake->ocean_shore,
                     &full_model = *(*full)->bake->ocean_shore;
    const RowDifferences effect = differences(old_model, full_model);
    const RowDifferences error = differences(local_model, full_model);
    const RowDifferences kept = differences(local_model, full_model, &local_model, &old_model);
    std::printf("%s:\n", what);
    print("  its effect (full bakes before and after)", effect);
    print("  re-baked where it reaches, against a full bake", error);
    print("  in the slots it kept", kept);
    std::size_t total = 0;
    const std::size_t same = slots_shared(local_model, old_model, &total);
    std::printf("  %zu of %zu stored slots kept; %.3f s re-baked where it reaches, %.3f s in full\n", same, total,
                local_s, full_s);
    std::printf("  amplitude factors over %.0e apart: %zu against the full bake (%zu moved by the stroke)\n",
                static_cast<double>(kAmplitudeApart), error.amplitudes_over, effect.amplitudes_over);
    EXPECT_GT(effect.amplitude, 0.05);
    // The rays' part as without the march; the march's amplitude within its tolerance
    // (kMarchAmplitudeTolerance, 1e-3 of the open-sea amplitude) and the half precision
    // it is held in, but at a texel or two on the breaker line, where a change far under
    // the tolerance may move the onset of breaking (a full bake's as much); the foam from
    // the energy of both.
    EXPECT_LT(error.residual, kOpenSeaPhaseTolerance);
    EXPECT_LT(error.amplitude, 0.01);
    EXPECT_LT(error.amplitudes_over, effect.amplitudes_over / 1000 + 3);
    EXPECT_LT(error.wavevector, 1e-4);
    EXPECT_LT(error.breaking, 5e-3);
    EXPECT_LT(error.steepness, 1e-3);
    EXPECT_EQ(error.depth, 0.0);
    EXPECT_EQ(error.distance, 0.0);
    EXPECT_LT(kept.amplitude, 0.01);
    EXPECT_LT(kept.amplitudes_over, effect.amplitudes_over / 1000 + 3);
    EXPECT_GT(same, total / 4);
    EXPECT_LT(same, total);
    return *local;
}

TEST(ShoreWaterEdit, AStrokeOnTheSeabedUnderDiffractedWavesIsReBakedWhereItReaches) {
    SceneBakeOptions keep;
    keep.keep_marches = true;
    auto first = bake_scene(island_scene(island_pixels()), keep);
    ASSERT_TRUE(first.ok()) << first.error().message;
    ASSERT_NE((*first)->bake->ocean_marches, nullptr);
    const auto one = check_diffracted_stroke(*first, island_scene(island_pixels({350.0, 350.0}, 2.0)),
                                             "a 2 m shoal in 4.75 m of water, the march taken up again");
    ASSERT_NE(one, nullptr);
    // A second stroke takes up the marches the first left.
    const Scene two = island_scene(test::island_pixels_with({{{350.0, 350.0}, 2.0}, {{-300.0, 380.0}, 1.5}}));
    check_diffracted_stroke(one, two, "a second shoal elsewhere, from the first's re-bake");
}

// Deep water moves under a stroke: a 2 m shoal in 11.1 m of water, upwave of the island,
// where the shortest wave (T = 3.6 s) is deep from 10.3 m down. Its sources there are
// marched again from the depths after, as the rest of its phase.
TEST(ShoreWaterEdit, AStrokeThatMovesAWavesDeepWaterIsReBakedWhereItReaches) {
    const glm::dvec2 at{-440.0, -440.0};
    const double before = 0.05 * glm::length(at) - 20.0, after = before - 2.0;
    const Scene shoal = island_scene(island_pixels(at, 2.0));
    const auto waves = shoal.ocean.waves().waves();
    EXPECT_TRUE(std::any_of(waves.begin(), waves.end(), [&](const Wave& w) {
        return detail::marched_deep_water(w.omega, before) != detail::marched_deep_water(w.omega, after);
    })) << "the stroke no longer crosses a wave's deep-water depth";
    SceneBakeOptions keep;
    keep.keep_marches = true;
    auto first = bake_scene(island_scene(island_pixels()), keep);
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_NE(check_diffracted_stroke(*first, shoal, "a 2 m shoal where the shortest wave's deep water ends"), nullptr);
    check_seabed_stroke(0, at);  // the rays alone
}

TEST(ShoreWaterEdit, WhereTheMarchCannotBeBlendedAloneTheRowsAreBakedAgain) {
    // Without the cap's ratios kept, a march's part cannot be made again alone where only
    // it moved: the rows are baked again there too, to the same tolerance, and fewer of
    // the previous bake's slots are kept than where the march's part is made alone.
    SceneBakeOptions keep;
    keep.keep_marches = true;
    auto first = bake_scene(island_scene(island_pixels()), keep);
    ASSERT_TRUE(first.ok()) << first.error().message;
    auto marches = std::make_shared<detail::ShoreMarches>(*(*first)->bake->ocean_marches);
    ASSERT_GT(marches->ratios.slots(), 0u);
    marches->ratios = detail::CapRatios();
    auto bake = std::make_shared<SceneBake>(*(*first)->bake);
    bake->ocean_marches = std::move(marches);
    auto without = std::make_shared<Scene>(**first);
    without->bake = std::move(bake);
    const Scene shoal = island_scene(island_pixels({350.0, 350.0}, 2.0));
    const auto rows = check_diffracted_stroke(without, shoal, "a 2 m shoal, every row where a march moved baked again");
    const auto alone = check_diffracted_stroke(*first, shoal, "the same, the march's part alone where only it moved");
    ASSERT_NE(rows, nullptr);
    ASSERT_NE(alone, nullptr);
    const ShoreWaves& old_model = *(*first)->bake->ocean_shore;
    std::size_t total = 0;
    EXPECT_LT(slots_shared(*rows->bake->ocean_shore, old_model, &total),
              slots_shared(*alone->bake->ocean_shore, old_model, &total));
}

// An edit's distance field updated where it reaches (update_shore) against the field baked
// whole over the edited terrain: the same shoreline, distances, directions and depths, to
// the bit, for strokes across the waterline, a new islet, and one inland that moves no
// shoreline.
TEST(ShoreWaterEdit, TheDistanceFieldUpdatedWhereAnEditReachesIsTheFullBakes) {
    BakeOptions options;
    options.resolution = 256;
    const Scene island = island_scene(island_pixels());
    auto before = bake_shore(island.terrain, 0.0, options);
    ASSERT_TRUE(before.ok()) << before.error().message;
    const struct {
        glm::dvec2 at;
        double bump;
        const char* what;
    } edits[] = {{{400.0, 0.0}, -2.0, "a dip across the waterline"},
                 {{-380.0, 0.0}, 3.0, "a mound across the waterline"},
                 {{440.0, 0.0}, 8.0, "an islet in 3 m of water"},
                 {{0.0, 100.0}, 3.0, "a mound inland"}};
    for (const auto& e : edits) {
        const Scene edited = island_scene(island_pixels(e.at, e.bump));
        const detail::HeightmapChange change = detail::heightmap_change(island.terrain, edited.terrain);
        ASSERT_TRUE(change && *change) << e.what;
        const auto t0 = std::chrono::steady_clock::now();
        auto updated = update_shore(*before, edited.terrain, 0.0, **change, 2);
        const double update_s = seconds_since(t0);
        ASSERT_TRUE(updated.ok()) << updated.error().message;
        ASSERT_TRUE(updated->has_value()) << e.what;
        const auto t1 = std::chrono::steady_clock::now();
        auto full = bake_shore(edited.terrain, 0.0, options);
        const double full_s = seconds_since(t1);
        ASSERT_TRUE(full.ok()) << full.error().message;
        const ShoreField& u = **updated;
        std::printf("%s: %zu segments, %zu polygons; updated in %.4f s, baked whole in %.4f s\n", e.what,
                    u.segment_count, u.polygons, update_s, full_s);
        EXPECT_TRUE(u.signed_distance == full->signed_distance) << e.what;
        EXPECT_TRUE(u.gradient == full->gradient) << e.what;
        EXPECT_TRUE(u.depth == full->depth) << e.what;
        EXPECT_EQ(u.segment_count, full->segment_count) << e.what;
        EXPECT_EQ(u.polygons, full->polygons) << e.what;
        EXPECT_EQ(u.holes, full->holes) << e.what;
        ASSERT_EQ(u.shorelines.size(), full->shorelines.size()) << e.what;
        for (std::size_t k = 0; k < u.shorelines.size(); ++k)
            EXPECT_EQ(u.shorelines[k].points, full->shorelines[k].points) << e.what << ", line " << k;
    }
    EXPECT_EQ(before->polygons, 1u);
}

/// A stroke across the waterline re-baked from a bake of the island with the rays alone:
/// the distance field baked again in full (it is a full bake's), the waves where the
/// stroke and the distances it moved reach.
void check_waterline_stroke(const Scene& edited, const char* what) {
    const RaysStroke r = rays_stroke(island_scene(island_pixels()), edited, what);
    ASSERT_NE(r.local, nullptr);
    EXPECT_TRUE(r.local->bake->reused.ocean_shore_water_edit);
    const std::size_t same = r.same, total = r.total;
    const ShoreField &old_line = *r.first->bake->shoreline, &new_line = *r.local->bake->shoreline,
                     &full_line = *r.full->bake->shoreline;
    EXPECT_FALSE(old_line.signed_distance == full_line.signed_distance) << "the shoreline moves";
    EXPECT_TRUE(new_line.signed_distance == full_line.signed_distance);
    EXPECT_TRUE(new_line.gradient == full_line.gradient);
    EXPECT_TRUE(new_line.depth == full_line.depth);
    EXPECT_GT(r.effect.depth, 1.0);
    expect_within_rays_tolerance(r);
    EXPECT_GT(same, total / 4);
    EXPECT_LT(same, total);
}

TEST(ShoreWaterEdit, AStrokeAcrossTheWaterlineIsReBakedWhereItReaches) {
    // A dip of 2 m on the beach (r = 400 m, the waterline): the sea comes in over it.
    check_waterline_stroke(island_scene(island_pixels({400.0, 0.0}, -2.0)), "a dip across the waterline");
    // A mound 3 m high on the far beach, 20 m inside the waterline: the land goes out.
    check_waterline_stroke(island_scene(island_pixels({-380.0, 0.0}, 3.0)), "a mound across the waterline");
}

TEST(ShoreWaterEdit, AStrokeAcrossTheWaterlineUnderDiffractedWavesIsReBakedWhereItReaches) {
    SceneBakeOptions keep;
    keep.keep_marches = true;
    auto first = bake_scene(island_scene(island_pixels()), keep);
    ASSERT_TRUE(first.ok()) << first.error().message;
    const auto one = check_diffracted_stroke(*first, island_scene(island_pixels({400.0, 0.0}, -2.0)),
                                             "a dip across the waterline, the march taken up again");
    ASSERT_NE(one, nullptr);
    const ShoreField &old_line = *(*first)->bake->shoreline, &new_line = *one->bake->shoreline;
    EXPECT_FALSE(old_line.signed_distance == new_line.signed_distance);
}

// A river from the island's slope out into the sea (the shoreline at r = 400 m), its
// discharge raised by a fifth: the channel is re-carved to its mouth, under the sea, and
// the waterline moves along its banks. The dry tiles it crosses inland stay dry; the
// shore is re-baked where the new channel and the distances it moved reach.
TEST(ShoreWaterEdit, ARiverReCarvedToItsMouthIsReBakedWhereItReaches) {
    auto with_river = [](double discharge) {
        Scene scene = island_scene(island_pixels());
        SceneRiver river;
        river.name = "brook";
        river.path = {{-20.0, 150.0}, {0.0, 300.0}, {10.0, 440.0}};
        river.width = {8.0, 10.0, 12.0};
        river.discharge = discharge;
        scene.rivers.push_back(river);
        return scene;
    };
    SceneBakeOptions keep;
    keep.keep_marches = true;
    auto first = bake_scene(with_river(5.0), keep);
    ASSERT_TRUE(first.ok()) << first.error().message;
    const ShoreTiles& shared = (*first)->bake->ocean_shore->shared();
    ASSERT_NE(std::find(shared.pages.begin(), shared.pages.end(), gpu::kShoreDrySlot), shared.pages.end());
    const auto edited = check_diffracted_stroke(*first, with_river(6.0), "a river's discharge raised by a fifth");
    ASSERT_NE(edited, nullptr);
    EXPECT_FALSE((*first)->bake->shoreline->signed_distance == edited->bake->shoreline->signed_distance)
        << "the waterline moves along the banks";
}

// Where the distance field is finer than the model's grid, the model's distances are the
// field's resampled: a stroke that moves the shoreline is baked in full.
TEST(ShoreWaterEdit, AStrokeThatMovesTheShorelineUnderAFinerDistanceFieldIsBakedInFull) {
    Scene scene = island_scene(island_pixels());
    scene.shore.distance_resolution = 512;
    scene.shore.diffraction = false;
    auto first = bake_scene(scene);
    ASSERT_TRUE(first.ok()) << first.error().message;
    SceneBakeOptions options;
    options.previous = *first;
    Scene beach = island_scene(island_pixels({400.0, 0.0}, -2.0));
    beach.shore.distance_resolution = 512;
    beach.shore.diffraction = false;
    auto edited = bake_scene(beach, options);
    ASSERT_TRUE(edited.ok()) << edited.error().message;
    EXPECT_FALSE((*edited)->bake->reused.ocean_shore_water_edit);
    auto full = bake_scene(beach);
    ASSERT_TRUE(full.ok()) << full.error().message;
    EXPECT_TRUE(test::same_tiles(*(*edited)->bake->ocean_shore, *(*full)->bake->ocean_shore));
}

}  // namespace
}  // namespace tidewater
