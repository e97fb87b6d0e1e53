// A body's optics: Jerlov's water types, a preset's "optics", each body kind's default,
// and bad values refused with the file and field.
#include <gtest/gtest.h>

#include <string>

#include "tidewater/scene.hpp"
#include "tidewater/water_optics.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

std::string scene_with_ocean(const std::string& ocean_extra, const std::string& lake_preset = R"("lake_rippled")") {
    return R"({"version": 1, "water_level": 0,
      "terrain": {"island": {"seed": 3, "radius": 800, "height": 60, "seabed": -80}},
      "ocean": {"preset": "ocean_rolling")" +
           ocean_extra + R"(},
      "lakes": [{"name": "crater", "level": 42.0, "at": [10, 20], "preset": )" +
           lake_preset + "}]}";
}

std::string refusal(const std::string& optics) {
    auto scene = parse_scene(scene_with_ocean(R"(, "optics": )" + optics), "o.json");
    return scene ? std::string("(loaded)") : scene.error().message;
}

/// Jerlov's table as the physics has it: from the clearest ocean (I) to the most turbid
/// coast (9C) blue light is lost ever faster, so the water's colour turns from blue (the
/// clear open ocean's I to II) to green (the turbid ocean's III and the coastal types,
/// where what the land washes in absorbs blue and green passes furthest).
TEST(WaterOptics, JerlovTypesTurnFromBlueToGreenTowardTheCoast) {
    const auto names = jerlov_type_names();
    ASSERT_EQ(names.size(), 10u);
    double previous_blue = 0.0;
    for (const std::string& name : names) {
        const auto type = jerlov_type_named(name);
        ASSERT_TRUE(type.has_value()) << name;
        const WaterOptics o = jerlov_optics(*type);
        EXPECT_TRUE(validate(o, name).ok()) << name;
        EXPECT_GT(o.extinction.b, previous_blue) << name;
        previous_blue = o.extinction.b;
        EXPECT_GT(o.extinction.r, o.extinction.g) << name << ": red is always lost fastest";
        const bool green = name.back() == 'C' || name == "III";
        if (green) {
            EXPECT_GT(o.color.g, o.color.b) << name;
        } else {
            EXPECT_GT(o.color.b, o.color.g) << name;
        }
        EXPECT_NEAR(std::max({o.color.r, o.color.g, o.color.b}), kDeepWaterBrightness, 1e-12) << name;
    }
    EXPECT_FALSE(jerlov_type_named("IV").has_value());
}

TEST(WaterOptics, EachBodyKindHasItsDefaultAndAPresetItsOwn) {
    auto plain = parse_scene(scene_with_ocean(""), "o.json");
    ASSERT_TRUE(plain.ok()) << plain.error().message;
    EXPECT_EQ(optics_of(*plain, {BodyKind::ocean, -1}), jerlov_optics(kDefaultOceanWaterType));
    EXPECT_EQ(optics_of(*plain, {BodyKind::lake, 0}), jerlov_optics(kDefaultInlandWaterType));
    EXPECT_EQ(optics_of(*plain, {BodyKind::none, -1}), jerlov_optics(kDefaultOceanWaterType));

    auto typed = parse_scene(scene_with_ocean(R"(, "optics": {"water_type": "IB"})",
                                              R"({"preset": "lake_rippled", "optics": {"water_type": "7C"}})"),
                             "o.json");
    ASSERT_TRUE(typed.ok()) << typed.error().message;
    EXPECT_EQ(optics_of(*typed, {BodyKind::ocean, -1}), jerlov_optics(JerlovType::IB));
    EXPECT_EQ(optics_of(*typed, {BodyKind::lake, 0}), jerlov_optics(JerlovType::C7));

    // An extinction alone takes deep water's colour from it; a colour given is kept.
    auto given = parse_scene(scene_with_ocean(R"(, "optics": {"extinction": [0.5, 0.1, 0.2]})"), "o.json");
    ASSERT_TRUE(given.ok()) << given.error().message;
    const WaterOptics o = optics_of(*given, {BodyKind::ocean, -1});
    EXPECT_EQ(o.extinction, glm::dvec3(0.5, 0.1, 0.2));
    EXPECT_EQ(o.color, deep_water_color(o.extinction));
    EXPECT_GT(o.color.g, o.color.b);
    auto coloured =
        parse_scene(scene_with_ocean(R"(, "optics": {"water_type": "I", "color": [0.0, 0.05, 0.1]})"), "o.json");
    ASSERT_TRUE(coloured.ok()) << coloured.error().message;
    EXPECT_EQ(optics_of(*coloured, {BodyKind::ocean, -1}).color, glm::dvec3(0.0, 0.05, 0.1));
    EXPECT_EQ(optics_of(*coloured, {BodyKind::ocean, -1}).extinction, jerlov_optics(JerlovType::I).extinction);
}

TEST(WaterOptics, BadOpticsAreRefusedNamingTheField) {
    EXPECT_NE(refusal(R"({"water_type": "muddy"})").find("o.json: /ocean/optics/water_type: \"muddy\" is not a Jerlov"),
              std::string::npos)
        << refusal(R"({"water_type": "muddy"})");
    EXPECT_NE(refusal(R"({"extinction": [0.4, 0, 0.1]})").find("o.json: /ocean/optics/extinction/1: 0 is out of range"),
              std::string::npos)
        << refusal(R"({"extinction": [0.4, 0, 0.1]})");
    EXPECT_NE(refusal(R"({"extinction": [0.4, 0.1]})").find("/ocean/optics/extinction: expected [red, green, blue]"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"water_type": "I", "color": [0, 2, 0]})").find("/ocean/optics/color/1: 2 is out of range"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"water_type": "I", "extinction": [0.4, 0.1, 0.1]})").find("exactly one of"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"color": [0, 0.1, 0.1]})").find("exactly one of"), std::string::npos);
    EXPECT_NE(refusal(R"({"water_type": "I", "tint": 1})").find("/ocean/optics"), std::string::npos);
    EXPECT_NE(refusal(R"("I")").find("/ocean/optics"), std::string::npos);
}

}  // namespace
}  // namespace tidewater
