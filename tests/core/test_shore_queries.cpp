// Shore queries through the SIMD kernel against the scalar double path of the same
// evaluation, on the default island (its waves on the model's grid, and in runs on
// coarser grids): the waterline, the surf zone and dry land, at
// three times. Tolerances: height 0.1 mm, normal 0.05 degrees, and exactly no motion
// on dry land; at most 3% (waterline) and 1% (surf zone) of the points may stall
// unconverged at kinks of the bilinear shore fields. Then determinism across thread counts, and queries while another
// thread bakes.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <thread>

#include "../baked_scene.hpp"
#include "test_helpers.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {
namespace {

const Scene& island() {
    static const Scene scene = [] {
        auto s = test::baked(default_scene());
        EXPECT_TRUE(s.ok()) << (s ? "" : s.error().message);
        return std::move(s).value();
    }();
    return scene;
}

/// The default island with its longer waves in runs on grids of 2 and 4 times the model's
/// texel (4 texels a deep-water wavelength).
const Scene& layered_island() {
    static const Scene scene = [] {
        auto plain = default_scene();
        EXPECT_TRUE(plain.ok());
        plain->shore.texels_per_wavelength = 4.0;
        auto s = test::baked(std::move(plain));
        EXPECT_TRUE(s.ok()) << (s ? "" : s.error().message);
        return std::move(s).value();
    }();
    return scene;
}

/// Some (keep_in_16 in 16) of the texel centres whose shore distance lies in [lo, hi] m, jittered inside the texel.
std::vector<glm::dvec2> band(double lo, double hi, std::size_t count, unsigned keep_in_16) {
    const ShoreWaves& shore = *island().ocean.shore();
    const int n = shore.resolution();
    std::vector<glm::dvec2> pts;
    std::uint64_t h = 12345;
    for (int j = 0; j < n && pts.size() < count; j += 1)
        for (int i = 0; i < n && pts.size() < count; i += 1) {
            const double d = shore.texel_values(i, j).shore_distance();
            h = h * 6364136223846793005ull + 1442695040888963407ull;
            if (d < lo || d > hi || (h >> 60) >= keep_in_16) continue;
            const double jx = static_cast<double>((h >> 20) & 1023) / 1024.0 - 0.5,
                         jz = static_cast<double>((h >> 40) & 1023) / 1024.0 - 0.5;
            pts.push_back(shore.corner() + shore.texel() * glm::dvec2(i + 0.5 + jx, j + 0.5 + jz));
        }
    return pts;
}

struct Band {
    const char* name;
    double lo, hi;
    unsigned keep_in_16;
    double stall_allowance;  ///< share of points allowed to end unconverged
};

TEST(ShoreQuery, SimdMatchesTheDoublePathAtTheWaterlineSurfAndLand) {
    for (const Scene* scene : {&island(), &layered_island()}) {
        const WaterBody& body = scene->ocean;
        ASSERT_TRUE(body.shore() && !body.shore()->trivial());
        std::printf("%zu run(s) of waves\n", body.shore()->layers().size());
        if (scene == &layered_island()) {
            ASSERT_GE(body.shore()->layers().size(), 2u);
        }
        for (const Band& b : {Band{"waterline", -6.0, 6.0, 16, 0.03}, Band{"surf zone", 6.0, 150.0, 1, 0.01},
                              Band{"dry land", -400.0, -6.0, 1, 0.0}}) {
            const std::vector<glm::dvec2> pts = band(b.lo, b.hi, 1500, b.keep_in_16);
            ASSERT_GT(pts.size(), 200u) << b.name;
            for (double t : {0.0, 37.5, 1000.25}) {
                std::vector<SurfacePoint> simd(pts.size());
                ASSERT_TRUE(query_surface(body, t, pts, simd).ok());
                double worst_h = 0.0, worst_n = 0.0;
                int dry = 0, unconverged = 0;
                for (std::size_t i = 0; i < pts.size(); ++i) {
                    const SurfacePoint ref = reference::query_point(body, t, pts[i]);
                    if (!simd[i].converged || !ref.converged) {
                        // Within a texel of the waterline the shore fields have kinks that the
                        // damped Newton step (local waves taken as constant) can stall at.
                        ++unconverged;
                        continue;
                    }
                    worst_h = std::max(worst_h, std::abs(simd[i].height - ref.height));
                    worst_n = std::max(
                        worst_n, std::acos(std::clamp(glm::dot(simd[i].normal, ref.normal), -1.0, 1.0)) * 180.0 / kPi);
                    EXPECT_NEAR(simd[i].depth, ref.depth, 1e-3) << b.name;
                    EXPECT_NEAR(simd[i].shore_distance, ref.shore_distance, 1e-2) << b.name;
                    if (ref.depth < -0.5) {
                        // Every tap around a point this far up the beach is dry: the water rests.
                        ++dry;
                        EXPECT_EQ(simd[i].height, body.level()) << b.name << " point " << i;
                        EXPECT_EQ(glm::length(simd[i].displacement), 0.0);
                        EXPECT_EQ(glm::length(simd[i].velocity), 0.0);
                        EXPECT_EQ(simd[i].normal, glm::dvec3(0.0, 1.0, 0.0));
                    }
                }
                const double stalled = static_cast<double>(unconverged) / static_cast<double>(pts.size());
                std::printf("%s, t = %g s: %zu points, %.1f%% unconverged, worst height %.2e m, normal %.3f deg\n",
                            b.name, t, pts.size(), 100.0 * stalled, worst_h, worst_n);
                EXPECT_LT(worst_h, 1e-4) << b.name << " at t = " << t;
                EXPECT_LT(worst_n, 0.05) << b.name << " at t = " << t;
                EXPECT_LE(stalled, b.stall_allowance) << b.name << " at t = " << t;
                if (std::string(b.name) == "dry land") {
                    EXPECT_GT(dry, 200) << "dry points checked";
                }
            }
        }
    }
}

// Depth and shore distance are properties of the query point: the shore model's grids
// there (level - terrain at texel centres), the same at any time and for any waves;
// `wet` is the surface standing above that terrain. Without a shore model both are
// +infinity and everything is wet.
TEST(ShoreQuery, DepthAndShoreDistanceBelongToTheQueryPoint) {
    const WaterBody& body = island().ocean;
    const ShoreWaves& shore = *body.shore();
    std::vector<glm::dvec2> pts = band(-30.0, 60.0, 2000, 4);
    ASSERT_GT(pts.size(), 500u);
    // Texel centres too, where the grid holds level - terrain exactly.
    const std::size_t jittered = pts.size();
    for (std::size_t k = 0; k < 200; ++k) {
        const glm::dvec2 p = pts[k * 2];
        const glm::dvec2 cell = glm::floor((p - shore.corner()) / shore.texel());
        pts.push_back(shore.corner() + shore.texel() * (cell + 0.5));
    }
    std::vector<LocalWave> local(body.waves().size());
    std::vector<SurfacePoint> first;
    std::size_t wet = 0, dry = 0;
    for (double t : {0.0, 3.3, 17.9}) {
        std::vector<SurfacePoint> out(pts.size());
        ASSERT_TRUE(query_surface(body, t, pts, out).ok());
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const LocalShore at = shore.sample(pts[i], local);
            ASSERT_NEAR(out[i].depth, at.depth, 1e-4) << i;
            ASSERT_NEAR(out[i].shore_distance, at.shore_distance, 1e-3) << i;
            if (i >= jittered) {
                ASSERT_NEAR(out[i].depth, body.level() - island().terrain.height_at(pts[i]), 1e-3) << i;
            }
            ASSERT_EQ(out[i].wet, out[i].height > body.level() - out[i].depth) << i;
            if (!first.empty()) {
                ASSERT_EQ(out[i].depth, first[i].depth) << "depth moved with the waves at " << i;
            }
            (out[i].wet ? wet : dry) += 1;
        }
        if (first.empty()) first = out;
    }
    EXPECT_GT(wet, 100u);
    EXPECT_GT(dry, 100u);

    auto open = body.with_shore(nullptr);
    ASSERT_TRUE(open.ok());
    std::vector<SurfacePoint> out(pts.size());
    ASSERT_TRUE(query_surface(*open, 1.0, pts, out).ok());
    for (const SurfacePoint& p : out) {
        EXPECT_TRUE(std::isinf(p.depth) && p.depth > 0.0);
        EXPECT_TRUE(std::isinf(p.shore_distance) && p.shore_distance > 0.0);
        EXPECT_TRUE(p.wet);
    }
}

std::vector<glm::dvec2> coast_points() {
    std::vector<glm::dvec2> pts(30001);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double a = static_cast<double>(i) * 0.0137, r = 450.0 + 250.0 * std::sin(static_cast<double>(i) * 0.011);
        pts[i] = {r * std::cos(a), r * std::sin(a)};
    }
    return pts;
}

// A point's answer depends on the point alone: one large call (solved in shore-tile
// order) and many small calls of 37 points (caller's order, other batch neighbours)
// give the same bits, heights-only calls included.
TEST(ShoreQuery, BitIdenticalForAnyBatching) {
    const auto pts = coast_points();
    const auto whole = test::surface_on_threads(island().ocean, 55.5, pts, 1);
    std::vector<SurfacePoint> pieces(pts.size());
    std::vector<double> heights(pts.size());
    ASSERT_TRUE(query_heights(island().ocean, 55.5, pts, heights).ok());
    for (std::size_t at = 0; at < pts.size(); at += 37) {
        const std::size_t n = std::min<std::size_t>(37, pts.size() - at);
        ASSERT_TRUE(
            query_surface(island().ocean, 55.5, std::span(pts.data() + at, n), std::span(pieces.data() + at, n)).ok());
    }
    test::expect_bitwise_equal(whole, pieces);
    for (std::size_t i = 0; i < pts.size(); ++i)
        ASSERT_EQ(std::memcmp(&heights[i], &whole[i].height, sizeof(double)), 0)
            << i << " " << heights[i] - whole[i].height << " " << whole[i].iterations;
}

// Near a shore a particle's foam also remembers its crests: the shore fields are fixed in
// time, so its earlier compression is the Lagrangian shore evaluation at earlier times
// (rest = point - displacement), and the foam is the larger of the breaking there and its
// crest foam now plus 0.5-2 s ago, faded by exp(-age / 1 s).
TEST(ShoreQuery, FoamRemembersTheParticlesCrestsNearTheShore) {
    const WaterBody& body = island().ocean;
    const auto pts = band(5.0, 200.0, 4000, 4);
    std::vector<SurfacePoint> out(pts.size());
    const double time = 55.5;
    ASSERT_TRUE(query_surface(body, time, pts, out).ok());
    double worst = 0.0;
    std::size_t remembered = 0, checked = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!out[i].converged || out[i].depth < 1.0) continue;
        const glm::dvec2 rest = pts[i] - out[i].displacement;
        LocalShore local;
        double crest = 0.0;
        for (int lag = 0; lag <= 4; ++lag) {
            const double age = 0.5 * lag;
            const double j =
                evaluate_lagrangian_shore(body.waves(), *body.shore(), rest, body.local_time(time) - age, &local)
                    .jacobian;
            crest += crest_foam(j, body.whitecap_jacobian()) * std::exp(-age / 1.0);
        }
        const double expected = std::max(local.breaking, std::min(crest, 1.0));
        worst = std::max(worst, std::abs(out[i].foam - expected));
        remembered +=
            out[i].foam > std::max(local.breaking, crest_foam(out[i].jacobian, body.whitecap_jacobian())) + 0.1 ? 1 : 0;
        ++checked;
    }
    std::printf("shore foam against the particles' history: worst %.2e over %zu points, %zu with a trail\n", worst,
                checked, remembered);
    EXPECT_GT(checked, pts.size() / 2);
    EXPECT_LT(worst, 5e-3);
    EXPECT_GT(remembered, 0u);
}

TEST(ShoreQuery, BitIdenticalForAnyThreadCount) {
    const auto pts = coast_points();
    const auto one = test::surface_on_threads(island().ocean, 55.5, pts, 1);
    for (unsigned threads : {0u, 2u, 3u, 8u})
        test::expect_bitwise_equal(one, test::surface_on_threads(island().ocean, 55.5, pts, threads));
}

// Two threads query (one open water, one the shore) while a third bakes a shore model:
// one scheduler serves all three, and the answers do not change.
TEST(ShoreQuery, QueriesWhileAnotherThreadBakes) {
    const auto pts = coast_points();
    const auto expected = test::surface_on_threads(island().ocean, 55.5, pts, 1);
    auto open = island().ocean.with_shore(nullptr);
    ASSERT_TRUE(open.ok());
    const auto expected_open = test::surface_on_threads(*open, 55.5, pts, 1);
    std::atomic<bool> baking{true};
    std::atomic<int> shore_rounds{0}, open_rounds{0};
    std::thread baker([&] {
        ShoreWaveOptions options;
        options.resolution = 512;
        options.threads = 0;
        for (int i = 0; i < 2; ++i) {
            auto model = bake_shore_waves(island().ocean.waves(), island().terrain, island().water_level(), options);
            EXPECT_TRUE(model.ok());
        }
        baking = false;
    });
    std::thread shore_queries([&] {
        do {
            test::expect_bitwise_equal(expected, test::surface_on_threads(island().ocean, 55.5, pts, 0));
            ++shore_rounds;
        } while (baking);
    });
    std::thread open_queries([&] {
        do {
            test::expect_bitwise_equal(expected_open, test::surface_on_threads(*open, 55.5, pts, 2));
            ++open_rounds;
        } while (baking);
    });
    baker.join();
    shore_queries.join();
    open_queries.join();
    EXPECT_GE(shore_rounds.load(), 1);
    EXPECT_GE(open_rounds.load(), 1);
}

}  // namespace
}  // namespace tidewater
