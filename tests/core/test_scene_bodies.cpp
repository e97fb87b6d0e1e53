// Lakes and rivers in scene files: what loads, what is refused (with the file and JSON
// path), and a lake's extent as baked.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/detail/water_bodies_bake.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

/// A bowl around the origin: 30 m at its rim, 10 m at the bottom, under an ocean far below.
std::string scene_with(const std::string& bodies,
                       const std::string& ocean = R"("ocean": "ocean_rolling", "water_level": -50.0,)") {
    return R"({ "version": 1, "name": "bodies", )" + ocean + R"(
      "terrain": { "island": { "seed": 3, "radius": 800, "height": 60, "seabed": -80 } }, )" +
           bodies + "}";
}

std::string refusal(const std::string& json) {
    auto scene = parse_scene(json, "bodies.json");
    return scene ? std::string("(loaded)") : scene.error().message;
}

TEST(SceneBodies, LakesAndRiversLoadWithTheirDefaults) {
    auto scene = parse_scene(scene_with(R"("lakes": [ { "name": "crater", "level": 42.0, "at": [10, 20] } ],
      "rivers": [ { "name": "mill", "path": [[0, 0], [100, 0], [200, 50]], "width": [8, 10, 12], "discharge": 3.0 } ])"),
                             "bodies.json");
    ASSERT_TRUE(scene) << scene.error().message;
    ASSERT_EQ(scene->lakes.size(), 1u);
    EXPECT_EQ(scene->lakes[0].name, "crater");
    EXPECT_DOUBLE_EQ(scene->lakes[0].body.level(), 42.0);
    EXPECT_EQ(scene->lakes[0].body.profile().name, "lake_rippled");
    ASSERT_EQ(scene->rivers.size(), 1u);
    const SceneRiver& r = scene->rivers[0];
    EXPECT_EQ(r.width, (std::vector<double>{8, 10, 12}));
    EXPECT_DOUBLE_EQ(r.manning, 0.035);
    EXPECT_TRUE(r.carve);
    EXPECT_EQ(r.body.profile().name, "river_flowing");
    EXPECT_TRUE(scene->has_ocean);
}

TEST(SceneBodies, AnInlandSceneHasNoOcean) {
    auto scene = parse_scene(scene_with(R"("lakes": [ { "name": "crater", "level": 42.0, "at": [10, 20] } ])", ""),
                             "inland.json");
    ASSERT_TRUE(scene) << scene.error().message;
    EXPECT_FALSE(scene->has_ocean);
    EXPECT_NE(refusal(scene_with(R"("lakes": [])", "")).find("a scene needs water"), std::string::npos);
    EXPECT_NE(refusal(scene_with(R"("lakes": [ { "name": "a", "level": 4, "at": [0, 0] } ])", R"("water_level": 1.0,)"))
                  .find("/water_level: is the ocean's level"),
              std::string::npos);
}

TEST(SceneBodies, BadBodiesAreRefusedWithTheirPath) {
    const std::string river =
        R"("rivers": [ { "name": "mill", "path": [[0, 0], [100, 0], [200, 50]], "width": 10, "discharge": 3.0 )";
    const std::pair<std::string, std::string> cases[] = {
        {R"("rivers": [ { "name": "m", "path": [[0, 0]], "width": 5, "discharge": 1 } ])",
         "bodies.json: /rivers/0/path: 1 points given"},
        {R"("rivers": [ { "name": "m", "path": [[0, 0], [100, 0], [100, 100], [50, -50]], "width": 5, "discharge": 1 } ])",
         "/rivers/0/path: crosses itself"},
        {R"("rivers": [ { "name": "m", "path": [[0, 0], [100, 0]], "width": [5, 6, 7], "discharge": 1 } ])",
         "/rivers/0/width: 3 widths for 2 path points"},
        {R"("rivers": [ { "name": "m", "path": [[0, 0], [100, 0]], "width": -5, "discharge": 1 } ])",
         "/rivers/0/width: -5 is out of range"},
        {R"("rivers": [ { "name": "m", "path": [[0, 0], [100, 0]], "width": 5, "discharge": 0 } ])",
         "/rivers/0/discharge: 0 is out of range"},
        {river + R"(, "colour": "blue" } ])", "/rivers/0/colour: unknown key"},
        {river + R"(, "manning": 2 } ])", "/rivers/0/manning: 2 is out of range"},
        {R"("lakes": [ { "name": "mill", "level": 4, "at": [0, 0] } ], )" + river + "} ]",
         "/rivers/0/name: \"mill\" names another body"},
        {R"("lakes": [ { "name": "ocean", "level": 4, "at": [0, 0] } ])", "/lakes/0/name: \"ocean\" names the ocean"},
        {R"("lakes": [ { "name": "a", "at": [0, 0] } ])", "/lakes/0/level: required number is missing"},
        {R"("lakes": [ { "name": "a", "level": 4, "at": [0, 0], "preset": "no_such" } ])",
         "preset \"no_such\" is not bundled"},
        {R"("lakes": { "name": "a" })", "/lakes: expected an array"},
    };
    for (const auto& [bodies, expected] : cases) {
        const std::string message = refusal(scene_with(bodies));
        EXPECT_NE(message.find(expected), std::string::npos) << "for " << bodies << "\ngot: " << message;
    }
}

TEST(SceneBodies, ALakeFillsItsBasinAndRefusesToSpill) {
    // The default island's hills: find a basin by baking a lake at a level just above a
    // low inland point, then check the extent against the terrain.
    auto scene = parse_scene(R"({ "version": 1, "name": "lake", "water_level": 0.0, "ocean": "ocean_rolling",
      "shore": { "enabled": false },
      "terrain": { "plane": { "height": 0.0, "slope": [0.0, 0.0] } },
      "lakes": [ { "name": "flat", "level": 5.0, "at": [0, 0] } ] })",
                             "lake.json");
    ASSERT_TRUE(scene) << scene.error().message;
    auto baked = bake_scene(*scene);
    ASSERT_FALSE(baked);
    EXPECT_NE(baked.error().message.find("/lakes/0: spills over the domain edge"), std::string::npos)
        << baked.error().message;

    auto high = parse_scene(R"({ "version": 1, "name": "lake", "water_level": 0.0, "ocean": "ocean_rolling",
      "shore": { "enabled": false }, "terrain": { "plane": { "height": 0.0, "slope": [0.0, 0.0] } },
      "lakes": [ { "name": "high", "level": -1.0, "at": [0, 0] } ] })",
                            "lake.json");
    ASSERT_TRUE(high);
    auto refused = bake_scene(*high);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("/lakes/0/at: the terrain there is 0.00 m, not under the lake's level -1 m"),
              std::string::npos)
        << refused.error().message;
}

TEST(SceneBodies, ABakeErrorNamesTheSceneFileEvenWithoutAName) {
    // A scene with no "name", read from a file: what the bake finds wrong names the file.
    const fs::path dir = fs::temp_directory_path() / fmt::format("tidewater_unnamed_{}", ::getpid());
    fs::create_directories(dir);
    const fs::path file = dir / "unnamed.json";
    {
        std::ofstream out(file);
        out << R"({ "version": 1, "water_level": 0.0, "ocean": "ocean_rolling", "shore": { "enabled": false },
          "terrain": { "plane": { "height": 0.0, "slope": [0.0, 0.0] } },
          "lakes": [ { "name": "high", "level": -1.0, "at": [0, 0] } ] })";
    }
    auto scene = load_scene(file);
    fs::remove_all(dir);
    ASSERT_TRUE(scene) << scene.error().message;
    EXPECT_EQ(scene->source, file.string());
    auto refused = bake_scene(*scene);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().message.rfind(file.string() + ": /lakes/0/at: the terrain there is 0.00 m", 0), 0u)
        << refused.error().message;
    // A scene built in code has no file: its name, else "the scene".
    Scene built = *scene;
    built.source.clear();
    EXPECT_EQ(scene_label(built), "the scene");
    built.name = "pond";
    EXPECT_EQ(scene_label(built), "scene \"pond\"");
}

TEST(SceneBodies, BakingReportsProgressToTheEndAndReBakingDoesNotCutTwice) {
    auto scene = parse_scene(R"({ "version": 1, "name": "carve", "water_level": 0.0, "ocean": "ocean_rolling",
      "shore": { "enabled": false },
      "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } },
      "rivers": [ { "name": "straight", "path": [[-1500, 0], [2400, 0]], "width": 20, "discharge": 10.0 } ] })",
                             "carve.json");
    ASSERT_TRUE(scene) << scene.error().message;
    std::vector<double> fractions;
    SceneBakeOptions options;
    options.progress = [&](std::string_view stage, double f) {
        EXPECT_EQ(stage, "water bodies");
        fractions.push_back(f);
    };
    auto baked = bake_scene(*scene, options);
    ASSERT_TRUE(baked) << baked.error().message;
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    EXPECT_TRUE((*baked)->baked());
    EXPECT_FALSE(scene->baked()) << "the parsed scene has rivers and no bake";
    // Re-baking the baked scene (whose terrain carries the channel) cuts from the shape again.
    auto again = bake_scene(**baked);
    ASSERT_TRUE(again) << again.error().message;
    for (const glm::dvec2 p : {glm::dvec2(0.0, 0.0), glm::dvec2(500.0, 3.0), glm::dvec2(-800.0, -4.0)}) {
        EXPECT_LT((*baked)->terrain.height_at(p), scene->terrain.height_at(p) - 0.3) << "carved at " << p.x;
        EXPECT_NEAR((*again)->terrain.height_at(p), (*baked)->terrain.height_at(p), 1e-9) << "at " << p.x;
    }
}

TEST(SceneBodies, AVeryLongNarrowRiverIsRefusedNotBaked) {
    auto scene = parse_scene(
        scene_with(
            R"("rivers": [ { "name": "thread", "path": [[0, 0], [9000000, 0]], "width": 0.5, "discharge": 1 } ])"),
        "long.json");
    ASSERT_TRUE(scene) << scene.error().message;
    auto baked = bake_scene(*scene);
    ASSERT_FALSE(baked);
    EXPECT_NE(baked.error().message.find("/rivers/0/path: the river \"thread\" is 9000000 m long"), std::string::npos)
        << baked.error().message;
}

TEST(SceneBodies, ALakeOverTheSummitSpills) {
    auto scene = parse_scene(R"({ "version": 1, "name": "summit", "water_level": 0.0, "ocean": "ocean_rolling",
      "shore": { "enabled": false, "resolution": 256 },
      "terrain": { "island": { "seed": 7, "radius": 600, "height": 80, "seabed": -40 } } })",
                             "summit.json");
    ASSERT_TRUE(scene) << scene.error().message;
    const Terrain& t = scene->terrain;
    glm::dvec2 best{0.0};
    double best_h = -1e9;
    for (double x = -300; x <= 300; x += 20)
        for (double z = -300; z <= 300; z += 20)
            if (t.height_at({x, z}) > best_h) {
                best_h = t.height_at({x, z});
                best = {x, z};
            }
    SceneLake lake;
    lake.name = "puddle";
    lake.at = best;
    lake.body = *WaterBody::create(*load_preset("lake_rippled"), best_h + 0.5, "test");
    // Half a metre over the summit, the whole domain is one lake that spills: refused.
    Scene with_lake = *scene;
    with_lake.lakes.push_back(lake);
    auto refused = detail::bake_water_bodies(with_lake, {});
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("spills over the domain edge"), std::string::npos);
}

}  // namespace
}  // namespace tidewater
