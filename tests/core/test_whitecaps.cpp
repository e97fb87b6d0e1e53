// Whitecap coverage: Monahan's W(U), and the crest foam the queries report covering that
// share of the open sea.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

WaterBody body_from_preset(const std::string& name, double wind = -1.0) {
    auto profile = load_preset(name);
    EXPECT_TRUE(profile.ok()) << (profile.ok() ? "" : profile.error().message);
    WaterProfile p = profile.value();
    if (wind > 0.0) p.spectrum->wind_speed = wind;
    if (wind > 0.0) p.waves = generate_waves(*p.spectrum, name).value();
    auto body = WaterBody::create(p, 0.0, name);
    EXPECT_TRUE(body.ok()) << (body.ok() ? "" : body.error().message);
    return std::move(body).value();
}

// Monahan and O'Muircheartaigh (1980): W = 3.84e-6 U^3.41, "about 1.8% at 12 m/s"; 0.5% at
// 8 m/s, 4.9% at 16 m/s from the same fit by hand.
TEST(Whitecaps, MonahanCoverageMatchesTheFit) {
    EXPECT_NEAR(monahan_whitecap_fraction(12.0), 0.0184, 2e-4);
    EXPECT_NEAR(monahan_whitecap_fraction(8.0), 0.0046, 1e-4);
    EXPECT_NEAR(monahan_whitecap_fraction(16.0), 0.0490, 3e-4);
    EXPECT_EQ(monahan_whitecap_fraction(0.0), 0.0);
    EXPECT_EQ(monahan_whitecap_fraction(200.0), 1.0);
}

// The curve crosses 1/2 at J*, is 0 above J* + (1 - J*)/4 and 1 below J* - (1 - J*)/4.
TEST(Whitecaps, CrestFoamTurnsOnAcrossTheWhitecapJacobian) {
    for (double star : {0.55, 0.8, 0.95}) {
        const double half = 0.25 * (1.0 - star);
        EXPECT_NEAR(crest_foam(star, star), 0.5, 1e-12);
        EXPECT_EQ(crest_foam(star + half + 1e-9, star), 0.0);
        EXPECT_EQ(crest_foam(star - half - 1e-9, star), 1.0);
        EXPECT_LT(crest_foam(star + 0.5 * half, star), 0.5);
        EXPECT_GT(crest_foam(star - 0.5 * half, star), 0.5);
    }
}

// The share of the drawn open sea the queries report as foam (>= 1/2), on an Eulerian grid
// over four of the longest waves at six instants: an estimate independent of the
// Lagrangian sample J* was set from. Within 15% of Monahan's W for the preset's 12 m/s
// wind and for the same spectrum under 8 and 16 m/s.
TEST(Whitecaps, OpenSeaFoamCoversMonahansShare) {
    for (double wind : {-1.0, 8.0, 16.0}) {
        const WaterBody body = body_from_preset("ocean_rolling", wind);
        const double u = body.profile().spectrum->wind_speed;
        const double expected = monahan_whitecap_fraction(u);
        double longest = 0.0;
        for (const Wave& w : body.waves().waves()) longest = std::max(longest, 2.0 * kPi / w.k);
        const int n = 256;
        std::vector<glm::dvec2> points;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                points.emplace_back((i + 0.5) * 4.0 * longest / n, (j + 0.5) * 4.0 * longest / n);
        std::vector<SurfacePoint> out(points.size());
        std::size_t foamy = 0, total = 0;
        for (int t = 0; t < 6; ++t) {
            ASSERT_TRUE(query_surface(body, 3.7 * t, points, out).ok());
            for (const SurfacePoint& p : out) foamy += p.foam >= 0.5 ? 1 : 0;
            total += out.size();
        }
        const double coverage = static_cast<double>(foamy) / static_cast<double>(total);
        EXPECT_NEAR(coverage / expected, 1.0, 0.15) << "U = " << u << " m/s: J* = " << body.whitecap_jacobian();
        // A stronger wind sets J* higher: more of the sea is past it.
        EXPECT_LT(body.whitecap_jacobian(), 1.0);
        EXPECT_GT(body.whitecap_jacobian(), 0.0);
    }
    EXPECT_LT(body_from_preset("ocean_rolling", 8.0).whitecap_jacobian(),
              body_from_preset("ocean_rolling", 16.0).whitecap_jacobian());
}

// The foam a particle reports is its crest foam now plus what its compression 0.5, 1, 1.5
// and 2 s ago left, faded by exp(-age / 1 s), capped at 1. The reference: the Lagrangian
// evaluation of the same particle (rest = point - displacement) at those earlier times,
// an evaluation of its own that shares none of the query's lag sums. Behind the crests
// (foam well above the fresh crest foam) this is the trail the whitecaps leave.
TEST(Whitecaps, AParticleKeepsTheFoamItsCrestMadeFadingOverTime) {
    const WaterBody body = body_from_preset("ocean_rolling");
    const double star = body.whitecap_jacobian();
    double longest = 0.0;
    for (const Wave& w : body.waves().waves()) longest = std::max(longest, 2.0 * kPi / w.k);
    std::vector<glm::dvec2> points;
    for (int i = 0; i < 160; ++i)
        for (int j = 0; j < 160; ++j)
            points.emplace_back((i + 0.5) * 2.0 * longest / 160, (j + 0.5) * 2.0 * longest / 160);
    const double time = 21.3;
    std::vector<SurfacePoint> out(points.size());
    ASSERT_TRUE(query_surface(body, time, points, out).ok());
    double worst = 0.0;
    std::size_t trailing = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec2 rest = points[i] - out[i].displacement;
        double expected = 0.0;
        for (int lag = 0; lag <= 4; ++lag) {
            const double age = 0.5 * lag;
            const double j = evaluate_lagrangian(body.waves(), rest, body.local_time(time) - age).jacobian;
            expected += crest_foam(j, star) * std::exp(-age / 1.0);
        }
        expected = std::min(expected, 1.0);
        worst = std::max(worst, std::abs(out[i].foam - expected));
        trailing += out[i].foam > crest_foam(out[i].jacobian, star) + 0.1 ? 1 : 0;
    }
    std::printf("foam against the particle's own history: worst %.2e; %zu of %zu points carry a trail\n", worst,
                trailing, points.size());
    EXPECT_LT(worst, 2e-3);
    EXPECT_GT(trailing, points.size() / 200);  // the trails are there to compare (0.5% of the sea at least)
}

// Waves authored one by one carry no wind: the default J*. A set with no waves is flat.
TEST(Whitecaps, BodiesWithoutAWindUseTheDefault) {
    const WaterBody authored = test::make_body({{0.0, 40.0, 0.5, 0.8, 0.0}});
    EXPECT_EQ(authored.whitecap_jacobian(), kDefaultWhitecapJacobian);
    EXPECT_EQ(whitecap_jacobian(WaveSet{}, 0.02), 1.0);
    // The same set gives the same J* every time (a seeded sample).
    const WaterBody a = body_from_preset("ocean_rolling"), b = body_from_preset("ocean_rolling");
    EXPECT_EQ(a.whitecap_jacobian(), b.whitecap_jacobian());
}

}  // namespace
}  // namespace tidewater
