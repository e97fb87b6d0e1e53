// Threads as an embedding uses them: queries on several threads (each itself parallel)
// while a bake runs on another and is swapped in, and the level editor's background
// re-bake of an edit whose result shares tiles with the model being queried. The
// ThreadSanitizer build runs these (ctest -L threads); the other builds check the answers.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "../../examples/level_editor/bake_worker.hpp"
#include "../island_heightmap.hpp"
#include "../small_island.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

using test::kSmallIsland;

std::vector<glm::dvec2> coast_points() {
    std::vector<glm::dvec2> points;
    for (int k = 0; k < 400; ++k) {
        const double angle = 0.0157 * k, r = 200.0 + 200.0 * std::fmod(k * 0.618, 1.0);
        points.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    return points;
}

std::vector<double> heights_of(const Scene& scene, const std::vector<glm::dvec2>& points, unsigned threads) {
    std::vector<WorldPoint> out(points.size());
    QueryOptions options;
    options.threads = threads;
    const Status st = query_world(scene, 2.0, points, out, options);
    EXPECT_TRUE(st.ok()) << st.error().message;
    std::vector<double> h(points.size());
    for (std::size_t k = 0; k < out.size(); ++k) h[k] = out[k].surface.height;
    return h;
}

Scene with_a_wider_island(const Scene& scene) {
    Scene edit = scene;
    IslandTerrain wider = std::get<IslandTerrain>(edit.terrain.shape());
    wider.radius = 340.0;  // was 300: the coast moves out
    edit.terrain = Terrain(wider);
    return edit;
}

// Four threads, each querying on two, read whichever scene is current while a bake on
// two more threads makes an edit and swaps it in: every answer is bit for bit the one
// of the scene it read, before or after.
TEST(Threads, QueriesOnManyThreadsWhileABakeIsMadeAndSwappedIn) {
    auto parsed = parse_scene(kSmallIsland, "small.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    SceneBakeOptions two_threads;
    two_threads.threads = 2;
    auto first = bake_scene(*parsed, two_threads);
    ASSERT_TRUE(first.ok()) << first.error().message;
    const auto points = coast_points();
    const std::vector<double> before = heights_of(**first, points, 1);

    std::atomic<std::shared_ptr<const Scene>> current{*first};
    std::atomic<bool> swapped{false};
    std::atomic<int> rounds{0}, wrong{0};
    auto reader = [&] {
        for (int round = 0; round < 2 || !swapped; ++round) {
            const std::shared_ptr<const Scene> scene = current.load();
            const std::vector<double> h = heights_of(*scene, points, 2);
            if (scene == *first && h != before) ++wrong;
            ++rounds;
        }
    };
    std::vector<std::jthread> readers;
    for (int t = 0; t < 4; ++t) readers.emplace_back(reader);
    auto rebaked = bake_scene(with_a_wider_island(*parsed), two_threads);
    ASSERT_TRUE(rebaked.ok()) << rebaked.error().message;
    current = *rebaked;
    swapped = true;
    readers.clear();  // joins
    EXPECT_EQ(wrong.load(), 0) << "a query of the first scene changed while the edit was baked";
    EXPECT_GE(rounds.load(), 8);
    const std::vector<double> after = heights_of(**rebaked, points, 1);
    EXPECT_NE(after, before) << "the edit changed the coast";
    EXPECT_EQ(heights_of(**rebaked, points, 2), after);
}

// The editor's loop: each frame polls the background bake (its progress under its lock)
// and queries the scene it draws, while the re-bake of a brush stroke shares the tiles
// it leaves with that scene: a stroke on dry land, then one on the seabed. The result
// swapped in answers as a bake made from scratch (the seabed's re-march within its
// tolerance).
TEST(Threads, TheEditorsBackgroundReBakeSharesTilesWithTheSceneItQueries) {
    auto first = bake_scene(test::island_scene(test::island_pixels()));
    ASSERT_TRUE(first.ok()) << first.error().message;
    std::shared_ptr<const Scene> drawn = *first;
    const auto points = coast_points();
    const Scene strokes[] = {test::island_scene(test::island_pixels({100.0, 100.0}, 3.0)),
                             test::island_scene(test::island_pixels({350.0, 350.0}, 2.0))};
    for (const Scene& edited : strokes) {
        const std::vector<double> before = heights_of(*drawn, points, 1);
        editor::BackgroundBake bake;
        bake.start(edited, drawn);
        int frames = 0;
        std::optional<Result<std::shared_ptr<const Scene>>> done;
        while (!(done = bake.ready())) {
            {
                const std::lock_guard<std::mutex> g(bake.lock);
                EXPECT_LE(bake.fraction.load(), 1.0) << bake.stage;
            }
            EXPECT_EQ(heights_of(*drawn, points, 2), before) << "frame " << frames;
            ++frames;
        }
        ASSERT_TRUE(done->ok()) << done->error().message;
        drawn = **done;
    }
    auto scratch = bake_scene(strokes[1]);
    ASSERT_TRUE(scratch.ok()) << scratch.error().message;
    const std::vector<double> edited = heights_of(*drawn, points, 2), whole = heights_of(**scratch, points, 1);
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(edited[k], whole[k], 2e-3) << k;
}

}  // namespace
}  // namespace tidewater
