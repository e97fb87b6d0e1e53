// Lakes and rivers on lavapipe under the validation layer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "../bowl_terrain.hpp"
#include "render_fixture.hpp"
#include "tidewater/detail/shore_waves.hpp"

namespace tidewater {
namespace {

// Lakes and rivers (issue: rivers and lakes).

/// A river on a plane falling 4 m per km, bending and widening into a calm sea at x = 2500
/// (a rolling sea would bare the 0.4% beach in its troughs far from the mouth).
const char* kRiverScene = R"({ "version": 1, "name": "river", "water_level": 0.0,
  "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } }, "ocean": "pool_calm", "shore": { "enabled": false },
  "rivers": [ { "name": "bend", "path": [[-1500, 0], [-600, 120], [200, -80], [1200, 60], [2900, 40]],
                "width": [40, 44, 50, 60, 70], "discharge": 60.0, "manning": 0.032 } ] })";

// The river is drawn where it runs, at its falling surface, and nothing wet shows on the
// dry land beside it (which stands above the river's surface).
TEST_F(RenderTest, RiverIsDrawnWhereItRunsAndTheLandBesideItIsDry) {
    const Scene scene = scene_from(kRiverScene);
    render::FrameInfo frame;
    frame.camera.position = {600.0, 160.0, -320.0};
    frame.camera.target = {900.0, 0.0, 40.0};
    frame.time = 2.0;
    const auto img = render(scene, frame, 480, 270);
    const auto& path = scene.rivers[0].path;
    int river_points = 0, land_points = 0;
    for (int k = 0; k <= 40; ++k) {
        // Along the reach from (200, -80) to (1200, 60): the centreline and 120 m beside it.
        const glm::dvec2 a = path[2], b = path[3];
        const glm::dvec2 c = a + (b - a) * (k / 40.0);
        const glm::dvec2 t = glm::normalize(b - a), left{-t.y, t.x};
        const WorldPoint on = query_world_point(scene, frame.time, c);
        ASSERT_EQ(on.body.kind, BodyKind::river) << k;
        if (auto q = test::project(frame.camera, 480, 270, {c.x, on.surface.height, c.y})) {
            const Rgb col = test::block(img, q->x, q->y, 1);
            EXPECT_TRUE(is_water(col)) << "river at " << q->x << "," << q->y << ": " << col.r << " " << col.g << " "
                                       << col.b;
            ++river_points;
        }
        for (double side : {-120.0, 120.0}) {
            const glm::dvec2 d = c + left * side;
            ASSERT_EQ(query_world_point(scene, frame.time, d).body.kind, BodyKind::none);
            if (auto q = test::project(frame.camera, 480, 270, {d.x, scene.terrain.height_at(d), d.y})) {
                const Rgb col = test::block(img, q->x, q->y, 1);
                EXPECT_TRUE(is_land(col))
                    << "dry land at " << q->x << "," << q->y << ": " << col.r << " " << col.g << " " << col.b;
                ++land_points;
            }
        }
    }
    EXPECT_GT(river_points, 20);
    EXPECT_GT(land_points, 50);
}

// Where the river meets the sea the water is continuous: along the river's axis through its
// mouth every pixel is water, and neighbouring pixels differ by no more than the waves do.
TEST_F(RenderTest, RiverMeetsTheSeaWithoutASeam) {
    const Scene scene = scene_from(kRiverScene);
    render::FrameInfo frame;
    frame.camera.position = {2200.0, 120.0, -260.0};
    frame.camera.target = {2500.0, 0.0, 40.0};
    frame.time = 4.0;
    const auto img = render(scene, frame, 480, 270);
    int samples = 0;
    double worst_step = 0.0;
    std::optional<Rgb> last;
    for (int k = 0; k <= 120; ++k) {
        const glm::dvec2 p{2300.0 + 400.0 * k / 120.0, 40.0};
        const WorldPoint w = query_world_point(scene, frame.time, p);
        ASSERT_NE(w.body.kind, BodyKind::none) << p.x;
        const auto q = test::project(frame.camera, 480, 270, {p.x, w.surface.height, p.y});
        if (!q) continue;
        const Rgb col = test::block(img, q->x, q->y, 1);
        EXPECT_TRUE(is_water(col)) << "at x = " << p.x << " (" << q->x << "," << q->y << "): " << col.r << " " << col.g
                                   << " " << col.b;
        if (last)
            worst_step =
                std::max({worst_step, std::abs(col.r - last->r), std::abs(col.g - last->g), std::abs(col.b - last->b)});
        last = col;
        ++samples;
    }
    EXPECT_GT(samples, 60);
    EXPECT_LT(worst_step, 0.2);
}

// A lake at 30 m in a bowl of an inland scene (no ocean): water inside its waterline
// (r = 245 m), dry slopes outside it; the floor at 10 m would hide water at any lower level.
TEST_F(RenderTest, LakeSitsAtItsLevelInTheHills) {
    auto parsed = test::bowl_lake_scene();
    ASSERT_TRUE(parsed) << parsed.error().message;
    auto scene = test::baked(*parsed);
    ASSERT_TRUE(scene) << scene.error().message;
    render::FrameInfo frame;
    frame.camera.position = {-420.0, 260.0, -420.0};
    frame.camera.target = {0.0, 30.0, 0.0};
    frame.time = 1.0;
    const auto img = render(*scene, frame, 480, 270);
    int water = 0, land = 0;
    for (int a = 0; a < 24; ++a) {
        const glm::dvec2 dir{std::cos(a * kPi / 12.0), std::sin(a * kPi / 12.0)};
        for (double r : {0.0, 120.0, 220.0}) {
            const glm::dvec2 p = dir * r;
            if (auto q = test::project(frame.camera, 480, 270, {p.x, 30.0, p.y})) {
                const Rgb col = test::block(img, q->x, q->y, 1);
                EXPECT_TRUE(is_water(col)) << "lake at r = " << r << ": " << col.r << " " << col.g << " " << col.b;
                ++water;
            }
        }
        const glm::dvec2 p = dir * 285.0;  // the slope 8 m above the lake
        if (auto q = test::project(frame.camera, 480, 270, {p.x, scene->terrain.height_at(p), p.y})) {
            const Rgb col = test::block(img, q->x, q->y, 1);
            EXPECT_TRUE(is_land(col)) << "slope at angle " << a << ": " << col.r << " " << col.g << " " << col.b;
            ++land;
        }
    }
    EXPECT_GT(water, 40);
    EXPECT_GT(land, 12);

    // The lake draws with its own shore model: in the shore view its water shows the
    // distance to its beach (about 245 m at the centre, under 30 m near the rim), not the
    // open water's "no shore" everywhere.
    frame.view = render::DebugView::shore;
    const auto shore_img = render(*scene, frame, 480, 270);
    const auto centre = test::project(frame.camera, 480, 270, {0.0, 30.0, 0.0});
    ASSERT_TRUE(centre);
    const Rgb middle = test::block(shore_img, centre->x, centre->y, 1);
    int rim_pixels = 0;
    for (int a = 0; a < 24; ++a) {
        const glm::dvec2 p = glm::dvec2(std::cos(a * kPi / 12.0), std::sin(a * kPi / 12.0)) * 225.0;
        const auto q = test::project(frame.camera, 480, 270, {p.x, 30.0, p.y});
        if (!q) continue;
        const Rgb rim = test::block(shore_img, q->x, q->y, 1);
        const double diff =
            std::max({std::abs(rim.r - middle.r), std::abs(rim.g - middle.g), std::abs(rim.b - middle.b)});
        EXPECT_GT(diff, 0.25) << "rim at angle " << a << " looks like the middle: " << rim.r << " " << rim.g << " "
                              << rim.b;
        ++rim_pixels;
    }
    EXPECT_GT(rim_pixels, 12);

    // And with its preset's ripples (0.6 m): seen from 6 m above the water, where a pixel
    // resolves them, the same lake without them shades differently. (From afar they only
    // widen the glitter: the far field is filtered.)
    frame.view = render::DebugView::normals;
    frame.camera.position = {-20.0, 36.0, -20.0};
    frame.camera.target = {0.0, 30.0, 0.0};
    const auto rippled = render(*scene, frame, 480, 270);
    Scene calm = *scene;
    WaterProfile profile = calm.lakes[0].body.profile();
    ASSERT_GT(profile.ripples.amplitude, 0.0) << "the default lake preset has ripples";
    profile.ripples.amplitude = 0.0;
    auto still = WaterBody::create(profile, calm.lakes[0].body.level(), "bowl");
    ASSERT_TRUE(still);
    auto shored = still->with_shore(calm.lakes[0].body.shore());  // the same waves: the same shore model
    ASSERT_TRUE(shored);
    calm.lakes[0].body = std::move(shored).value();
    ASSERT_TRUE(calm.baked());
    const auto smooth = render(calm, frame, 480, 270);
    int differ = 0, lake_pixels = 0;
    for (int y = 210; y < 270; y += 6)  // the bottom rows: water within about 10 m
        for (int x = 8; x < 480; x += 16) {
            const Rgb a = test::pixel(rippled, x, y), b = test::pixel(smooth, x, y);
            differ += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 0.01 ? 1 : 0;
            ++lake_pixels;
        }
    EXPECT_GT(differ, lake_pixels / 2) << differ << " of " << lake_pixels << " lake pixels change with the ripples";
}

}  // namespace
}  // namespace tidewater
