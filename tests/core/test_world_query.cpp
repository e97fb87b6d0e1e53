// Queries of a world of water bodies: which body a point is in, a river's falling
// surface with waves that ride its current, a lake at its level feeling its beaches,
// no step where a river meets the sea, the SIMD kernel against the double reference,
// and drift along the current against the streamline's travel time.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <memory>

#include "../bowl_terrain.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/drift.hpp"
#include "tidewater/floating_body.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

std::shared_ptr<const Scene> bake_or_die(const Scene& scene) {
    auto baked = bake_scene(scene);
    if (!baked) ADD_FAILURE() << baked.error().message;
    return baked ? std::move(baked).value() : std::make_shared<const Scene>(scene);
}

std::shared_ptr<const Scene> bake_json(const std::string& json) {
    auto scene = parse_scene(json, "world-test.json");
    if (!scene) {
        ADD_FAILURE() << scene.error().message;
        return std::make_shared<const Scene>();
    }
    return bake_or_die(*scene);
}

/// A straight river on a plane falling 4 m per km toward the sea (the coast at x = 2500),
/// with one wave running downstream so that its speed over the ground can be measured.
const char* kReach = R"({
  "version": 1, "name": "reach", "water_level": 0.0,
  "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } },
  "ocean": "ocean_rolling",
  "shore": { "enabled": false },
  "rivers": [ { "name": "reach", "path": [[-2000, 30], [2900, 30]], "width": 24, "discharge": 40.0, "manning": 0.03,
                "preset": { "name": "one_wave",
                            "waves": [ { "direction": 0.0, "wavelength": 3.6, "amplitude": 0.03, "steepness": 0.5 } ] } } ]
})";

const detail::RiverBake& river_of(const Scene& scene, std::size_t r) {
    return scene.bake->bodies->rivers[r];
}

TEST(WorldQuery, FindsTheBodyOfEveryPoint) {
    const auto scene = bake_json(kReach);
    const WorldPoint river = query_world_point(*scene, 3.0, {0.0, 30.0});
    EXPECT_EQ(river.body, (BodyRef{BodyKind::river, 0}));
    EXPECT_EQ(body_name(*scene, river.body), "reach");
    EXPECT_GT(river.flow.x, 0.3) << "downstream is +x";
    EXPECT_LT(std::abs(river.flow.y), 0.05 * river.flow.x);
    const WorldPoint sea = query_world_point(*scene, 3.0, {2800.0, -300.0});
    EXPECT_EQ(sea.body.kind, BodyKind::ocean);
    EXPECT_EQ(body_name(*scene, sea.body), "ocean");
    EXPECT_EQ(sea.flow, glm::dvec2(0.0));
    const WorldPoint land = query_world_point(*scene, 3.0, {0.0, 200.0});
    EXPECT_EQ(land.body.kind, BodyKind::none);
    EXPECT_EQ(body_name(*scene, land.body), "");
    EXPECT_FALSE(land.surface.wet);
    // Just past the mouth the river's plume still carries it, fading out.
    const glm::dvec2 mouth = river_of(*scene, 0).centreline.back();
    const WorldPoint plume = query_world_point(*scene, 3.0, mouth + glm::dvec2(10.0, 0.0));
    EXPECT_EQ(plume.body.kind, BodyKind::ocean);
    EXPECT_GT(plume.flow.x, 0.1);
    const WorldPoint far = query_world_point(*scene, 3.0, mouth + glm::dvec2(600.0, 0.0));
    EXPECT_EQ(far.flow, glm::dvec2(0.0));
}

// A point in space is under a body's surface by how far its surface stands above it: in
// the river, in the sea, and never over land, wherever the point is.
TEST(WorldQuery, SubmersionIsHowFarTheSurfaceStandsAbove) {
    const auto scene = bake_json(kReach);
    const glm::dvec2 river{0.0, 30.0}, sea{2800.0, -300.0}, land{0.0, 200.0};
    const double river_surface = query_world_point(*scene, 3.0, river).surface.height;
    const double sea_surface = query_world_point(*scene, 3.0, sea).surface.height;
    const std::vector<glm::dvec3> points{{river.x, river_surface - 0.4, river.y},
                                         {river.x, river_surface + 0.1, river.y},
                                         {sea.x, sea_surface - 3.0, sea.y},
                                         {sea.x, sea_surface + 2.0, sea.y},
                                         {land.x, -50.0, land.y}};
    std::vector<Submersion> out(points.size());
    ASSERT_TRUE(query_submersion(*scene, 3.0, points, out).ok());
    EXPECT_TRUE(out[0].under);
    EXPECT_EQ(out[0].body, (BodyRef{BodyKind::river, 0}));
    EXPECT_NEAR(out[0].depth, 0.4, 1e-9);
    EXPECT_FALSE(out[1].under);
    EXPECT_NEAR(out[1].depth, -0.1, 1e-9);
    EXPECT_TRUE(out[2].under);
    EXPECT_EQ(out[2].body.kind, BodyKind::ocean);
    EXPECT_NEAR(out[2].depth, 3.0, 1e-9);
    EXPECT_FALSE(out[3].under);
    EXPECT_FALSE(out[4].under) << "under the ground, not under water";
    EXPECT_EQ(out[4].body.kind, BodyKind::none);
    std::vector<Submersion> short_out(2);
    EXPECT_FALSE(query_submersion(*scene, 3.0, points, short_out).ok());
}

TEST(WorldQuery, RiverSurfaceFallsUnderItsWaves) {
    const auto scene = bake_json(kReach);
    const detail::RiverBake& r = river_of(*scene, 0);
    for (const double x : {-1500.0, -500.0, 800.0, 2000.0}) {
        const glm::dvec2 p{x, 30.0};
        const double still = r.grid.sample(r.surface_height, p);
        double sum = 0.0, lo = 1e9, hi = -1e9;
        const int n = 64;
        for (int k = 0; k < n; ++k) {
            const WorldPoint w = query_world_point(*scene, 0.37 * k, p);
            ASSERT_TRUE(w.surface.converged);
            sum += w.surface.height;
            lo = std::min(lo, w.surface.height);
            hi = std::max(hi, w.surface.height);
            // The still water column is the baked one under the falling surface.
            EXPECT_NEAR(w.surface.depth, r.grid.sample(r.depth, p), 1e-9);
            EXPECT_TRUE(w.surface.wet);
        }
        EXPECT_NEAR(sum / n, still, 0.01) << "x = " << x;
        EXPECT_GT(hi - lo, 0.03) << "the river's wave is there";
        EXPECT_LT(hi - lo, 0.07) << "and no more than its height";
    }
    // The surface falls from source to mouth (0.004 per m).
    EXPECT_GT(query_world_point(*scene, 0.0, {-1500.0, 30.0}).surface.height,
              query_world_point(*scene, 0.0, {1500.0, 30.0}).surface.height + 10.0);
}

TEST(WorldQuery, RiverWavesRideTheCurrent) {
    const auto scene = bake_json(kReach);
    const detail::RiverBake& r = river_of(*scene, 0);
    const double speed = r.mean_speed;
    ASSERT_GT(speed, 0.3);
    const double k = kTwoPi / 3.6, c0 = std::sqrt(kGravity / k);
    const double dt = 0.2;
    // The wave pattern moves downstream at c0 + U: the surface at p a moment later is the
    // surface upstream by (c0 + U) dt now. Heights are relative to the still surface.
    auto eta = [&](glm::dvec2 p, double t) {
        return query_world_point(*scene, t, p).surface.height - r.grid.sample(r.surface_height, p);
    };
    double worst = 0.0, worst_without_current = 0.0;
    for (int m = 0; m < 24; ++m) {
        const glm::dvec2 p{-600.0 + 0.31 * m, 30.0};
        const double t = 1.3 + 0.17 * m;
        const double later = eta(p, t + dt);
        worst = std::max(worst, std::abs(later - eta(p - glm::dvec2((c0 + speed) * dt, 0.0), t)));
        worst_without_current = std::max(worst_without_current, std::abs(later - eta(p - glm::dvec2(c0 * dt, 0.0), t)));
    }
    EXPECT_LT(worst, 1e-3) << "m";
    EXPECT_GT(worst_without_current, 0.01) << "waves that ignored the current would be this far off";
}

TEST(WorldQuery, NoStepWhereTheRiverMeetsTheSea) {
    const auto scene = bake_json(kReach);
    const detail::RiverBake& r = river_of(*scene, 0);
    // Walk down the centreline to where the river's water turns into the sea's.
    for (const double across : {0.0, -5.0, 6.0}) {
        glm::dvec2 a = r.centreline.back() + glm::dvec2(-40.0, across),
                   b = r.centreline.back() + glm::dvec2(60.0, across);
        ASSERT_EQ(query_world_point(*scene, 0.0, a).body.kind, BodyKind::river);
        ASSERT_EQ(query_world_point(*scene, 0.0, b).body.kind, BodyKind::ocean);
        for (int it = 0; it < 40; ++it) {
            const glm::dvec2 mid = 0.5 * (a + b);
            (query_world_point(*scene, 0.0, mid).body.kind == BodyKind::river ? a : b) = mid;
        }
        for (const double t : {0.0, 1.7, 4.1, 9.3}) {
            const WorldPoint up = query_world_point(*scene, t, a - glm::dvec2(5e-4, 0.0));
            const WorldPoint down = query_world_point(*scene, t, b + glm::dvec2(5e-4, 0.0));
            ASSERT_EQ(up.body.kind, BodyKind::river);
            ASSERT_EQ(down.body.kind, BodyKind::ocean);
            EXPECT_LT(std::abs(up.surface.height - down.surface.height), 1e-3) << "across " << across << ", t " << t;
            EXPECT_LT(glm::length(up.flow - down.flow), 1e-3) << "the current is continuous";
        }
    }
}

TEST(WorldQuery, KernelMatchesTheDoubleReference) {
    const auto scene = bake_json(kReach);
    std::vector<glm::dvec2> points;
    const glm::dvec2 mouth = river_of(*scene, 0).centreline.back();
    for (int k = 0; k < 300; ++k) {
        const double f = k / 299.0;
        points.push_back({-1800.0 + 4600.0 * f, 30.0 + 11.0 * std::sin(7.0 * f)});  // river, then plume and sea
        points.push_back(mouth + glm::dvec2(-30.0 + 150.0 * f, 20.0 * std::cos(9.0 * f)));
    }
    std::vector<WorldPoint> fast(points.size());
    ASSERT_TRUE(query_world(*scene, 12.5, points, fast, {.threads = 2}));
    double worst_height = 0.0, worst_velocity = 0.0;
    std::size_t rivers = 0, plumes = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const WorldPoint ref = reference::query_world_point(*scene, 12.5, points[i]);
        ASSERT_EQ(ref.body, fast[i].body) << i;
        worst_height = std::max(worst_height, std::abs(ref.surface.height - fast[i].surface.height));
        worst_velocity = std::max(worst_velocity, glm::length(ref.surface.velocity - fast[i].surface.velocity));
        rivers += fast[i].body.kind == BodyKind::river;
        plumes += fast[i].body.kind == BodyKind::ocean && fast[i].flow != glm::dvec2(0.0);
    }
    EXPECT_GT(rivers, 100u);
    EXPECT_GT(plumes, 20u);
    EXPECT_LT(worst_height, 1e-4) << "m";
    EXPECT_LT(worst_velocity, 1e-3) << "m/s";
}

TEST(WorldQuery, LakeSitsAtItsLevelAndFeelsItsBeaches) {
    auto parsed = test::bowl_lake_scene();
    ASSERT_TRUE(parsed) << parsed.error().message;
    const auto scene = bake_or_die(*parsed);
    ASSERT_TRUE(scene->lakes[0].body.shore()) << "the lake has its own shore model";
    auto spread = [&](glm::dvec2 p) {
        double lo = 1e9, hi = -1e9, sum = 0.0;
        for (int k = 0; k < 48; ++k) {
            const WorldPoint w = query_world_point(*scene, 0.41 * k, p);
            EXPECT_EQ(w.body, (BodyRef{BodyKind::lake, 0}));
            lo = std::min(lo, w.surface.height);
            hi = std::max(hi, w.surface.height);
            sum += w.surface.height;
        }
        EXPECT_NEAR(sum / 48.0, 30.0, 0.02);
        return hi - lo;
    };
    // Radius of the waterline: about 245 m. Toward it the waves are held under the breaking
    // cap (0.78 of the depth, the ripples' 2 cm besides) and die out on the beach.
    const double centre = spread({0.0, 0.0});
    EXPECT_GT(centre, 0.02);
    double last = centre;
    for (double x : {243.0, 244.5, 244.8}) {
        const double depth = query_world_point(*scene, 0.0, {x, 0.0}).surface.depth;
        const double beach = spread({x, 0.0});
        EXPECT_LT(beach, 0.78 * depth + 0.02) << "at x = " << x << " m, " << depth << " m of water";
        EXPECT_LT(beach, last) << "at x = " << x << " m";
        last = beach;
    }
    EXPECT_LT(last, 0.35 * centre);
    const WorldPoint land = query_world_point(*scene, 0.0, {260.0, 0.0});
    EXPECT_EQ(land.body.kind, BodyKind::none);
    EXPECT_NEAR(land.surface.height, scene->terrain.height_at({260.0, 0.0}), 1e-9)
        << "an inland scene's land is its terrain";
    EXPECT_FALSE(land.surface.wet);
}

TEST(WorldQuery, AFloatingBodyRidesTheRiverAndFeelsItsCurrent) {
    const auto scene = bake_json(kReach);
    FloatingBody barrel = FloatingBody::four_point(1.0, 1.0);
    barrel.position = {0.0, 30.0};
    auto att = hull_attitude(*scene, barrel, 4.0);
    ASSERT_TRUE(att) << att.error().message;
    const WorldPoint under = query_world_point(*scene, 4.0, barrel.position);
    EXPECT_NEAR(att->heave, under.surface.height, 0.06) << "it floats on the river's surface, not the sea's";
    EXPECT_NEAR(att->current.x, under.flow.x, 0.02);
    EXPECT_GT(att->current.x, 0.3);
    barrel.position = {2800.0, -300.0};
    att = hull_attitude(*scene, barrel, 4.0);
    ASSERT_TRUE(att);
    EXPECT_EQ(att->current, glm::dvec2(0.0)) << "no current in the open sea";
}

TEST(WorldQuery, RefusesAnUnbakedSceneWithBodies) {
    auto parsed = parse_scene(kReach, "reach.json");
    ASSERT_TRUE(parsed);
    std::vector<glm::dvec2> points{{0.0, 30.0}};
    std::vector<WorldPoint> out(1);
    const Status st = query_world(*parsed, 0.0, points, out);
    ASSERT_FALSE(st);
    EXPECT_NE(st.error().message.find("bake_scene"), std::string::npos) << st.error().message;
    std::vector<WorldPoint> too_small;
    EXPECT_FALSE(query_world(*bake_json(kReach), 0.0, points, too_small));
}

/// The time a tracer takes between gates x = a and x = b (linear between samples).
double crossing_time(const std::vector<DriftSample>& track, double gate) {
    for (std::size_t k = 1; k < track.size(); ++k) {
        const double x0 = track[k - 1].position.x, x1 = track[k].position.x;
        if (x0 < gate && x1 >= gate)
            return track[k - 1].time + (gate - x0) / (x1 - x0) * (track[k].time - track[k - 1].time);
    }
    return std::nan("");
}

TEST(WorldQuery, DriftTakesTheStreamlinesTravelTime) {
    auto parsed = parse_scene(R"({
      "version": 1, "name": "bends", "water_level": 0.0,
      "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } },
      "ocean": "ocean_rolling", "shore": { "enabled": false },
      "rivers": [ { "name": "bends", "path": [[-1500, 0], [-900, 120], [-300, -60], [400, 0], [2300, 0]],
                    "width": [20, 30, 16, 24, 24], "discharge": 30.0 } ] })",
                              "bends.json");
    ASSERT_TRUE(parsed);
    const auto scene = bake_or_die(*parsed);
    const glm::dvec2 start{-1400.0, 0.0 + 120.0 * (100.0 / 600.0)};
    const double gate_a = -1200.0, gate_b = -100.0;
    // The streamline's travel time by arc length: midpoint steps of 5 cm along the current.
    double expected = 0.0;
    {
        glm::dvec2 p = start;
        const double ds = 0.05;
        bool counting = false;
        for (int k = 0; k < 4000000 && p.x < gate_b; ++k) {
            const glm::dvec2 v0 = current_at(*scene, p);
            const glm::dvec2 mid = p + 0.5 * ds * v0 / glm::length(v0);
            const glm::dvec2 v = current_at(*scene, mid);
            const glm::dvec2 next = p + ds * v / glm::length(v);
            if (!counting && next.x >= gate_a) counting = true;
            if (counting) {
                // The parts of the step inside the gates.
                const double from = std::max(p.x, gate_a), to = std::min(next.x, gate_b);
                if (to > from) expected += (to - from) / (next.x - p.x) * ds / glm::length(v);
            }
            p = next;
        }
    }
    ASSERT_GT(expected, 100.0);
    double times[3];
    const double steps[3] = {1.0 / 30.0, 1.0 / 60.0, 1.0 / 144.0};
    for (int s = 0; s < 3; ++s) {
        auto track = drift(*scene, start, {.start_time = 0.0, .duration = 2.0 * expected, .dt = steps[s]});
        ASSERT_TRUE(track) << track.error().message;
        times[s] = crossing_time(*track, gate_b) - crossing_time(*track, gate_a);
        EXPECT_NEAR(times[s] / expected, 1.0, 0.02) << "dt " << steps[s];
        EXPECT_EQ(body_name(*scene, track->front().body), "bends");
    }
    EXPECT_NEAR(times[0] / times[2], 1.0, 0.01);
    EXPECT_NEAR(times[1] / times[2], 1.0, 0.01);
}

TEST(WorldQuery, DriftRefusesBadInput) {
    const auto scene = bake_json(kReach);
    EXPECT_FALSE(drift(*scene, {0.0, 400.0}, {}));  // on land
    EXPECT_FALSE(drift(*scene, {0.0, 30.0}, {.duration = -1.0}));
    EXPECT_FALSE(drift(*scene, {0.0, 30.0}, {.duration = 10.0, .dt = 0.0}));
    EXPECT_FALSE(drift(*scene, {std::nan(""), 30.0}, {}));
}

}  // namespace
}  // namespace tidewater
