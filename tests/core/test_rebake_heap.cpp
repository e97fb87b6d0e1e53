// An editor's session without its window: rounds of re-bakes, each baked from the scene
// before it keeping its marches, as the level editor bakes its strokes and preset swaps.
// The heap in use after a round is what it was after the first: nothing a re-bake makes
// outlives the scene that holds it. (The editor's own soak, tests/editor, draws frames on
// lavapipe, whose threads hold tens of MiB at times of their choosing; here nothing else
// allocates, so the bound is tight.)
#include <gtest/gtest.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdio>
#include <memory>
#include <vector>

#include "../island_heightmap.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;  // the sanitizers keep freed blocks in quarantine
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

/// The bytes the heap has handed out and not had back (MiB).
double heap_in_use_mib() {
#ifdef __GLIBC__
    const struct mallinfo2 heap = mallinfo2();
    return static_cast<double>(heap.uordblks + heap.hblkhd) / 1048576.0;
#else
    return 0.0;
#endif
}

/// `scene` with the ocean's waves from bundled preset `name`.
Scene with_preset(Scene scene, const char* name) {
    auto profile = load_preset(name);
    EXPECT_TRUE(profile.ok()) << name;
    auto body = WaterBody::create(*profile, scene.water_level(), "ocean");
    EXPECT_TRUE(body.ok()) << name;
    scene.ocean = std::move(body).value();
    return scene;
}

TEST(ReBakeHeap, RoundsOfStrokesAndPresetSwapsHoldTheHeapInUse) {
#ifndef __GLIBC__
    GTEST_SKIP() << "the heap in use is read from glibc's mallinfo2";
#endif
    if (kSanitized) GTEST_SKIP() << "a sanitizer's allocator holds freed blocks back";
    // A round leaves the scene as it found it: a shoal raised on the seabed and lowered, the
    // preset swapped and swapped back (the shore baked in full), a mound raised across the
    // waterline and lowered.
    const std::vector<Scene> round = {
        test::island_scene(test::island_pixels({350.0, 350.0}, 2.0)),
        test::island_scene(test::island_pixels()),
        with_preset(test::island_scene(test::island_pixels()), "lake_rippled"),
        test::island_scene(test::island_pixels()),
        test::island_scene(test::island_pixels({0.0, 400.0}, 3.0)),
        test::island_scene(test::island_pixels()),
    };
    SceneBakeOptions options;
    options.keep_marches = true;
    auto first = bake_scene(round.back(), options);
    ASSERT_TRUE(first.ok()) << first.error().message;
    std::shared_ptr<const Scene> scene = std::move(first).value();
    constexpr int kRounds = 4;
    std::vector<double> heap;
    int local = 0;
    for (int r = 0; r < kRounds; ++r) {
        for (const Scene& edited : round) {
            options.previous = scene;
            auto baked = bake_scene(edited, options);
            ASSERT_TRUE(baked.ok()) << baked.error().message;
            local += (*baked)->bake->reused.ocean_shore_water_edit ? 1 : 0;
            options.previous.reset();
            scene = std::move(baked).value();
        }
#ifdef __GLIBC__
        malloc_trim(0);
#endif
        heap.push_back(heap_in_use_mib());
    }
    std::printf("heap in use after each round of six re-bakes:");
    for (const double h : heap) std::printf(" %.2f", h);
    std::printf(" MiB (%d of %d re-bakes where the edit reaches)\n", local, 6 * kRounds);
    // The strokes took the local path, so what it keeps is what is held.
    EXPECT_GE(local, 2 * kRounds);
    // 18 re-bakes after the first round: a leak of 64 KiB each would show.
    EXPECT_LE(heap.back(), heap.front() + 1.0) << "the heap in use grew over the rounds";
}

}  // namespace
}  // namespace tidewater
