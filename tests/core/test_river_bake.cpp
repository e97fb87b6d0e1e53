// Rivers as baked: water conserved through every section and at a confluence, no flow
// through the banks, a surface that never rises and meets still water without a step,
// and Manning's mean speed on a uniform reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/detail/water_bodies_bake.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater {
namespace {

using detail::RiverBake;

Scene parse_or_die(const std::string& json) {
    auto scene = parse_scene(json, "river-test.json");
    if (!scene) ADD_FAILURE() << scene.error().message;
    return scene ? std::move(scene).value() : Scene{};
}

detail::WaterBodiesBake bake_or_die(const Scene& scene) {
    auto bake = detail::bake_water_bodies(scene, {});
    if (!bake) ADD_FAILURE() << bake.error().message;
    return bake ? std::move(bake).value() : detail::WaterBodiesBake{};
}

/// A plane falling 1 m in 100 m toward the sea at x = 2000; a river that bends twice and
/// widens from 20 m to 40 m runs into it.
const char* kBendingRiver = R"({
  "version": 1, "name": "bend", "water_level": 0.0,
  "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } },
  "ocean": "ocean_rolling",
  "rivers": [ { "name": "bend", "path": [[-1500, 0], [-500, 250], [600, -150], [2300, 0]],
                "width": [20, 25, 40, 40], "discharge": 30.0 } ]
})";

/// The centreline sample nearest `along`, its position and downstream direction.
void section_at(const RiverBake& r, double along, glm::dvec2& p, glm::dvec2& t, double& width) {
    std::size_t k = 1;
    while (k + 2 < r.along.size() && r.along[k] < along) ++k;
    p = r.centreline[k];
    const glm::dvec2 d = r.centreline[k + 1] - r.centreline[k - 1];
    t = d / std::hypot(d.x, d.y);
    width = r.width[k];
}

/// Flux of the baked discharge field h u through the cross-section at `along`, m^3/s;
/// `side` +1 or -1 counts only the left or the right half (0: all of it).
double discharge_through(const RiverBake& r, double along, int side = 0) {
    glm::dvec2 p, t;
    double width = 0.0;
    section_at(r, along, p, t, width);
    const glm::dvec2 n{-t.y, t.x};
    const double reach = 0.5 * width + 4.0 * r.grid.texel, step = r.grid.texel / 16.0;
    double q = 0.0;
    for (double s = side > 0 ? 0.0 : -reach; s <= (side < 0 ? 0.0 : reach); s += step) {
        const glm::dvec2 x = p + s * n;
        q += (r.grid.sample(r.discharge_x, x) * t.x + r.grid.sample(r.discharge_z, x) * t.y) * step;
    }
    return q;
}

TEST(RiverBake, DischargeIsTheSameThroughEverySection) {
    const Scene scene = parse_or_die(kBendingRiver);
    const auto bake = bake_or_die(scene);
    ASSERT_EQ(bake.rivers.size(), 1u);
    const RiverBake& r = bake.rivers[0];
    EXPECT_EQ(r.end, detail::RiverEnd::ocean);
    const double length = r.along.back();
    for (double f : {0.1, 0.25, 0.4, 0.55, 0.7, 0.85}) {
        const double q = discharge_through(r, f * length);
        EXPECT_NEAR(q, 30.0, 0.3) << "at " << f * length << " m of " << length;
    }
}

TEST(RiverBake, NoCurrentOutsideTheRiver) {
    const Scene scene = parse_or_die(kBendingRiver);
    const auto bake = bake_or_die(scene);
    const RiverBake& r = bake.rivers[0];
    const auto& g = r.grid;
    // No current outside the river's water.
    for (std::size_t t = 0; t < g.size(); ++t) {
        if (r.texel[t] != 0) continue;
        ASSERT_EQ(r.flow_x[t] * r.flow_x[t] + r.flow_z[t] * r.flow_z[t], 0.0f) << "texel " << t;
    }
}

TEST(RiverBake, SurfaceNeverRisesAndMeetsTheSeaWithoutAStep) {
    const Scene scene = parse_or_die(kBendingRiver);
    const auto bake = bake_or_die(scene);
    const RiverBake& r = bake.rivers[0];
    for (std::size_t k = 1; k < r.surface.size(); ++k) ASSERT_LE(r.surface[k], r.surface[k - 1]) << "sample " << k;
    EXPECT_NEAR(r.surface.back(), 0.0, 1e-3) << "the sea's level";
    // The surface field along the centreline, sampled finely, never rises either.
    double last = 1e9;
    for (std::size_t k = 0; k + 1 < r.centreline.size(); ++k)
        for (int m = 0; m < 4; ++m) {
            const glm::dvec2 p = r.centreline[k] + 0.25 * m * (r.centreline[k + 1] - r.centreline[k]);
            const double eta = r.grid.sample(r.surface_height, p);
            ASSERT_LE(eta, last + 1e-4) << "at " << r.along[k];
            last = eta;
        }
    // Carving: the bed under the channel is the terrain the queries and the renderer see.
    ASSERT_TRUE(r.cut);
    const glm::dvec2 mid = r.centreline[r.centreline.size() / 2];
    EXPECT_LT(bake.terrain.height_at(mid), scene.terrain.height_at(mid) - 0.3);
    EXPECT_NEAR(bake.terrain.height_at(mid), r.bed[r.centreline.size() / 2], 0.1);
}

TEST(RiverBake, MeanSpeedFollowsManningOnAUniformReach) {
    const Scene scene = parse_or_die(R"({
      "version": 1, "name": "reach", "water_level": 0.0,
      "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } },
      "ocean": "ocean_rolling",
      "rivers": [ { "name": "reach", "path": [[-2000, 30], [2900, 30]], "width": 24, "discharge": 40.0, "manning": 0.03 } ]
    })");
    const auto bake = bake_or_die(scene);
    const RiverBake& r = bake.rivers[0];
    // A section in the middle: area and wetted perimeter from the baked depth and bed.
    const glm::dvec2 c{0.0, 30.0};
    const double step = r.grid.texel / 32.0;
    double area = 0.0, perimeter = 0.0, last_bed = 0.0;
    bool last_wet = false;
    for (double z = -20.0; z <= 20.0; z += step) {
        const glm::dvec2 p = c + glm::dvec2(0.0, z);
        const double depth = r.grid.sample(r.depth, p), bed = bake.terrain.height_at(p);
        if (depth > 0.0) {
            area += depth * step;
            if (last_wet) perimeter += std::hypot(step, bed - last_bed);
        }
        last_wet = depth > 0.0;
        last_bed = bed;
    }
    const double slope = (r.surface[r.surface.size() / 4] - r.surface[3 * r.surface.size() / 4]) /
                         (r.along[3 * r.surface.size() / 4] - r.along[r.surface.size() / 4]);
    const double manning = std::pow(area / perimeter, 2.0 / 3.0) * std::sqrt(slope) / 0.03;
    const double mean = 40.0 / area;
    EXPECT_NEAR(slope, 0.004, 2e-4);
    EXPECT_NEAR(mean / manning, 1.0, 0.05) << "mean " << mean << " m/s, Manning " << manning << " m/s";
    EXPECT_NEAR(discharge_through(r, 0.5 * r.along.back()), 40.0, 0.4);
}

TEST(RiverBake, DischargesAddAtAConfluence) {
    const Scene scene = parse_or_die(R"({
      "version": 1, "name": "confluence", "water_level": 0.0,
      "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } },
      "ocean": "ocean_rolling",
      "rivers": [
        { "name": "main", "path": [[-1500, 0], [2400, 0]], "width": 30, "discharge": 25.0 },
        { "name": "tributary", "path": [[-900, -700], [-300, -250], [0, 0]], "width": 16, "discharge": 9.0 }
      ]
    })");
    const auto bake = bake_or_die(scene);
    const RiverBake& main = bake.rivers[0];
    const RiverBake& tributary = bake.rivers[1];
    EXPECT_EQ(tributary.end, detail::RiverEnd::river);
    EXPECT_EQ(tributary.receiver, 0);
    EXPECT_DOUBLE_EQ(main.discharge, 34.0);
    // The junction is near x = 0, 1500 m along the main river.
    for (double along : {600.0, 1200.0}) EXPECT_NEAR(discharge_through(main, along), 25.0, 0.25) << along;
    for (double along : {1800.0, 2400.0, 3200.0}) EXPECT_NEAR(discharge_through(main, along), 34.0, 0.34) << along;
    for (double f : {0.3, 0.6}) EXPECT_NEAR(discharge_through(tributary, f * tributary.along.back()), 9.0, 0.09);
    // The tributary meets the main river's surface at the junction.
    EXPECT_NEAR(tributary.surface.back(), main.grid.sample(main.surface_height, tributary.centreline.back()), 0.02);
}

/// A plane falling 1 m in 100 m to the sea at x = 500 with a round knoll 5 m high
/// (Gaussian, sigma 10 m) at (0, knoll_z): a 2 km heightmap at 2 m pixels.
Terrain plane_with_knoll(double knoll_z) {
    auto image = std::make_shared<Gray16Image>();
    const int size = 1001;
    image->width = image->height = size;
    image->pixels.resize(static_cast<std::size_t>(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double x = (i - 500) * 2.0, z = (j - 500) * 2.0;
            const double r2 = x * x + (z - knoll_z) * (z - knoll_z);
            const double h = 5.0 - 0.01 * x + 5.0 * std::exp(-r2 / (2.0 * 10.0 * 10.0));
            image->pixels[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::lround((h + 10.0) / 40.0 * 65535.0));
        }
    HeightmapTerrain map;
    map.file = "knoll";
    map.size = {2000.0, 2000.0};
    map.min_height = -10.0;
    map.max_height = 30.0;
    map.image = std::move(image);
    return Terrain(map);
}

/// Circulation of the current round a circle, and the same integral of its speed, m^2/s.
std::pair<double, double> circulation(const RiverBake& r, glm::dvec2 centre, double radius) {
    double gamma = 0.0, speed = 0.0;
    const int steps = 720;
    for (int k = 0; k < steps; ++k) {
        const double a = 2.0 * 3.141592653589793 * k / steps, dl = 2.0 * 3.141592653589793 * radius / steps;
        const glm::dvec2 p = centre + radius * glm::dvec2(std::cos(a), std::sin(a));
        const glm::dvec2 u{r.grid.sample(r.flow_x, p), r.grid.sample(r.flow_z, p)};
        gamma += (-u.x * std::sin(a) + u.y * std::cos(a)) * dl;
        speed += std::hypot(u.x, u.y) * dl;
    }
    return {gamma, speed};
}

TEST(RiverBake, TheCarveGoesRoundAKnollAndTheRiverSplitsAroundIt) {
    for (const double knoll_z : {0.0, 4.0}) {
        Scene scene = parse_or_die(R"({
          "version": 1, "name": "knoll", "water_level": 0.0,
          "terrain": { "plane": { "height": 5.0, "slope": [-0.01, 0.0] } }, "ocean": "ocean_rolling",
          "rivers": [ { "name": "split", "path": [[-900, 0], [700, 0]], "width": 60, "discharge": 40.0 } ]
        })");
        scene.terrain = plane_with_knoll(knoll_z);
        detail::BodiesBakeOptions options;
        options.texels_across = 16.0;
        auto bake = detail::bake_water_bodies(scene, options);
        ASSERT_TRUE(bake) << bake.error().message;
        const RiverBake& r = bake->rivers[0];
        ASSERT_EQ(r.islands, 1u) << "knoll at z = " << knoll_z;
        // The knoll stays land (the carve went round it); the water beside it is carved.
        EXPECT_GT(bake->terrain.height_at({0.0, knoll_z}), r.grid.sample(r.surface_height, {0.0, knoll_z}) + 3.0);
        // The same discharge above, across and below the island (the river runs 900 m to it).
        for (double along : {500.0, 900.0, 1200.0}) EXPECT_NEAR(discharge_through(r, along), 40.0, 0.4) << along;
        // Across the island the flow splits between its two sides by their width.
        const double left = discharge_through(r, 900.0, 1), right = discharge_through(r, 900.0, -1);
        EXPECT_NEAR(left + right, 40.0, 0.4);
        if (knoll_z == 0.0) {
            EXPECT_NEAR(left / 40.0, 0.5, 0.03) << "a centred knoll halves the flow";
        } else {
            EXPECT_LT(left, 0.8 * right) << "the narrow side (left, z > 4) carries less";
            EXPECT_GT(left, 0.1 * 40.0) << "but still some";
        }
        // No net circulation round the island, against the speed integrated round the loop
        // (a circle in open water between the island and both banks: the centred knoll's).
        {
            const auto [gamma, speed] = circulation(r, {0.0, knoll_z}, knoll_z == 0.0 ? 24.0 : 22.0);
            std::printf("knoll: circulation %.3f m^2/s of a speed integral %.1f m^2/s\n", gamma, speed);
            EXPECT_LT(std::abs(gamma), 0.05 * speed) << "circulation " << gamma << " m^2/s, speed integral " << speed;
        }
    }
}

}  // namespace
}  // namespace tidewater
