// Floating bodies and boat wakes on lavapipe under the validation layer: drawn where the
// CPU puts them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "tidewater/scene_floaters.hpp"

namespace tidewater {
namespace {

// Floating bodies (FrameInfo::floats) are drawn where SceneFloaters puts them: from 80 m
// straight above a tug on a calm pool, the pixels under its deck carry its red paint and
// those 30 m beside it are water; a barrel drifting 40 m off shows its orange. Under the
// validation layer. A body without a hull is refused, naming it.
TEST_F(RenderTest, FloatingBodiesAreDrawnWhereTheyFloat) {
    const Scene scene =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm",
        "boats": [{"name": "tug", "path": [[-400, 0], [400, 0]], "speed": 5.0, "length": 20.0, "beam": 6.0, "draft": 1.5}],
        "floats": [{"name": "barrel", "at": [100, 40], "radius": 1.0, "height": 1.5, "mass": 1500, "color": [0.9, 0.45, 0.05]}]})");
    auto floaters = SceneFloaters::create(std::make_shared<const Scene>(scene), 20.0);  // the tug's centre at x = -300
    ASSERT_TRUE(floaters) << floaters.error().message;
    const std::vector<render::FloatDraw> draws = render::float_draws(*floaters);
    render::FrameInfo frame;
    frame.time = 20.0;
    frame.floats = draws;
    auto look_down_at = [&](glm::dvec3 at) {
        frame.camera.position = at + glm::dvec3(0.0, 80.0, 0.0);
        frame.camera.target = at + glm::dvec3(0.0, 0.0, 1.0);  // image up is +z, image right is -x
        frame.camera.fov_y_deg = 60.0;
    };
    auto red = [](Rgb c) { return c.r > 1.8 * c.g && c.r > 1.8 * c.b; };
    const glm::dvec3 tug = floaters->pose(0).position;
    look_down_at(tug);
    const auto img = render(scene, frame, 320, 320);
    // 80 m up with a 60 degree field: 320 pixels span 92 m, 3.5 pixels a metre.
    int painted = 0, beside = 0;
    for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
            painted += red(test::pixel(img, 160 + dx, 160 + dy));
            beside += red(test::pixel(img, 160 + dx, 160 + 105 + dy)) + red(test::pixel(img, 160 + dx, 160 - 105 + dy));
        }
    const Rgb deck = test::pixel(img, 160, 160), water = test::pixel(img, 160, 265);
    std::printf(
        "tug at (%.1f, %.3f, %.1f): %d of 81 pixels under its deck red (%.2f %.2f %.2f), %d of 162 beside it (water "
        "%.2f %.2f %.2f)\n",
        tug.x, tug.y, tug.z, painted, deck.r, deck.g, deck.b, beside, water.r, water.g, water.b);
    EXPECT_GT(painted, 70);
    EXPECT_EQ(beside, 0);
    const glm::dvec3 barrel = floaters->pose(1).position;
    look_down_at(barrel);
    const auto barrel_img = render(scene, frame, 320, 320);
    const Rgb top = test::pixel(barrel_img, 160, 160);
    std::printf("barrel at (%.1f, %.3f, %.1f): %.2f %.2f %.2f\n", barrel.x, barrel.y, barrel.z, top.r, top.g, top.b);
    EXPECT_GT(top.r, 1.5 * top.g);
    EXPECT_GT(top.g, 2.0 * top.b);
    render::FloatDraw missing;
    frame.floats = std::span<const render::FloatDraw>(&missing, 1);
    auto refused = target_->render(*renderer_, frame);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("FrameInfo::floats[0]"), std::string::npos) << refused.error().message;
}

// Boat wakes are drawn where the CPU puts them: a tug at 5 m/s on a calm pool seen from
// 300 m up (1 degree off the vertical), the wake view (the wakes' share of the height).
// Inside Kelvin's wedge behind the boat most pixels show the wake; ahead of the boat and
// outside 25 degrees of its track (beyond 40 m of the bow) almost none do; under the image centre the drawn wake
// is the CPU query's wake column within 2 cm (8-bit colour, rest against fixed point).
// The shaded view shows the stern's churned foam behind the boat.
TEST_F(RenderTest, BoatWakesAreDrawnInKelvinsWedge) {
    const Scene scene =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm",
        "boats": [{"name": "tug", "path": [[-400, 0], [400, 0]], "speed": 5.0, "length": 20.0, "beam": 6.0, "draft": 1.5}]})");
    render::FrameInfo frame;
    frame.time = 100.0;  // the tug's bow shoulders are at x = 105
    const glm::dvec3 centre{-60.0, 0.0, 20.0};
    frame.camera.position = centre + glm::dvec3(0.0, 300.0, 0.0);
    frame.camera.target = frame.camera.position + glm::dvec3(0.0, -300.0, 5.0);
    frame.camera.fov_y_deg = 60.0;
    frame.view = render::DebugView::wake;
    const auto img = render(scene, frame, 320, 320);
    // Image axes from above: find the world point under each pixel on the plane y = 0.
    const glm::dmat4 view = glm::lookAt(frame.camera.position, frame.camera.target, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 proj = glm::perspective(frame.camera.fov_y_deg * kPi / 180.0, 1.0, 0.3, 1000.0);
    const glm::dmat4 inv = glm::inverse(proj * view);
    auto ground = [&](int x, int y) {
        const glm::dvec2 ndc{(x + 0.5) / 160.0 - 1.0, 1.0 - (y + 0.5) / 160.0};
        glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), b = inv * glm::dvec4(ndc, 1.0, 1.0);
        const glm::dvec3 p = glm::dvec3(a) / a.w, q = glm::dvec3(b) / b.w;
        return p + (q - p) * (p.y / (p.y - q.y));
    };
    auto wake_of = [](Rgb c) { return 2.0 * (c.r < 0.99 ? c.r / 1.5 : 1.0 - c.b / 1.5) - 1.0; };  // heat_color inverted
    int inside = 0, inside_drawn = 0, outside = 0, outside_drawn = 0;
    const glm::dvec2 apex{105.0, 0.0};
    for (int y = 0; y < 320; y += 4)
        for (int x = 0; x < 320; x += 4) {
            const glm::dvec3 w = ground(x, y);
            const glm::dvec2 rel = glm::dvec2(w.x, w.z) - apex;
            const double behind = -rel.x, angle = std::atan2(std::abs(rel.y), behind) * 180.0 / kPi;
            const bool drawn = std::abs(wake_of(test::pixel(img, x, y))) > 0.02;
            if (behind > 20.0 && angle < 15.0) {
                ++inside;
                inside_drawn += drawn;
            } else if (glm::length(rel) > 40.0 && (behind < -10.0 || angle > 25.0)) {  // beyond the bow's near field
                ++outside;
                outside_drawn += drawn;
            }
        }
    const glm::dvec3 under = ground(160, 160);
    const WorldPoint cpu = query_world_point(scene, frame.time, {under.x, under.z});
    const double gpu = 0.25 * (wake_of(test::pixel(img, 159, 159)) + wake_of(test::pixel(img, 160, 159)) +
                               wake_of(test::pixel(img, 159, 160)) + wake_of(test::pixel(img, 160, 160)));
    std::printf(
        "wake drawn on %d of %d pixels inside the wedge, %d of %d outside; under the centre %.4f m drawn, %.4f m "
        "queried\n",
        inside_drawn, inside, outside_drawn, outside, gpu, cpu.surface.wake);
    EXPECT_GT(inside_drawn, inside / 2);
    EXPECT_LT(outside_drawn, outside / 50 + 1);
    EXPECT_GT(std::abs(cpu.surface.wake), 0.03) << "the centre is on a wave of the wake";
    EXPECT_NEAR(gpu, cpu.surface.wake, 0.02);
    frame.view = render::DebugView::shaded;
    frame.camera.position = {200.0, 60.0, 120.0};
    frame.camera.target = {20.0, 0.0, 0.0};
    const auto shaded = render(scene, frame, 320, 180);
    const auto calm = render(
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm"})"),
        frame, 320, 180);
    int white = 0;
    auto is_white = [](Rgb c) { return c.r > 0.75 && c.g > 0.75 && c.b > 0.75; };
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x)
            white += is_white(test::pixel(shaded, x, y)) && !is_white(test::pixel(calm, x, y));
    std::printf("shaded: %d white pixels of churned foam; %.4f from the calm pool\n", white,
                test::mean_difference(shaded, calm));
    EXPECT_GT(white, 20);  // the calm pool has none
    EXPECT_GT(test::mean_difference(shaded, calm), 0.002);
}

}  // namespace
}  // namespace tidewater
