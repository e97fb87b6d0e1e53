// Floating rigid bodies against Archimedes and the heave oscillator.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "test_helpers.hpp"
#include "tidewater/buoyancy.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

constexpr double kRhoG = kWaterDensity * 9.81;

/// Releases a body on calm water (level 0) and returns its centre's mean height over
/// 10 s after 20 s: where its weight and buoyancy balance (it oscillates about it).
double settle(const RigidBodyProps& props, double start_height) {
    const WaterBody calm = test::make_body({});
    BuoyancyWorld world;
    RigidBodyState s;
    s.position = {0.0, start_height, 0.0};
    auto id = world.add(props, s);
    EXPECT_TRUE(id.ok());
    EXPECT_TRUE(world.advance({nullptr, &calm, nullptr}, 20.0).ok());
    double sum = 0.0;
    int n = 0;
    while (world.time() < 30.0) {
        EXPECT_TRUE(world.step({nullptr, &calm, nullptr}).ok());
        sum += world.state(*id).position.y;
        ++n;
    }
    return sum / n;
}

// Equilibrium drafts: a 2 x 1 x 1.5 m box of 900 kg floats 0.2927 m deep (m / (rho A));
// a sphere of radius 1 m and 1500 kg to the depth d of pi d^2 (3 R - d) / 3 = m / rho.
// Both within 1% (the sphere's mesh of 48 rings holds 99.7% of the sphere's volume).
TEST(Buoyancy, EquilibriumDraftsAreArchimedes) {
    const RigidBodyProps box = RigidBodyProps::solid_box({2.0, 1.0, 1.5}, 900.0);
    const double box_draft = -settle(box, 0.25) + 0.5;
    const double box_expected = 900.0 / (kWaterDensity * 2.0 * 1.5);
    RigidBodyProps sphere;
    sphere.mass = 1500.0;
    sphere.inertia = glm::dvec3(0.4 * 1500.0);
    sphere.hull = HullMesh::sphere(1.0, 48);
    const double sphere_draft = -settle(sphere, 0.25) + 1.0;
    double lo = 0.0, hi = 2.0;  // pi d^2 (3 - d) / 3 = m / rho by bisection
    for (int i = 0; i < 60; ++i) {
        const double d = 0.5 * (lo + hi);
        (kPi * d * d * (3.0 - d) / 3.0 < 1500.0 / kWaterDensity ? lo : hi) = d;
    }
    std::printf("box draft %.4f m (Archimedes %.4f); sphere %.4f m (%.4f); sphere mesh volume %.4f of 4/3 pi\n",
                box_draft, box_expected, sphere_draft, lo, sphere.hull.volume() / (4.0 / 3.0 * kPi));
    EXPECT_NEAR(box_draft, box_expected, 0.01 * box_expected);
    EXPECT_NEAR(sphere_draft, lo, 0.01 * lo);
}

/// The heave period of a box released 5 cm above its equilibrium on calm water without
/// drag, from the zero crossings of its displacement, with integration step `step`.
double heave_period(const RigidBodyProps& props, double equilibrium, double step) {
    const WaterBody calm = test::make_body({});
    BuoyancyOptions options;
    options.step = step;
    BuoyancyWorld world(options);
    RigidBodyState s;
    s.position = {0.0, equilibrium + 0.05, 0.0};
    const int id = *world.add(props, s);
    std::vector<double> crossings;
    double last = 0.05, last_t = 0.0;
    while (world.time() < 30.0) {
        EXPECT_TRUE(world.step({nullptr, &calm, nullptr}).ok());
        const double y = world.state(id).position.y - equilibrium;
        if (last > 0.0 && y <= 0.0) crossings.push_back(last_t + step * last / (last - y));
        last = y;
        last_t = world.time();
    }
    return crossings.size() >= 2 ? (crossings.back() - crossings.front()) / double(crossings.size() - 1) : 0.0;
}

// Calm-water heave: T = 2 pi sqrt(m / (rho g A_wp)) within 3% (a box: a linear spring),
// the same within 0.5% at 30, 60 and 144 steps a second.
TEST(Buoyancy, HeavePeriodIsTheSpringOfTheWaterplane) {
    RigidBodyProps box = RigidBodyProps::solid_box({3.0, 1.0, 2.0}, 1800.0);
    box.drag = 0.0;
    const double area = 3.0 * 2.0, draft = 1800.0 / (kWaterDensity * area);
    const double expected = kTwoPi * std::sqrt(1800.0 / (kRhoG * area));
    const double equilibrium = 0.5 - draft;
    std::vector<double> periods;
    for (const double rate : {30.0, 60.0, 144.0}) periods.push_back(heave_period(box, equilibrium, 1.0 / rate));
    std::printf("heave period %.4f s at 30 Hz, %.4f at 60 Hz, %.4f at 144 Hz; 2 pi sqrt(m / rho g A) = %.4f s\n",
                periods[0], periods[1], periods[2], expected);
    for (double p : periods) EXPECT_NEAR(p, expected, 0.03 * expected);
    const auto [lo, hi] = std::minmax_element(periods.begin(), periods.end());
    EXPECT_LT((*hi - *lo) / *lo, 0.005);
}

// Long waves carry a small body up and down with them: for a wave 20 times the box's
// length the heave amplitude is the wave's within 5%.
TEST(Buoyancy, LongWavesLiftTheBodyByTheirAmplitude) {
    const double lambda = 40.0, a = 0.25;
    const WaterBody sea = test::make_body({{0.0, lambda, a, 0.0, 0.0}});
    BuoyancyWorld world;
    RigidBodyProps box = RigidBodyProps::solid_box({2.0, 0.6, 2.0}, 600.0);
    RigidBodyState s;
    s.position = {0.0, 0.3 - 600.0 / (kWaterDensity * 4.0), 0.0};
    const int id = *world.add(box, s);
    double lo = 1e9, hi = -1e9;
    const double period = std::sqrt(kTwoPi * lambda / 9.81);
    while (world.time() < 12.0 * period) {
        ASSERT_TRUE(world.step({nullptr, &sea, nullptr}).ok());
        if (world.time() > 6.0 * period) {
            lo = std::min(lo, world.state(id).position.y);
            hi = std::max(hi, world.state(id).position.y);
        }
    }
    const double response = 0.5 * (hi - lo) / a;
    std::printf("heave response %.3f for lambda / L = %.0f\n", response, lambda / 2.0);
    EXPECT_NEAR(response, 1.0, 0.05);
}

// A barrel 60 m beside a tug's track heaves more as the wake passes than before it comes.
TEST(Buoyancy, ABarrelRidesThePassingWake) {
    auto scene =
        parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm",
        "boats": [{"name": "tug", "path": [[0, 0], [2000, 0]], "speed": 5.0, "length": 20.0, "beam": 6.0, "draft": 1.5}]})",
                    "s.json");
    ASSERT_TRUE(scene) << scene.error().message;
    auto baked = bake_scene(*scene);
    ASSERT_TRUE(baked) << baked.error().message;
    BuoyancyOptions options;
    options.step = 1.0 / 20.0;  // the barrel heaves with a 1.3 s period
    BuoyancyWorld world(options);
    RigidBodyState s;
    s.position = {300.0, 0.0, 60.0};
    RigidBodyProps barrel = RigidBodyProps::barrel(0.3, 0.9, 120.0);
    barrel.hull = HullMesh::cylinder(0.3, 0.9, 12);
    const int id = *world.add(barrel, s);
    world.set_time(45.0);
    std::vector<double> before, during;
    while (world.time() < 115.0) {
        ASSERT_TRUE(world.step({baked->get(), nullptr, nullptr}).ok());
        const double t = world.time(), y = world.state(id).position.y;
        if (t > 50.0 && t < 70.0)
            before.push_back(y);  // the tug passes x = 300 at t = 60; its wake reaches the barrel near 95
        if (t > 95.0 && t < 115.0) during.push_back(y);
    }
    auto spread = [](const std::vector<double>& v) {
        return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    std::printf("barrel heave range: %.4f m before the wake, %.4f m as it passes\n", spread(before), spread(during));
    EXPECT_GT(spread(during), 3.0 * spread(before));
    EXPECT_GT(spread(during), 0.05);
}

TEST(Buoyancy, BadBodiesAreRefused) {
    BuoyancyWorld world;
    RigidBodyProps p = RigidBodyProps::solid_box({1.0, 1.0, 1.0}, 100.0);
    p.mass = -1.0;
    EXPECT_FALSE(world.add(p, {}).ok());
    p.mass = std::nan("");
    EXPECT_FALSE(world.add(p, {}).ok());
    p = RigidBodyProps::solid_box({1.0, 1.0, 1.0}, 100.0);
    std::swap(p.hull.triangles[0][1], p.hull.triangles[0][2]);
    for (auto& t : p.hull.triangles) std::swap(t[1], t[2]);  // inside out
    auto inward = world.add(p, {});
    ASSERT_FALSE(inward.ok());
    EXPECT_NE(inward.error().message.find("not positive"), std::string::npos) << inward.error().message;
    p.hull.triangles[0][0] = 99;
    auto out_of_range = world.add(p, {});
    ASSERT_FALSE(out_of_range.ok());
    EXPECT_NE(out_of_range.error().message.find("names vertex 99"), std::string::npos) << out_of_range.error().message;
    EXPECT_FALSE(world.advance({}, std::nan("")).ok());
}

}  // namespace
}  // namespace tidewater
