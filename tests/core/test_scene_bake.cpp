// Parsing is not baking: parse_scene only reads; bake_scene makes the shore model
// once, with progress and cancellation, into an immutable scene that threads share;
// a saved bake loads without the work.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "../shore_model_compare.hpp"
#include "../small_island.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

using test::kSmallIsland;

std::vector<glm::dvec2> beach_points() {
    std::vector<glm::dvec2> points;
    for (int k = 0; k < 300; ++k) {
        const double angle = 0.021 * k, r = 240.0 + 120.0 * std::fmod(k * 0.618, 1.0);
        points.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    return points;
}

TEST(SceneBake, ParsingDoesNotBake) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->ocean.shore(), nullptr);
    EXPECT_EQ(scene->bake, nullptr);
    EXPECT_FALSE(scene->baked());
    // A scene whose shore is off has nothing to bake.
    auto off =
        parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -9}}, "ocean": "pool_calm",
                               "shore": {"enabled": false}})",
                    "off.json");
    ASSERT_TRUE(off.ok());
    EXPECT_TRUE(off->baked());
}

TEST(SceneBake, BakesTheShoreWithProgressAndLeavesItsInputAlone) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    std::vector<std::pair<std::string, double>> calls;
    SceneBakeOptions options;
    options.progress = [&](std::string_view stage, double f) { calls.emplace_back(std::string(stage), f); };
    auto baked = bake_scene(*scene, options);
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    const Scene& s = **baked;
    ASSERT_TRUE(s.baked());
    ASSERT_NE(s.ocean.shore(), nullptr);
    EXPECT_EQ(s.ocean.shore(), s.bake->ocean_shore);
    ASSERT_NE(s.bake->shoreline, nullptr);
    EXPECT_FALSE(s.bake->loaded);
    EXPECT_GT(s.bake->seconds, 0.0);
    EXPECT_EQ(scene->ocean.shore(), nullptr);  // the parsed scene is unchanged
    EXPECT_EQ(scene->bake, nullptr);

    ASSERT_GE(calls.size(), 3u);
    EXPECT_EQ(calls.front().first, "shoreline");
    EXPECT_EQ(calls.back().first, "shore waves");
    EXPECT_DOUBLE_EQ(calls.back().second, 1.0);
    for (std::size_t k = 1; k < calls.size(); ++k) EXPECT_GE(calls[k].second, calls[k - 1].second) << k;
}

// The shoreline is baked once, at the distance field's resolution, and the model samples
// it: its shore distance is that field's, signed by the model texel's own depth.
TEST(SceneBake, OneShorelineBakeServesTheModel) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    SceneBakeOptions options;
    options.distance_resolution = 256;
    auto baked = bake_scene(*scene, options);
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    const ShoreField& line = *(*baked)->bake->shoreline;
    const ShoreWaves& model = *(*baked)->bake->ocean_shore;
    ASSERT_EQ(line.resolution, 256);
    ASSERT_EQ(model.resolution(), 64);
    const int n = model.resolution();
    int stored = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 p = model.texel_center(i, j);
            const double depth = model.texel_values(i, j).depth();
            if (std::abs(depth) >= 0.5 * gpu::kShoreFarValue) continue;  // a tile not stored
            ++stored;
            EXPECT_NEAR(depth, 0.0 - scene->terrain.height_at(p), 1e-4 * (1.0 + std::abs(depth)));
            const double expected = std::abs(line.distance_at(p)) * (depth > 0.0 ? 1.0 : -1.0);
            ASSERT_NEAR(model.texel_values(i, j).shore_distance(), expected, 1e-3 * (1.0 + std::abs(expected)))
                << i << "," << j;
        }
    EXPECT_GT(stored, n * n / 2);
    // Against a model that baked its own 64-texel shoreline: within a model texel.
    auto own = bake_scene(*scene);
    ASSERT_TRUE(own.ok());
    const ShoreWaves& coarse = *(*own)->bake->ocean_shore;
    double worst = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double a = coarse.texel_values(i, j).shore_distance(), b = model.texel_values(i, j).shore_distance();
            if (std::max(std::abs(a), std::abs(b)) < 0.5 * gpu::kShoreFarValue)
                worst = std::max(worst, std::abs(a - b));
        }
    std::printf("shore distance from a 256 shoreline vs its own 64 bake: worst %.2f m (texel %.2f m)\n", worst,
                model.texel());
    EXPECT_LT(worst, model.texel());
}

TEST(SceneBake, CancelStopsTheBakeAndKeepsNothing) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    // Cancelled before it starts.
    std::stop_source before;
    before.request_stop();
    SceneBakeOptions options;
    options.cancel = before.get_token();
    auto none = bake_scene(*scene, options);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::cancelled);

    // Cancelled from another thread part way through the waves.
    std::stop_source stop;
    std::atomic<bool> asked{false};
    std::atomic<int> calls_after{0};
    SceneBakeOptions during;
    during.cancel = stop.get_token();
    during.progress = [&](std::string_view stage, double) {
        if (asked) ++calls_after;
        if (stage == "shore waves" && !asked.exchange(true)) std::thread([&] { stop.request_stop(); }).join();
    };
    auto stopped = bake_scene(*scene, during);
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().code, ErrorCode::cancelled);
    EXPECT_NE(stopped.error().message.find("cancelled"), std::string::npos);
    EXPECT_TRUE(asked);
    // The waves still to do were skipped: far fewer reports than waves.
    EXPECT_LT(calls_after.load(), static_cast<int>(scene->ocean.waves().size()) / 2);
}

TEST(SceneBake, SavedBakeLoadsWithoutTheWork) {
    const fs::path dir = fs::temp_directory_path() / ("tidewater_scene_bake_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    auto baked = bake_scene(*scene);
    ASSERT_TRUE(baked.ok());
    ASSERT_TRUE(save_scene_bake(dir / "bake", **baked).ok());
    EXPECT_FALSE(save_scene_bake(dir / "other", *scene).ok());  // parsed, not baked

    Scene from_folder = *scene;
    from_folder.shore.bake_folder = dir / "bake";
    std::vector<std::string> stages;
    SceneBakeOptions options;
    options.progress = [&](std::string_view stage, double) { stages.emplace_back(stage); };
    auto loaded = bake_scene(from_folder, options);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE((*loaded)->bake->loaded);
    EXPECT_EQ((*loaded)->bake->shoreline, nullptr);
    for (const auto& s : stages) EXPECT_EQ(s, "loading");
    // The same water within the 16-bit encoding.
    const auto points = beach_points();
    std::vector<double> a(points.size()), b(points.size());
    ASSERT_TRUE(query_heights((*baked)->ocean, 3.0, points, a).ok());
    ASSERT_TRUE(query_heights((*loaded)->ocean, 3.0, points, b).ok());
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(a[k], b[k], 5e-3) << k;

    // A folder that is not there names the scene's shore entry and the file.
    from_folder.shore.bake_folder = dir / "missing";
    auto missing = bake_scene(from_folder);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("/shore"), std::string::npos) << missing.error().message;
    EXPECT_NE(missing.error().message.find("missing"), std::string::npos) << missing.error().message;
    fs::remove_all(dir);
}

// A scene that names its saved bake gives no shore settings; the scene loaded from it
// takes the bake's, so that an edit of it (its bake folder cleared, as an editor does) is
// baked as the bake was. A bake saved before they were recorded leaves the texels per
// wavelength and diffraction as the scene has them.
TEST(SceneBake, ASceneLoadedFromItsSavedBakeTakesTheBakesShoreSettings) {
    const fs::path dir = fs::temp_directory_path() / ("tidewater_scene_settings_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    scene->shore.resolution = 96;
    scene->shore.distance_resolution = 192;
    scene->shore.breaking_index = 0.7;
    scene->shore.texels_per_wavelength = 0.0;
    scene->shore.diffraction = false;
    auto baked = bake_scene(*scene);
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    ASSERT_TRUE(save_scene_bake(dir, **baked).ok());

    auto named = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(named.ok());
    named->shore = SceneShore{};
    named->shore.bake_folder = dir;
    auto loaded = bake_scene(*named);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const SceneShore& got = (*loaded)->shore;
    EXPECT_EQ(got.resolution, 96);
    EXPECT_EQ(got.distance_resolution, 192);
    EXPECT_EQ(got.breaking_index, 0.7);
    EXPECT_EQ(got.texels_per_wavelength, 0.0);
    EXPECT_FALSE(got.diffraction);
    EXPECT_EQ(got.bake_folder, dir);
    EXPECT_TRUE((*loaded)->baked());

    // Edited (here not at all) and baked again: the same model as the first bake.
    Scene edited = **loaded;
    edited.shore.bake_folder.clear();
    auto again = bake_scene(edited);
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_TRUE(test::same_tiles(*(*again)->bake->ocean_shore, *(*baked)->bake->ocean_shore));

    // An older bake: no texels per wavelength or diffraction recorded.
    {
        std::ifstream in(dir / "shore.json");
        nlohmann::json doc = nlohmann::json::parse(in);
        doc["model"].erase("texels_per_wavelength");
        doc["model"].erase("diffraction");
        std::ofstream(dir / "shore.json") << doc.dump();
    }
    auto older = bake_scene(*named);
    ASSERT_TRUE(older.ok()) << older.error().message;
    EXPECT_EQ((*older)->shore.resolution, 96);
    EXPECT_EQ((*older)->shore.texels_per_wavelength, kDefaultShoreTexelsPerWavelength);
    EXPECT_TRUE((*older)->shore.diffraction);
    // A recorded setting out of range is refused by name.
    {
        std::ifstream in(dir / "shore.json");
        nlohmann::json doc = nlohmann::json::parse(in);
        doc["model"]["texels_per_wavelength"] = 2.0;
        std::ofstream(dir / "shore.json") << doc.dump();
    }
    auto bad = bake_scene(*named);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("texels_per_wavelength"), std::string::npos) << bad.error().message;
    fs::remove_all(dir);
}

TEST(SceneBake, EditorRebakesAfterATerrainEdit) {
    // Deep water everywhere: the bake finds nothing to change.
    auto scene =
        parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -200}}, "ocean": "ocean_rolling",
                                 "shore": {"resolution": 64}})",
                    "edit");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto deep = bake_scene(*scene);
    ASSERT_TRUE(deep.ok());
    EXPECT_FALSE((*deep)->ocean.shore());
    ASSERT_TRUE((*deep)->bake->ocean_shore);
    EXPECT_TRUE((*deep)->bake->ocean_shore->trivial());
    // The editor raises an island and re-bakes: the waves now stop on its land.
    IslandTerrain island;
    island.radius = 300.0;
    island.height = 40.0;
    island.seabed = -30.0;
    scene->terrain = Terrain(island);
    // A copy of the old bake with the new terrain is not baked: it would draw the old shore.
    Scene stale = **deep;
    EXPECT_TRUE(stale.baked());
    stale.terrain = scene->terrain;
    EXPECT_FALSE(stale.baked());
    auto edited = bake_scene(*scene);
    ASSERT_TRUE(edited.ok());
    Scene swapped_ocean = **edited;
    swapped_ocean.ocean = scene->ocean;  // the parsed ocean: no shore model
    EXPECT_FALSE(swapped_ocean.baked());
    ASSERT_TRUE((*edited)->ocean.shore());
    std::vector<glm::dvec2> centre{{0.0, 0.0}};
    std::vector<SurfacePoint> out(1);
    ASSERT_TRUE(query_surface((*edited)->ocean, 3.0, centre, out).ok());
    EXPECT_EQ(out[0].height, 0.0);  // dry land: nothing moves
    // A shore turned off bakes to no model; a bad grid is an error naming the shore.
    scene->shore.enabled = false;
    auto off = bake_scene(*scene);
    ASSERT_TRUE(off.ok());
    EXPECT_FALSE((*off)->ocean.shore());
    scene->shore.enabled = true;
    scene->shore.resolution = 3;
    auto bad = bake_scene(*scene);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("/shore"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("resolution"), std::string::npos) << bad.error().message;
}

// Two threads query a shared baked scene while a third bakes an edit of it: the
// queries give the same bits as before, and the new bake is whole.
TEST(SceneBake, TwoThreadsQueryWhileAThirdBakes) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    auto first = bake_scene(*scene);
    ASSERT_TRUE(first.ok());
    const std::shared_ptr<const Scene> shared = *first;
    const auto points = beach_points();
    std::vector<double> expected(points.size());
    ASSERT_TRUE(query_heights(shared->ocean, 2.0, points, expected).ok());

    std::atomic<bool> baking{true};
    std::atomic<int> mismatches{0}, rounds{0};
    auto query_loop = [&] {
        std::vector<double> h(points.size());
        // At least a few rounds, and on until the bake is done.
        for (int round = 0; round < 3 || baking; ++round) {
            if (!query_heights(shared->ocean, 2.0, points, h).ok()) ++mismatches;
            for (std::size_t k = 0; k < points.size(); ++k)
                if (h[k] != expected[k]) ++mismatches;
            ++rounds;
        }
    };
    Scene edit = *scene;
    IslandTerrain higher = std::get<IslandTerrain>(edit.terrain.shape());
    higher.height = 60.0;
    edit.terrain = Terrain(higher);
    Result<std::shared_ptr<const Scene>> rebaked = Error{};
    std::thread a(query_loop), b(query_loop);
    std::thread baker([&] {
        rebaked = bake_scene(edit);
        baking = false;
    });
    baker.join();
    a.join();
    b.join();
    EXPECT_EQ(mismatches.load(), 0);
    EXPECT_GE(rounds.load(), 6);
    ASSERT_TRUE(rebaked.ok()) << rebaked.error().message;
    ASSERT_TRUE((*rebaked)->ocean.shore());
    // The edit's bake is the one a quiet machine makes.
    auto quiet = bake_scene(edit);
    ASSERT_TRUE(quiet.ok());
    std::vector<double> x(points.size()), y(points.size());
    ASSERT_TRUE(query_heights((*rebaked)->ocean, 2.0, points, x).ok());
    ASSERT_TRUE(query_heights((*quiet)->ocean, 2.0, points, y).ok());
    for (std::size_t k = 0; k < points.size(); ++k) ASSERT_EQ(x[k], y[k]) << k;
}

TEST(SceneBake, RefusesABadDistanceResolution) {
    auto scene = parse_scene(kSmallIsland, "s.json");
    ASSERT_TRUE(scene.ok());
    // Out of range, and coarser than the 64-texel model that would sample it.
    for (const auto& [resolution, words] :
         {std::pair{4, "distance_resolution"}, std::pair{32, "coarser than the shore model"}}) {
        SceneBakeOptions options;
        options.distance_resolution = resolution;
        auto r = bake_scene(*scene, options);
        ASSERT_FALSE(r.ok()) << resolution;
        EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
    }
}

/// Every baked field of two rivers, bit for bit.
void expect_same_river(const detail::RiverBake& a, const detail::RiverBake& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.texel, b.texel) << a.name;
    EXPECT_EQ(a.surface, b.surface) << a.name;
    EXPECT_EQ(a.psi, b.psi) << a.name;
    EXPECT_EQ(a.flow_x, b.flow_x) << a.name;
    EXPECT_EQ(a.flow_z, b.flow_z) << a.name;
    EXPECT_EQ(a.query_texels, b.query_texels) << a.name;
    ASSERT_EQ(a.cut != nullptr, b.cut != nullptr) << a.name;
    if (a.cut) {
        EXPECT_EQ(a.cut->depth, b.cut->depth) << a.name;
    }
}

// An editor's re-bake from its last good scene: what the edit leaves alone is reused, and
// the result is the full bake's.
TEST(SceneBake, ReBakingAfterAnEditReusesWhatItLeavesAloneAndMatchesAFullBake) {
    auto parsed = default_scene();
    ASSERT_TRUE(parsed.ok());
    parsed->shore.resolution = 96;
    auto first = bake_scene(*parsed);
    ASSERT_TRUE(first.ok()) << first.error().message;

    // A new preset for the tarn: its shore model is re-baked, the rivers and the ocean's are not.
    Scene ripples = *parsed;
    auto calm = load_preset("pool_calm");
    ASSERT_TRUE(calm.ok());
    auto lake = WaterBody::create(*calm, ripples.lakes[0].body.level(), "tarn");
    ASSERT_TRUE(lake.ok());
    ripples.lakes[0].body = std::move(lake).value();
    SceneBakeOptions options;
    options.previous = *first;
    auto quick = bake_scene(ripples, options);
    ASSERT_TRUE(quick.ok()) << quick.error().message;
    EXPECT_EQ((*quick)->bake->reused.rivers, 2u);
    EXPECT_EQ((*quick)->bake->reused.lake_shores, 0u);
    EXPECT_TRUE((*quick)->bake->reused.ocean_shore);
    EXPECT_EQ((*quick)->bake->ocean_shore, (*first)->bake->ocean_shore);
    EXPECT_TRUE((*quick)->baked());

    // Another sea: the ocean's shore model is re-baked, the rivers and the tarn's are not.
    Scene sea = *parsed;
    auto swell = WaterBody::create(*calm, sea.water_level(), "ocean");
    ASSERT_TRUE(swell.ok());
    sea.ocean = std::move(swell).value();
    auto resea = bake_scene(sea, options);
    ASSERT_TRUE(resea.ok()) << resea.error().message;
    EXPECT_EQ((*resea)->bake->reused.rivers, 2u);
    EXPECT_EQ((*resea)->bake->reused.lake_shores, 1u);
    EXPECT_FALSE((*resea)->bake->reused.ocean_shore);
    EXPECT_TRUE((*resea)->baked());

    // A terrain edit away from the rivers (a hill raised in the sea): they are reused,
    // and equal what a full bake of the edited scene gives.
    Scene hill = *parsed;
    auto island = std::get<IslandTerrain>(hill.terrain.shape());
    island.knolls.push_back({{640.0, 330.0}, 120.0, 30.0});
    hill.terrain = Terrain(island);
    auto hilled = bake_scene(hill, options);
    ASSERT_TRUE(hilled.ok()) << hilled.error().message;
    EXPECT_EQ((*hilled)->bake->reused.rivers, 2u);
    EXPECT_FALSE((*hilled)->bake->reused.ocean_shore);
    auto hill_full = bake_scene(hill);
    ASSERT_TRUE(hill_full.ok());
    for (std::size_t r = 0; r < hill.rivers.size(); ++r)
        expect_same_river((*hilled)->bake->bodies->rivers[r], (*hill_full)->bake->bodies->rivers[r]);

    // The rill widened: it and the brook it joins are re-baked (the brook's inflow and the
    // rill's banks change); the brook reaches into the tarn's basin and the sea, so both
    // shore models are re-baked too. The result is the full bake's.
    Scene wider = *parsed;
    for (double& w : wider.rivers[1].width) w += 2.0;
    auto edited = bake_scene(wider, options);
    ASSERT_TRUE(edited.ok()) << edited.error().message;
    EXPECT_EQ((*edited)->bake->reused.rivers, 0u);
    EXPECT_FALSE((*edited)->bake->reused.ocean_shore);
    auto full = bake_scene(wider);
    ASSERT_TRUE(full.ok());
    for (std::size_t r = 0; r < wider.rivers.size(); ++r)
        expect_same_river((*edited)->bake->bodies->rivers[r], (*full)->bake->bodies->rivers[r]);
    EXPECT_TRUE(test::same_tiles(*(*edited)->bake->lake_shores[0], *(*full)->bake->lake_shores[0]));
    EXPECT_TRUE(test::same_tiles(*(*edited)->bake->ocean_shore, *(*full)->bake->ocean_shore));
}

}  // namespace
}  // namespace tidewater
