// A terrain edit on dry land, re-baked where it is: the previous bake's shore model and
// distance field with only the ground's height under the edit baked again, bit for bit
// what a full bake of the edited terrain gives; an edit that reaches the water is baked
// in full.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "../island_heightmap.hpp"
#include "../shore_model_compare.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

using test::island_pixels;
using test::island_scene;

void expect_same_shore(const SceneBake& a, const SceneBake& b) {
    ASSERT_TRUE(a.ocean_shore && b.ocean_shore && a.shoreline && b.shoreline);
    EXPECT_TRUE(test::same_tiles(*a.ocean_shore, *b.ocean_shore)) << "the model's layers and slots, bit for bit";
    EXPECT_TRUE(a.shoreline->depth == b.shoreline->depth);
    EXPECT_TRUE(a.shoreline->signed_distance == b.shoreline->signed_distance);
    EXPECT_TRUE(a.shoreline->gradient == b.shoreline->gradient);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

TEST(ShoreLandEdit, AnEditOfDryLandIsTheFullBakeBitForBit) {
    const Scene scene = island_scene(island_pixels());
    auto first = bake_scene(scene);
    ASSERT_TRUE(first.ok()) << first.error().message;
    SceneBakeOptions options;
    options.previous = *first;

    // A mound 250 m from the centre: 150 m inland, in the stored band, dry before and after.
    const Scene mound = island_scene(island_pixels({250.0, 0.0}, 3.0));
    const auto t0 = std::chrono::steady_clock::now();
    auto local = bake_scene(mound, options);
    const double local_s = seconds_since(t0);
    ASSERT_TRUE(local.ok()) << local.error().message;
    EXPECT_TRUE((*local)->bake->reused.ocean_shore_land_edit);
    EXPECT_FALSE((*local)->bake->reused.ocean_shore);
    const auto t1 = std::chrono::steady_clock::now();
    auto full = bake_scene(mound);
    const double full_s = seconds_since(t1);
    ASSERT_TRUE(full.ok()) << full.error().message;
    expect_same_shore(*(*local)->bake, *(*full)->bake);
    // The edit shows: some stored depth differs from the first bake's.
    const std::vector<float> before = (*first)->bake->ocean_shore->shared().floats();
    const std::vector<float> after = (*local)->bake->ocean_shore->shared().floats();
    ASSERT_EQ(before.size(), after.size());
    std::size_t changed = 0;
    for (std::size_t k = 0; k < before.size(); ++k) changed += before[k] != after[k];
    std::printf("dry-land edit: %zu stored values changed; %.3f s re-baked where it is, %.3f s in full\n", changed,
                local_s, full_s);
    EXPECT_GT(changed, 50u);
    // Only the slots under the mound are new; the rest are the first bake's memory, and so
    // are the runs' tiles and the distance field's distances.
    const ShoreTiles &old_tiles = (*first)->bake->ocean_shore->shared(),
                     &new_tiles = (*local)->bake->ocean_shore->shared();
    ASSERT_EQ(old_tiles.slot_count(), new_tiles.slot_count());
    std::size_t copied = 0;
    for (std::size_t s = 0; s < old_tiles.slot_count(); ++s) copied += old_tiles.slot(s) != new_tiles.slot(s);
    std::printf("dry-land edit: %zu of %zu shared slots copied\n", copied, old_tiles.slot_count());
    EXPECT_GE(copied, 1u);
    EXPECT_LE(copied, 4u);
    EXPECT_EQ((*first)->bake->ocean_shore->layers().data(), (*local)->bake->ocean_shore->layers().data());
    EXPECT_EQ(&(*first)->bake->shoreline->signed_distance.values(),
              &(*local)->bake->shoreline->signed_distance.values());
    EXPECT_NE(&(*first)->bake->shoreline->depth.values(), &(*local)->bake->shoreline->depth.values());

    // The same pixels in another image object: nothing is baked again.
    auto same = bake_scene(island_scene(island_pixels()), options);
    ASSERT_TRUE(same.ok());
    EXPECT_TRUE((*same)->bake->reused.ocean_shore_land_edit);
    EXPECT_EQ((*same)->bake->ocean_shore, (*first)->bake->ocean_shore);
}

TEST(ShoreLandEdit, AnEditThatReachesTheWaterIsBakedInFull) {
    const Scene scene = island_scene(island_pixels());
    auto first = bake_scene(scene);
    ASSERT_TRUE(first.ok()) << first.error().message;
    SceneBakeOptions options;
    options.previous = *first;
    // A mound on the beach (r = 400 m): the shoreline moves.
    const Scene beach = island_scene(island_pixels({400.0, 0.0}, 3.0));
    auto edited = bake_scene(beach, options);
    ASSERT_TRUE(edited.ok()) << edited.error().message;
    EXPECT_FALSE((*edited)->bake->reused.ocean_shore_land_edit);
    EXPECT_FALSE((*edited)->bake->reused.ocean_shore);
    auto full = bake_scene(beach);
    ASSERT_TRUE(full.ok());
    expect_same_shore(*(*edited)->bake, *(*full)->bake);
    // A mound whose foot reaches the water (r = 365 m, 40 m wide: to 405 m): baked in full.
    auto touching = bake_scene(island_scene(island_pixels({365.0, 0.0}, 3.0)), options);
    ASSERT_TRUE(touching.ok());
    EXPECT_FALSE((*touching)->bake->reused.ocean_shore_land_edit) << "the mound's foot reaches the water";
    // One that stops 30 m short of it (r = 330 m): re-baked where it is, still the full bake.
    const Scene near = island_scene(island_pixels({330.0, 0.0}, 3.0));
    auto near_edit = bake_scene(near, options);
    ASSERT_TRUE(near_edit.ok());
    EXPECT_TRUE((*near_edit)->bake->reused.ocean_shore_land_edit);
    auto near_full = bake_scene(near);
    ASSERT_TRUE(near_full.ok());
    expect_same_shore(*(*near_edit)->bake, *(*near_full)->bake);
}

// A river re-carved inland (the rill's middle bend moved 6 m): the shore is re-baked
// only under the channels that changed, bit for bit a full bake of the edited scene.
TEST(ShoreLandEdit, ARiverReCarvedInlandIsReBakedWhereItsChannelChanged) {
    auto scene = default_scene();
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto first = bake_scene(*scene);
    ASSERT_TRUE(first.ok()) << first.error().message;
    Scene bend = *scene;
    SceneRiver* rill = nullptr;
    for (SceneRiver& r : bend.rivers)
        if (r.name == "rill") rill = &r;
    ASSERT_NE(rill, nullptr);
    rill->path[1] += glm::dvec2(6.0, 0.0);
    SceneBakeOptions options;
    options.previous = *first;
    const auto t0 = std::chrono::steady_clock::now();
    auto local = bake_scene(bend, options);
    const double local_s = seconds_since(t0);
    ASSERT_TRUE(local.ok()) << local.error().message;
    const auto t1 = std::chrono::steady_clock::now();
    auto full = bake_scene(bend);
    const double full_s = seconds_since(t1);
    ASSERT_TRUE(full.ok()) << full.error().message;
    std::printf("river edit: %.3f s with the previous bake, %.3f s in full\n", local_s, full_s);
    EXPECT_FALSE((*local)->bake->terrain.cuts() == (*first)->bake->terrain.cuts()) << "the channel is re-carved";
    EXPECT_TRUE((*local)->bake->reused.ocean_shore_land_edit);
    expect_same_shore(*(*local)->bake, *(*full)->bake);
    // The shore model sees the new channel: its depths differ from the first bake's there.
    EXPECT_NE((*local)->bake->ocean_shore->shared().floats(), (*first)->bake->ocean_shore->shared().floats());
    std::printf("river edit: %zu of %zu rivers reused\n", (*local)->bake->reused.rivers, bend.rivers.size());
}

}  // namespace
}  // namespace tidewater
