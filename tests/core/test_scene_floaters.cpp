// The scene's boats and floats riding its water (tidewater/scene_floaters.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tidewater/constants.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/scene_floaters.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

std::string pool(const std::string& extra) {
    return R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": {"waves": [{"direction": 0, "wavelength": 50, "amplitude": 0.001, "steepness": 0.1}]})" +
           extra + "}";
}

std::shared_ptr<const Scene> baked(const std::string& text) {
    auto scene = parse_scene(text, "floats.json");
    EXPECT_TRUE(scene) << (scene ? "" : scene.error().message);
    if (!scene) return nullptr;
    auto b = bake_scene(*scene);
    EXPECT_TRUE(b) << (b ? "" : b.error().message);
    return b ? *b : nullptr;
}

const char* kBoatAndBarrel =
    R"(, "boats": [{"name": "tug", "path": [[0, 0], [400, 0], [400, 400]], "speed": 4.0, "length": 20.0,
                                              "beam": 6.0, "draft": 1.5, "start": 0.0}],
    "floats": [{"name": "barrel", "shape": "barrel", "at": [-300, -300], "radius": 0.3, "height": 0.9, "mass": 120},
               {"name": "crate", "shape": "box", "at": [-320, -300], "size": [1.0, 0.6, 0.8], "mass": 150},
               {"name": "buoy", "shape": "sphere", "at": [-340, -300], "radius": 0.5, "mass": 200}])";

// On nearly still water the floats settle at Archimedes' draft (a tall barrel tips
// onto its side: upright its centre of mass is above its metacentre) and the boat keeps
// to its path and heading, floating at its draft, nearly level.
TEST(SceneFloaters, BoatsKeepToTheirPathsAndFloatsSettleAtTheirDraft) {
    auto scene = baked(pool(kBoatAndBarrel));
    ASSERT_TRUE(scene);
    auto floaters = SceneFloaters::create(scene, 30.0);
    ASSERT_TRUE(floaters) << floaters.error().message;
    ASSERT_EQ(floaters->bodies().size(), 4u);
    EXPECT_TRUE(floaters->bodies()[0].boat);
    // The boat's hull is closed and outward: its volume is the hull's plan x 2 drafts plus the deckhouse's.
    const HullMesh& hull = floaters->bodies()[0].hull;
    ASSERT_TRUE(hull.validate().ok());
    EXPECT_NEAR(hull.volume(), HullMesh::boat_plan_area(20.0, 6.0) * 3.0 + 5.0 * 3.0 * 2.25, 1e-9);
    // It keeps the water out of its hull, bow included: every hull vertex under the deck
    // lies within 2 % of the hull's length of its clip's surface, on or outside it, and the
    // clip reaches no further than the hull (a point just past the beam or the deck is out).
    const ClipVolume& dry = floaters->bodies()[0].clip;
    ASSERT_EQ(dry.shape, ClipVolume::Shape::convex);
    ASSERT_TRUE(validate(dry, "boat").ok());
    double bow = -1e9;
    for (const glm::dvec3& v : hull.vertices) {
        if (v.y > 1.5 + 1e-9) continue;  // the deckhouse
        bow = std::max(bow, v.x);
        EXPECT_LT(clip_distance(dry, v), 0.02 * 20.0) << v.x << " " << v.y << " " << v.z;
        EXPECT_GT(clip_distance(dry, v), -1e-9) << "the clip lies inside the hull";
    }
    EXPECT_LT(clip_distance(dry, {bow - 2.0, 0.0, 0.0}), 0.0) << "the bow is dry inside";
    EXPECT_GT(clip_distance(dry, {0.0, 0.0, 3.05}), 0.0) << "past the beam";
    EXPECT_GT(clip_distance(dry, {0.0, 1.55, 0.0}), 0.0) << "above the deck";
    EXPECT_EQ(floaters->bodies()[1].name, "barrel");
    // The crate (1 x 0.6 x 0.8 m, 150 kg): its centre 0.3 m above its bottom, averaged over 10 s.
    double crate_y = 0.0;
    int n = 0;
    for (double t = 30.0; t < 40.0; t += 0.1, ++n) {
        ASSERT_TRUE(floaters->advance_to(t).ok());
        crate_y += floaters->pose(2).position.y;
    }
    crate_y /= n;
    const double crate_draft = 150.0 / (kWaterDensity * 0.8);
    const glm::dvec3 barrel_axis = floaters->pose(1).orientation * glm::dvec3(0.0, 1.0, 0.0);
    std::printf("crate draft %.4f m (Archimedes %.4f); barrel axis %.0f deg from upright; buoy centre at %.3f m\n",
                0.3 - crate_y, crate_draft, std::acos(std::abs(barrel_axis.y)) * 180.0 / kPi,
                floaters->pose(3).position.y);
    EXPECT_NEAR(0.3 - crate_y, crate_draft, 0.01 * crate_draft);
    EXPECT_GT(std::acos(std::abs(barrel_axis.y)), 30.0 * kPi / 180.0);
    EXPECT_LT(std::abs(floaters->pose(1).position.y), 0.3);
    // The buoy (r = 0.5 m, 200 kg) floats with its centre above the water.
    EXPECT_GT(floaters->pose(3).position.y, 0.0);
    EXPECT_LT(floaters->pose(3).position.y, 0.5);
    for (double t : {40.0, 90.0, 110.0}) {  // on the first leg, before the corner (t = 100), on the second
        ASSERT_TRUE(floaters->advance_to(t).ok());
        glm::dvec2 at;
        double heading = 0.0;
        scene->boats[0].pose_at(floaters->time(), at, heading);
        const SceneFloaters::Pose boat = floaters->pose(0);
        const glm::dvec3 forward = boat.orientation * glm::dvec3(1.0, 0.0, 0.0);
        const double drawn = std::atan2(forward.z, forward.x);
        const double tilt = std::acos(std::clamp((boat.orientation * glm::dvec3(0.0, 1.0, 0.0)).y, -1.0, 1.0));
        std::printf(
            "t = %.0f s: boat %.6f m off its path, heading %.6f deg off, origin at y = %.4f m, tilted %.2f deg\n", t,
            glm::length(glm::dvec2(boat.position.x, boat.position.z) - at),
            std::abs(std::remainder(drawn - heading, kTwoPi)) * 180.0 / kPi, boat.position.y, tilt * 180.0 / kPi);
        EXPECT_LT(glm::length(glm::dvec2(boat.position.x, boat.position.z) - at), 1e-6);
        EXPECT_LT(std::abs(std::remainder(drawn - heading, kTwoPi)), 1e-6);
        EXPECT_LT(std::abs(boat.position.y),
                  0.04);                     // keel at -draft: the origin at the waterline (it heels in the turn)
        EXPECT_LT(tilt, 5.0 * kPi / 180.0);  // it heels in the turn
    }
}

// The same start and step give the same motion however the host advances it.
TEST(SceneFloaters, TheMotionDoesNotDependOnHowOftenItIsAdvanced) {
    auto scene = baked(pool(kBoatAndBarrel));
    ASSERT_TRUE(scene);
    auto a = SceneFloaters::create(scene, 0.0);
    auto b = SceneFloaters::create(scene, 0.0);
    ASSERT_TRUE(a && b);
    ASSERT_TRUE(a->advance_to(20.0).ok());
    for (double t = 0.0; t <= 20.0; t += 1.0 / 144.0) ASSERT_TRUE(b->advance_to(t).ok());
    ASSERT_TRUE(b->advance_to(20.0).ok());
    for (std::size_t i = 0; i < a->bodies().size(); ++i) {
        EXPECT_EQ(a->pose(i).position, b->pose(i).position) << i;
        EXPECT_EQ(a->pose(i).orientation, b->pose(i).orientation) << i;
    }
    // An edited copy with the same bodies carries on (the editor's re-bakes); one with
    // other bodies is refused.
    const glm::dvec3 before = a->pose(1).position;
    EXPECT_TRUE(a->set_scene(std::make_shared<const Scene>(*scene)).ok());
    EXPECT_EQ(a->pose(1).position, before);
    ASSERT_TRUE(a->advance_to(21.0).ok());
    auto other = baked(pool(""));
    ASSERT_TRUE(other);
    EXPECT_FALSE(a->set_scene(other).ok());
}

// An open box (a skiff 3 x 0.8 x 1.6 m of 480 kg) floats as the closed box does, at
// Archimedes' draft: 480 / (1000 x 3 x 1.6) = 0.1 m; it is drawn without its lid and keeps
// the water out of its hold, a box its own size round its body frame.
TEST(SceneFloaters, AnOpenBoxFloatsAtItsDraftWithItsHoldDry) {
    auto scene = baked(pool(
        R"(, "floats": [{"name": "skiff", "shape": "open_box", "at": [5, 5], "size": [3, 0.8, 1.6], "mass": 480}])"));
    ASSERT_TRUE(scene);
    auto floaters = SceneFloaters::create(scene, 30.0);
    ASSERT_TRUE(floaters) << floaters.error().message;
    const SceneFloaters::Body& skiff = floaters->bodies()[0];
    EXPECT_EQ(skiff.hull.triangles.size(), 10u);
    for (const auto& t : skiff.hull.triangles) {
        const bool top =
            skiff.hull.vertices[t[0]].y > 0.0 && skiff.hull.vertices[t[1]].y > 0.0 && skiff.hull.vertices[t[2]].y > 0.0;
        EXPECT_FALSE(top) << "a face on its top";
    }
    EXPECT_EQ(skiff.clip.shape, ClipVolume::Shape::box);
    EXPECT_EQ(skiff.clip.half_extents, glm::dvec3(1.5, 0.4, 0.8));
    const SceneFloaters::Pose pose = floaters->pose(0);
    const double bottom = pose.position.y - 0.4;
    std::printf("open box: bottom %.3f m under the surface (Archimedes 0.100 m)\n", -bottom);
    EXPECT_NEAR(-bottom, 0.1, 0.01);
    // Its hold is dry: the queries with its clip at its pose say so.
    ClipVolume hold = skiff.clip;
    hold.center = pose.position + pose.orientation * skiff.clip.center;
    hold.orientation = pose.orientation * skiff.clip.orientation;
    QueryOptions options;
    options.clip_volumes = std::span<const ClipVolume>(&hold, 1);
    const glm::dvec2 inside(pose.position.x, pose.position.z);
    WorldPoint water;
    ASSERT_TRUE(
        query_world(*scene, 30.0, std::span<const glm::dvec2>(&inside, 1), std::span<WorldPoint>(&water, 1), options)
            .ok());
    EXPECT_FALSE(water.surface.wet);
}

TEST(SceneFloaters, BadFloatsAreRefusedByName) {
    const std::pair<const char*, const char*> cases[] = {
        {R"(, "floats": [{"shape": "raft", "at": [0, 0], "mass": 10}])", "/floats/0/shape"},
        {R"(, "floats": [{"shape": "barrel", "at": [0, 0], "radius": 0.3, "height": 0.9, "mass": 1000}])",
         "/floats/0/mass"},
        {R"(, "floats": [{"shape": "barrel", "at": [0, 0], "size": [1, 1, 1], "mass": 10}])", "/floats/0/size"},
        {R"(, "floats": [{"shape": "box", "at": [0, 0], "size": [1, -1, 1], "mass": 10}])", "/floats/0/size"},
        {R"(, "floats": [{"shape": "sphere", "at": [0, "x"], "radius": 0.5, "mass": 10}])", "/floats/0/at"},
        {R"(, "floats": [{"shape": "sphere", "at": [0, 0], "radius": NaN, "mass": 10}])", "floats.json"},
        {R"(, "floats": [{"shape": "sphere", "at": [0, 0], "radius": 0.5}])", "/floats/0/mass"},
        {R"(, "floats": [{"shape": "sphere", "at": [0, 0], "radius": 0.5, "mass": 10, "colour": [1, 0, 0]}])",
         "colour"},
        {R"(, "floats": {"shape": "sphere"})", "/floats"},
    };
    for (const auto& [extra, where] : cases) {
        auto scene = parse_scene(pool(extra), "floats.json");
        ASSERT_FALSE(scene) << extra;
        EXPECT_NE(scene.error().message.find("floats.json"), std::string::npos) << scene.error().message;
        EXPECT_NE(scene.error().message.find(where), std::string::npos) << scene.error().message;
    }
    // A float set on land is refused when it is set afloat.
    auto island =
        parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": 5}}, "ocean": "pool_calm",
                                 "floats": [{"name": "stranded", "at": [0, 0], "mass": 10}]})",
                    "land.json");
    ASSERT_TRUE(island) << island.error().message;
    auto b = bake_scene(*island);
    ASSERT_TRUE(b) << b.error().message;
    auto floaters = SceneFloaters::create(*b, 0.0);
    ASSERT_FALSE(floaters);
    EXPECT_NE(floaters.error().message.find("stranded"), std::string::npos) << floaters.error().message;
    // So is a boat whose path crosses land (a bar across the pool at x = 100).
    auto barred = parse_scene(R"({"version": 1, "water_level": 0, "ocean": "pool_calm",
                                 "terrain": {"island": {"seed": 7, "radius": 300, "height": 40, "seabed": -40}},
                                 "boats": [{"name": "tug", "path": [[-900, 0], [900, 0]], "speed": 5.0, "length": 20.0,
                                            "beam": 6.0, "draft": 1.5}]})",
                              "barred.json");
    ASSERT_TRUE(barred) << barred.error().message;
    auto barred_baked = bake_scene(*barred);
    ASSERT_TRUE(barred_baked) << barred_baked.error().message;
    auto aground = SceneFloaters::create(*barred_baked, 0.0);
    ASSERT_FALSE(aground);
    EXPECT_NE(aground.error().message.find("boats/0 (tug): its path runs over land"), std::string::npos)
        << aground.error().message;
}

}  // namespace
}  // namespace tidewater
