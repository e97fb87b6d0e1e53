// Scene and preset JSON: the documented forms load; bad input gets an error
// naming the file, the JSON path and the allowed range.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

std::string scene_with_ocean(const std::string& ocean, const std::string& terrain = R"({"flat": {"height": -20}})") {
    return R"({"version": 1, "name": "t", "water_level": 0.5, "terrain": )" + terrain + R"(, "ocean": )" + ocean + "}";
}

const char* kInlineWaves =
    R"({"waves": [{"direction": 10, "wavelength": 30, "amplitude": 0.5, "steepness": 0.5},
                  {"direction": 80, "wavelength": 12, "amplitude": 0.2, "steepness": 0.6, "phase": 1.0}]})";

TEST(SceneJson, LoadsInlineWavesAndFlatTerrain) {
    auto scene = parse_scene(scene_with_ocean(kInlineWaves), "s.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->name, "t");
    EXPECT_DOUBLE_EQ(scene->water_level(), 0.5);
    EXPECT_DOUBLE_EQ(scene->ocean.level(), 0.5);
    EXPECT_DOUBLE_EQ(scene->terrain.height_at({100.0, 3.0}), -20.0);
    ASSERT_EQ(scene->ocean.waves().size(), 2u);
    EXPECT_DOUBLE_EQ(scene->ocean.waves().waves()[1].phase, 1.0);
}

TEST(SceneJson, LoadsPlaneTerrainSpectrumAndPresetOverrides) {
    auto scene = parse_scene(
        scene_with_ocean(R"({"spectrum": {"type": "pierson_moskowitz", "wind_speed": 8, "wave_count": 12, "seed": 4}})",
                         R"({"plane": {"height": -5, "slope": [0.1, -0.02]}})"),
        "s.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_DOUBLE_EQ(scene->terrain.height_at({10.0, 50.0}), -5.0 + 1.0 - 1.0);
    EXPECT_EQ(scene->ocean.waves().size(), 12u);
    ASSERT_TRUE(scene->ocean.profile().spectrum.has_value());

    auto preset = parse_scene(scene_with_ocean(R"("lake_rippled")"), "s.json");
    ASSERT_TRUE(preset.ok()) << preset.error().message;
    EXPECT_EQ(preset->ocean.profile().name, "lake_rippled");

    auto overridden = parse_scene(
        scene_with_ocean(R"({"preset": "lake_rippled", "time_offset": 3.5, "ripples": {"amplitude": 0}})"), "s.json");
    ASSERT_TRUE(overridden.ok()) << overridden.error().message;
    EXPECT_DOUBLE_EQ(overridden->ocean.time_offset(), 3.5);
    EXPECT_FALSE(overridden->ocean.ripples().enabled());
    EXPECT_EQ(overridden->ocean.waves().size(), preset->ocean.waves().size());
}

TEST(SceneJson, LoadsPresetFileRelativeToScene) {
    const auto dir = std::filesystem::temp_directory_path() / "tidewater_scene_json_test";
    std::filesystem::create_directories(dir / "presets");
    std::ofstream(dir / "presets" / "mine.json")
        << R"({"version": 1, "name": "mine", "waves": [{"direction": 0, "wavelength": 7, "amplitude": 0.1, "steepness": 0.3}]})";
    std::ofstream(dir / "scene.json") << scene_with_ocean(R"("presets/mine.json")");
    auto scene = load_scene(dir / "scene.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->ocean.profile().name, "mine");
    std::filesystem::remove_all(dir);
}

TEST(SceneJson, FoldClampIsAWarning) {
    const std::string ocean =
        R"({"fold_policy": "clamp", "waves": [{"direction": 0, "wavelength": 6.2832, "amplitude": 0.8, "steepness": 1},
                                             {"direction": 90, "wavelength": 6.2832, "amplitude": 0.8, "steepness": 1}]})";
    auto scene = parse_scene(scene_with_ocean(ocean), "s.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_EQ(scene->warnings.size(), 1u);
    EXPECT_NE(scene->warnings[0].find("s.json: /ocean/waves"), std::string::npos) << scene->warnings[0];
    EXPECT_NEAR(scene->ocean.waves().fold_measure(), 1.0, 1e-9);
    auto rejected =
        parse_scene(scene_with_ocean(std::string(ocean).replace(ocean.find("clamp"), 5, "reject")), "s.json");
    ASSERT_FALSE(rejected.ok());
    EXPECT_EQ(rejected.error().code, ErrorCode::fold_violation);
}

struct BadScene {
    const char* name;
    std::string text;
    std::vector<std::string> expected;  // substrings of the message
};

TEST(SceneJson, BadInputNamesFilePathAndRange) {
    const std::string good_wave = R"({"direction": 0, "wavelength": 10, "amplitude": 0.1, "steepness": 0.5})";
    auto wave_list = [&](const std::string& bad) { return R"({"waves": [)" + good_wave + "," + bad + "]}"; };
    std::string many = R"({"waves": [)";
    for (int i = 0; i < 65; ++i) many += (i ? "," : "") + good_wave;
    many += "]}";
    const std::vector<BadScene> cases = {
        {"malformed", R"({"version": 1, "water_level": 0,, })", {"bad.json", "malformed JSON", "line 1"}},
        {"truncated", R"({"version": 1, "terrain": {"flat": )", {"bad.json", "malformed JSON"}},
        {"nan literal",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": NaN, "amplitude": 0.1, "steepness": 0.5})")),
         {"bad.json", "malformed JSON"}},
        {"overflow",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": 1e999, "amplitude": 0.1, "steepness": 0.5})")),
         {"bad.json"}},
        {"wrong type",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": "long", "amplitude": 0.1, "steepness": 0.5})")),
         {"bad.json: /ocean/waves/1/wavelength", "expected a number, found string"}},
        {"unknown key",
         scene_with_ocean(
             wave_list(R"({"direction": 0, "wavelength": 5, "amplitude": 0.1, "steepness": 0.5, "colour": 1})")),
         {"bad.json: /ocean/waves/1/colour", "unknown key",
          "allowed here: direction, wavelength, amplitude, steepness, phase"}},
        {"unknown top key",
         R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -1}}, "ocean": "pool_calm", "sky": 1})",
         {"bad.json: /sky", "unknown key"}},
        {"wavelength zero",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": 0, "amplitude": 0.1, "steepness": 0.5})")),
         {"bad.json: /ocean/waves/1/wavelength", "0 < wavelength"}},
        {"negative amplitude",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": 3, "amplitude": -0.1, "steepness": 0.5})")),
         {"bad.json: /ocean/waves/1/amplitude", "-0.1", "0 <= amplitude"}},
        {"steepness above 1",
         scene_with_ocean(wave_list(R"({"direction": 0, "wavelength": 3, "amplitude": 0.01, "steepness": 1.5})")),
         {"bad.json: /ocean/waves/1/steepness", "0 <= steepness <= 1"}},
        {"missing field",
         scene_with_ocean(wave_list(R"({"direction": 0, "amplitude": 0.01, "steepness": 0.5})")),
         {"bad.json: /ocean/waves/1/wavelength", "missing"}},
        {"too many waves", scene_with_ocean(many), {"bad.json: /ocean/waves", "65 waves", "at most 64"}},
        {"missing version",
         R"({"water_level": 0, "terrain": {"flat": {"height": -1}}, "ocean": "pool_calm"})",
         {"bad.json: /version", "missing"}},
        {"future version",
         R"({"version": 2, "water_level": 0, "terrain": {"flat": {"height": -1}}, "ocean": "pool_calm"})",
         {"unsupported version 2"}},
        {"no terrain", R"({"version": 1, "water_level": 0, "ocean": "pool_calm"})", {"bad.json: /terrain", "missing"}},
        {"two terrains",
         scene_with_ocean(R"("pool_calm")", R"({"flat": {"height": -1}, "plane": {"height": 0, "slope": [0, 0]}})"),
         {"/terrain", "exactly one"}},
        {"bad slope",
         scene_with_ocean(R"("pool_calm")", R"({"plane": {"height": 0, "slope": [0.1]}})"),
         {"/terrain/plane/slope", "two numbers"}},
        {"unknown preset", scene_with_ocean(R"("ocean_stormy")"), {"ocean_stormy", "not bundled", "ocean_rolling"}},
        {"missing preset file", scene_with_ocean(R"("no/such/preset.json")"), {"no/such/preset.json", "cannot open"}},
        {"two sources",
         scene_with_ocean(R"({"preset": "pool_calm", "waves": []})"),
         {"bad.json: /ocean", "exactly one"}},
        {"bad spectrum",
         scene_with_ocean(R"({"spectrum": {"type": "tma", "wind_speed": 5}})"),
         {"bad.json: /ocean/spectrum/type", "jonswap"}},
        {"spectrum range",
         scene_with_ocean(R"({"spectrum": {"type": "jonswap", "wind_speed": 5, "fetch": 10}})"),
         {"bad.json: /ocean/spectrum/fetch", "1000 <= fetch"}},
        {"ripple octaves",
         scene_with_ocean(R"({"waves": [], "ripples": {"octaves": 12}})"),
         {"bad.json: /ocean/ripples/octaves", "1 to 8"}},
        {"fold policy",
         scene_with_ocean(R"({"waves": [], "fold_policy": "ignore"})"),
         {"bad.json: /ocean/fold_policy", "clamp"}},
        {"water level",
         R"({"version": 1, "water_level": 1e7, "terrain": {"flat": {"height": -1}}, "ocean": "pool_calm"})",
         {"bad.json: /water_level", "out of range"}},
        {"knolls not a list",
         scene_with_ocean(R"("pool_calm")", R"({"island": {"knolls": {"at": [0, 0]}}})"),
         {"bad.json: /terrain/island/knolls", "expected an array"}},
        {"knoll radius",
         scene_with_ocean(R"("pool_calm")", R"({"island": {"knolls": [{"at": [0, 0], "radius": 0, "height": 2}]}})"),
         {"bad.json: /terrain/island/knolls/0/radius", "out of range"}},
        {"knoll height",
         scene_with_ocean(R"("pool_calm")", R"({"island": {"knolls": [{"at": [0, 0], "radius": 5, "height": -2}]}})"),
         {"bad.json: /terrain/island/knolls/0/height"}},
        {"knoll without a place",
         scene_with_ocean(R"("pool_calm")", R"({"island": {"knolls": [{"radius": 5, "height": 2}]}})"),
         {"bad.json: /terrain/island/knolls/0/at", "missing"}},
        {"knoll unknown key",
         scene_with_ocean(R"("pool_calm")",
                          R"({"island": {"knolls": [{"at": [0, 0], "radius": 5, "height": 2, "rock": 1}]}})"),
         {"bad.json: /terrain/island/knolls/0/rock", "unknown key"}},
        {"not an object", "[1, 2]", {"bad.json", "expected an object"}},
        {"duplicate key",
         R"({"version": 1, "water_level": 0, "water_level": 1, "terrain": {"flat": {"height": -1}}, "ocean": "pool_calm"})",
         {"bad.json", "duplicate key \"water_level\""}},
        {"nested duplicate",
         scene_with_ocean(
             wave_list(R"({"direction": 0, "wavelength": 5, "amplitude": 0.1, "amplitude": 0.2, "steepness": 0.5})")),
         {"bad.json", "duplicate key \"amplitude\""}},
    };
    for (const BadScene& c : cases) {
        auto scene = parse_scene(c.text, "bad.json");
        ASSERT_FALSE(scene.ok()) << c.name;
        for (const std::string& part : c.expected) {
            EXPECT_NE(scene.error().message.find(part), std::string::npos)
                << c.name << ": \"" << part << "\" not in: " << scene.error().message;
        }
    }
}

TEST(SceneJson, MissingSceneFileNamesThePath) {
    auto scene = load_scene("/no/such/dir/scene.json");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().code, ErrorCode::io_error);
    EXPECT_NE(scene.error().message.find("/no/such/dir/scene.json"), std::string::npos);
}

TEST(SceneJson, SizesADocumentCanAskForAreBounded) {
    // Nesting: a scene's deepest is 6; 40 arrays within each other are refused by name.
    const std::string deep = R"({"version": 1, "name": )" + std::string(40, '[') + std::string(40, ']') + "}";
    auto nested = parse_scene(deep, "deep.json");
    ASSERT_FALSE(nested.ok());
    EXPECT_EQ(nested.error().message, "deep.json: nested deeper than 32 objects and arrays");
    // A name of 100 000 bytes.
    auto long_name = parse_scene(
        R"({"version": 1, "name": ")" + std::string(100000, 'x') + R"(", "ocean": "pool_calm"})", "long.json");
    ASSERT_FALSE(long_name.ok());
    EXPECT_EQ(long_name.error().message, "long.json: a string of 100000 bytes (at most 65536)");
    // A file of 80 MiB is refused before it is read (a sparse file: nothing is written).
    const std::filesystem::path big = std::filesystem::temp_directory_path() / "tidewater_big_scene.json";
    std::ofstream(big).put(' ');
    std::filesystem::resize_file(big, std::uintmax_t{80} << 20);
    auto huge = load_scene(big);
    std::filesystem::remove(big);
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().message, big.string() + ": 83886080 bytes, at most 67108864 read: not a file this reads");
}

TEST(SceneJson, DefaultSceneIsBundled) {
    auto scene = default_scene();
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->name, "default");
    EXPECT_FALSE(scene->ocean.waves().empty());
}

// Seed 000's four profiles, clearly different: the ocean's Hs is over 10x the lake's,
// the lake's over 3x the pool's; the river's waves all run within 15 degrees of
// downstream while the lake's spread over more than 45 degrees.
TEST(Presets, BundledProfilesLoadAndDiffer) {
    const auto names = bundled_preset_names();
    ASSERT_EQ(names, (std::vector<std::string>{"lake_rippled", "ocean_rolling", "pool_calm", "river_flowing"}));
    std::map<std::string, WaterBody> bodies;
    for (const auto& n : names) {
        auto p = load_preset(n);
        ASSERT_TRUE(p.ok()) << p.error().message;
        EXPECT_EQ(p->name, n);
        EXPECT_FALSE(p->description.empty());
        auto body = WaterBody::create(*p, 0.0, n);
        ASSERT_TRUE(body.ok());
        bodies.emplace(n, std::move(body).value());
    }
    const double hs_ocean = bodies["ocean_rolling"].waves().significant_wave_height();
    const double hs_lake = bodies["lake_rippled"].waves().significant_wave_height();
    const double hs_pool = bodies["pool_calm"].waves().significant_wave_height();
    EXPECT_GT(hs_ocean, 10.0 * hs_lake);
    EXPECT_GT(hs_lake, 3.0 * hs_pool);
    double river_max = 0.0, lake_min = 1e9, lake_max = -1e9;
    for (const auto& w : bodies["river_flowing"].profile().waves)
        river_max = std::max(river_max, std::abs(w.direction_deg));
    for (const auto& w : bodies["lake_rippled"].profile().waves) {
        lake_min = std::min(lake_min, w.direction_deg);
        lake_max = std::max(lake_max, w.direction_deg);
    }
    EXPECT_LE(river_max, 15.0);
    EXPECT_GT(lake_max - lake_min, 45.0);
    for (const auto& [name, body] : bodies) EXPECT_TRUE(body.ripples().enabled()) << name;
}

TEST(Presets, PresetFileErrorsNameTheFile) {
    auto p = parse_preset(
        R"({"version": 1, "name": "x", "waves": [{"direction": 0, "wavelength": 5, "amplitude": 9, "steepness": 1}]})",
        "steep.json");
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("steep.json"), std::string::npos) << p.error().message;
    EXPECT_EQ(p.error().code, ErrorCode::fold_violation);
}

// The shore model's grid goes to 8192 texels a side (2 m over an 8 km world), no further.
TEST(SceneJson, ShoreResolutionGoesTo8192) {
    const std::string base = R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -20}},
        "ocean": "ocean_rolling", "shore": {"resolution": )";
    auto fine = parse_scene(base + "8192}}", "fine.json");
    ASSERT_TRUE(fine.ok()) << fine.error().message;
    EXPECT_EQ(fine->shore.resolution, 8192);
    auto over = parse_scene(base + "8193}}", "over.json");
    ASSERT_FALSE(over.ok());
    EXPECT_NE(over.error().message.find("over.json"), std::string::npos);
    EXPECT_NE(over.error().message.find("/shore/resolution"), std::string::npos) << over.error().message;
}

}  // namespace
}  // namespace tidewater
