// Synthetic recovery: records made by the runtime itself (Eulerian queries for gauges
// and profiles, the Lagrangian map for a buoy) from known waves, with noise and gaps,
// are fitted back within 2% in amplitude and period and 2 degrees in direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/gerstner.hpp"
#include "tidewater/query.hpp"
#include "tidewater/water_body.hpp"

namespace tidewater::calibration {
namespace {

/// Known waves: periods 5-14 s, amplitudes 0.2-0.8 m, sum(Q k A) about 0.3.
std::vector<WaveSpec> known_waves(std::uint64_t seed, int count, bool random_directions) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<WaveSpec> w(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const double period = 5.0 + 9.0 * (i + 0.3 + 0.4 * u(rng)) / count;  // well separated
        const double omega = kTwoPi / period;
        WaveSpec& s = w[static_cast<std::size_t>(i)];
        s.wavelength = kTwoPi * kGravity / (omega * omega);
        s.amplitude = 0.2 + 0.6 * u(rng);
        s.steepness = 0.3 + 0.4 * u(rng);
        s.phase = kTwoPi * u(rng);
        s.direction_deg = random_directions ? 360.0 * u(rng) : 0.0;
    }
    return w;
}

WaterBody body_of(const std::vector<WaveSpec>& waves) {
    WaterProfile p;
    p.waves = waves;
    auto body = WaterBody::create(p, 0.0, "synthetic");
    EXPECT_TRUE(body.ok());
    return std::move(body).value();
}

/// Noise and gaps: 1 cm Gaussian noise, 4% of samples dropped at random and one block.
template <typename Keep>
void degrade(MeasuredRecord& r, std::uint64_t seed, const Keep& keep_extra) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    MeasuredRecord out = r;
    out.axis.clear(), out.z.clear(), out.east.clear(), out.north.clear();
    const std::size_t block = r.size() / 3;
    for (std::size_t k = 0; k < r.size(); ++k) {
        if (u(rng) < 0.04 || (k >= block && k < block + r.size() / 20)) continue;
        out.axis.push_back(r.axis[k]);
        out.z.push_back(r.z[k] + noise(rng));
        if (r.kind == RecordKind::buoy) {
            out.east.push_back(r.east[k] + noise(rng));
            out.north.push_back(r.north[k] + noise(rng));
        }
        keep_extra(k);
    }
    r = std::move(out);
}

void expect_recovered(const std::vector<WaveSpec>& truth, const PhaseFit& fit, bool check_direction) {
    ASSERT_EQ(fit.waves.size(), truth.size());
    for (const WaveSpec& t : truth) {
        const double omega = std::sqrt(kGravity * kTwoPi / t.wavelength);
        const auto it =
            std::min_element(fit.waves.begin(), fit.waves.end(), [&](const FittedWave& a, const FittedWave& b) {
                return std::abs(a.omega - omega) < std::abs(b.omega - omega);
            });
        const double period = kTwoPi / omega;
        EXPECT_NEAR(it->amplitude, t.amplitude, 0.02 * t.amplitude) << "period " << period;
        EXPECT_NEAR(it->period(), period, 0.02 * period);
        if (check_direction) {
            const double d = std::remainder(it->direction_deg - t.direction_deg, 360.0);
            EXPECT_LT(std::abs(d), 2.0) << "period " << period << ": fitted " << it->direction_deg << ", true "
                                        << t.direction_deg;
        }
    }
    EXPECT_GT(fit.r2, 0.99);
}

TEST(SyntheticRecovery, GaugeRecordWithNoiseAndGaps) {
    for (std::uint64_t seed : {3u, 11u}) {
        const auto truth = known_waves(seed, 4, false);
        const WaterBody body = body_of(truth);
        MeasuredRecord r;
        r.kind = RecordKind::gauge;
        r.source = "synthetic gauge";
        const std::vector<glm::dvec2> gauge{{0.0, 0.0}};
        std::vector<SurfacePoint> out(1);
        for (int k = 0; k < 1200; ++k) {
            const double t = 0.5 * k;
            ASSERT_TRUE(query_surface(body, t, gauge, out).ok());
            r.axis.push_back(t);
            r.z.push_back(out[0].height);
        }
        degrade(r, seed, [](std::size_t) {});
        PhaseFitOptions o;
        o.waves = 4;
        auto fit = fit_phase_resolved(r, o);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        std::printf("gauge seed %llu: R^2 %.5f, rmse %.4f m, %d iterations, %.2f s\n",
                    static_cast<unsigned long long>(seed), fit->r2, fit->rmse, fit->iterations, fit->seconds);
        expect_recovered(truth, *fit, false);
    }
}

TEST(SyntheticRecovery, BuoyRecordRecoversDirections) {
    for (std::uint64_t seed : {5u, 17u}) {
        const auto truth = known_waves(seed, 4, true);
        auto set = WaveSet::create(truth, FoldPolicy::reject, "synthetic");
        ASSERT_TRUE(set.ok());
        MeasuredRecord r;
        r.kind = RecordKind::buoy;
        r.source = "synthetic buoy";
        for (int k = 0; k < 1536; ++k) {
            const double t = k / 1.28;
            const LagrangianSample s = evaluate_lagrangian(*set, {0.0, 0.0}, t);
            r.axis.push_back(t);
            r.z.push_back(s.displacement.y);
            r.east.push_back(s.displacement.x);   // runtime x is east
            r.north.push_back(s.displacement.z);  // runtime z is north
        }
        degrade(r, seed, [](std::size_t) {});
        PhaseFitOptions o;
        o.waves = 4;
        auto fit = fit_phase_resolved(r, o);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        std::printf("buoy seed %llu: R^2 %.5f (horizontal %.5f), %d iterations, %.2f s\n",
                    static_cast<unsigned long long>(seed), fit->r2, fit->horizontal_r2, fit->iterations, fit->seconds);
        expect_recovered(truth, *fit, true);
    }
}

TEST(SyntheticRecovery, ProfileRecordAtOneInstant) {
    for (std::uint64_t seed : {7u, 23u}) {
        const auto truth = known_waves(seed, 3, false);
        const WaterBody body = body_of(truth);
        MeasuredRecord r;
        r.kind = RecordKind::profile;
        r.source = "synthetic profile";
        std::vector<glm::dvec2> line;
        for (int k = 0; k < 1500; ++k) line.push_back({0.5 * k, 0.0});
        std::vector<SurfacePoint> out(line.size());
        ASSERT_TRUE(query_surface(body, 0.0, line, out).ok());
        for (std::size_t k = 0; k < line.size(); ++k) {
            r.axis.push_back(line[k].x);
            r.z.push_back(out[k].height);
        }
        degrade(r, seed, [](std::size_t) {});
        PhaseFitOptions o;
        o.waves = 3;
        auto fit = fit_phase_resolved(r, o);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        std::printf("profile seed %llu: R^2 %.5f, %d iterations, %.2f s\n", static_cast<unsigned long long>(seed),
                    fit->r2, fit->iterations, fit->seconds);
        expect_recovered(truth, *fit, false);
    }
}

}  // namespace
}  // namespace tidewater::calibration
