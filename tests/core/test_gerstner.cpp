// Lagrangian Gerstner evaluation: analytic derivatives against finite
// differences, and phase accuracy at large times.
#include <cmath>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

using test::make_body;
using test::random_waves;

glm::dvec3 position(const WaveSet& set, glm::dvec2 rest, double t) {
    const LagrangianSample s = evaluate_lagrangian(set, rest, t);
    return glm::dvec3(rest.x, 0.0, rest.y) + s.displacement;
}

// Normal, Jacobian determinant and velocity against central differences
// (step 1e-5 m / 1e-5 s; tolerance 1e-6, the O(h^2) error plus rounding).
TEST(Gerstner, AnalyticDerivativesMatchFiniteDifferences) {
    const WaterBody body = make_body(random_waves(16, 0.9, 21));
    const WaveSet& set = body.waves();
    const double h = 1e-5;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec2 rest{i * 0.917 - 120.0, i * -0.53 + 33.0};
        const double t = 0.1 * i;
        const LagrangianSample s = evaluate_lagrangian(set, rest, t);
        const glm::dvec3 tx =
            (position(set, rest + glm::dvec2(h, 0), t) - position(set, rest - glm::dvec2(h, 0), t)) / (2 * h);
        const glm::dvec3 tz =
            (position(set, rest + glm::dvec2(0, h), t) - position(set, rest - glm::dvec2(0, h), t)) / (2 * h);
        const glm::dvec3 n = glm::normalize(glm::cross(tz, tx));
        EXPECT_NEAR(glm::length(n - s.normal), 0.0, 1e-6) << i;
        EXPECT_NEAR(tx.x * tz.z - tx.z * tz.x, s.jacobian, 1e-6) << i;
        EXPECT_NEAR(tx.y, s.slope.x, 1e-6) << i;
        EXPECT_NEAR(tz.y, s.slope.y, 1e-6) << i;
        const glm::dvec3 v = (position(set, rest, t + h) - position(set, rest, t - h)) / (2 * h);
        EXPECT_NEAR(glm::length(v - s.velocity), 0.0, 1e-5) << i;
    }
}

// The horizontal map never folds on a fold-free set: the Jacobian stays >= 1 - sum(QkA).
TEST(Gerstner, JacobianBoundedByFoldMeasure) {
    const WaterBody body = make_body(random_waves(32, 0.95, 8));
    double lowest = 1.0;
    for (int i = 0; i < 20000; ++i) {
        lowest = std::min(lowest, evaluate_lagrangian(body.waves(), {i * 0.05, i * 0.031}, 3.0).jacobian);
    }
    EXPECT_GE(lowest, (1.0 - 0.95) * (1.0 - 0.95) - 1e-12);  // det >= (1 - sum)^2 for the 2x2 map
    EXPECT_LT(lowest, 0.9);                                  // and the steep set does compress the surface somewhere
}

// At t = 1e6 s the phase is as accurate as at t = 10 s: compare against a
// long double evaluation within 1e-8 m (Lagrangian; double rounding of omega*t is
// ~5e-9 rad at 4e7 s) and 2e-6 m (float query kernel).
TEST(Gerstner, LargeTimeKeepsPhaseAccuracy) {
    const double lambda = 37.0, a = 0.8;
    const WaterBody body = make_body({{0.0, lambda, a, 0.0, 0.25}});
    const long double k = 2.0L * 3.14159265358979323846264338327950288L / lambda;
    const long double omega = std::sqrt(static_cast<long double>(kGravity) * k);
    for (double t : {10.0, 1e6, 1e6 + 0.37, 3.7e7}) {
        for (double x : {0.0, 11.0, 1234.5}) {
            const long double theta = std::fmod(k * x - omega * static_cast<long double>(t) + 0.25L,
                                                2.0L * 3.14159265358979323846264338327950288L);
            const double expected = static_cast<double>(a * std::sin(theta));
            EXPECT_NEAR(evaluate_lagrangian(body.waves(), {x, 0.0}, t).displacement.y, expected, 1e-8) << t;
            EXPECT_NEAR(query_point(body, t, {x, 0.0}).height, expected, 2e-6) << t;
        }
    }
}

TEST(Gerstner, WrapAngleStaysInRange) {
    for (double v : {-1e9, -7.0, -kPi, 0.0, kPi, 7.0, 1e9}) {
        const double w = wrap_angle(v);
        EXPECT_GE(w, -kPi);
        EXPECT_LT(w, kPi);
        EXPECT_NEAR(std::remainder(w - v, kTwoPi), 0.0, 1e-6);
    }
}

}  // namespace
}  // namespace tidewater
