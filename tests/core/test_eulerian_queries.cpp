// Eulerian queries against theory: dispersion, trochoid shape, convergence
// on steep seas, determinism. Tolerances are stated next to each check.
#include <cmath>
#include <cstring>

#include "kernel/kernel_waves.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/reference.hpp"

namespace tidewater {
namespace {

using test::expect_bitwise_equal;
using test::make_body;
using test::random_waves;
using test::surface_on_threads;

/// An independent yardstick: the rest position whose particle lands on `point`, found
/// by Newton with backtracking on the forward (Lagrangian) map to 1e-12 m.
glm::dvec2 exact_rest_position(const WaveSet& set, double t, glm::dvec2 point) {
    auto residual = [&](glm::dvec2 x0, LagrangianSample& s) {
        s = evaluate_lagrangian(set, x0, t);
        return x0 + glm::dvec2(s.displacement.x, s.displacement.z) - point;
    };
    glm::dvec2 x0 = point;
    LagrangianSample s;
    glm::dvec2 f = residual(x0, s);
    for (int it = 0; it < 200 && glm::length(f) > 1e-12; ++it) {
        const double det = s.jxx * s.jzz - s.jxz * s.jxz;
        const glm::dvec2 step{-(s.jzz * f.x - s.jxz * f.y) / det, -(s.jxx * f.y - s.jxz * f.x) / det};
        double scale = 1.0;
        for (int b = 0; b < 30; ++b, scale *= 0.5) {
            LagrangianSample trial;
            const glm::dvec2 fc = residual(x0 + scale * step, trial);
            if (glm::length(fc) < glm::length(f) || b == 29) {
                x0 += scale * step;
                f = fc;
                s = trial;
                break;
            }
        }
    }
    return x0;
}

// Period of a single deep-water wave from zero up-crossings of the queried height
// at a fixed point: T = sqrt(2*pi*lambda/g) within 0.1%.
TEST(EulerianQuery, SingleWavePeriodMatchesDeepWaterDispersion) {
    for (double lambda : {5.0, 20.0, 150.0}) {
        const WaterBody body = make_body({{30.0, lambda, 0.05 * lambda / (2 * kPi), 0.8, 0.3}});
        const double expected = std::sqrt(kTwoPi * lambda / kGravity);
        const double dt = expected / 2000.0;
        std::vector<double> crossings;
        double prev = query_point(body, 0.0, {3.0, -7.0}).height;
        for (int i = 1; i < 2000 * 12; ++i) {
            const double h = query_point(body, i * dt, {3.0, -7.0}).height;
            if (prev < 0.0 && h >= 0.0) crossings.push_back((i - 1) * dt + dt * prev / (prev - h));
            prev = h;
        }
        ASSERT_GE(crossings.size(), 10u);
        const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
        EXPECT_NEAR(measured / expected, 1.0, 1e-3) << "lambda " << lambda;
    }
}

// Crest at +A and trough at -A within 1 mm (sampled every 2 mm along one wavelength).
TEST(EulerianQuery, CrestAndTroughReachAmplitude) {
    const double lambda = 20.0, a = 1.2;
    const WaterBody body = make_body({{0.0, lambda, a, 0.6, 0.0}});
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 10000; ++i) pts.push_back({lambda * i / 10000.0, 0.0});
    std::vector<double> h(pts.size());
    ASSERT_TRUE(query_heights(body, 1.7, pts, h).ok());
    EXPECT_NEAR(*std::max_element(h.begin(), h.end()), a, 1e-3);
    EXPECT_NEAR(*std::min_element(h.begin(), h.end()), -a, 1e-3);
}

/// Exact trochoid inversion by bisection: x = x0 + Q*A*cos(theta) is increasing in x0.
double trochoid_height(double x, double k, double a, double q, double omega, double t, double phase) {
    double lo = x - q * a - 1e-9, hi = x + q * a + 1e-9;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        const double xm = mid + q * a * std::cos(k * mid - omega * t + phase);
        (xm < x ? lo : hi) = mid;
    }
    const double x0 = 0.5 * (lo + hi);
    return a * std::sin(k * x0 - omega * t + phase);
}

// The queried profile equals the exact trochoid within 1 mm at Q = 0.9 (k*A = 1, so Q*k*A = 0.9).
TEST(EulerianQuery, ProfileMatchesExactTrochoidAtSteepness09) {
    const double lambda = 31.4, k = kTwoPi / lambda, a = 1.0 / k, q = 0.9, phase = 0.4;
    const WaterBody body = make_body({{0.0, lambda, a, q, phase}});
    const double omega = std::sqrt(kGravity * k);
    for (double t : {0.0, 3.3, 1000.7}) {
        std::vector<glm::dvec2> pts;
        for (int i = 0; i <= 4000; ++i) pts.push_back({-lambda + 2.0 * lambda * i / 4000.0, 12.5});
        std::vector<SurfacePoint> out(pts.size());
        ASSERT_TRUE(query_surface(body, t, pts, out).ok());
        double worst = 0.0;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            ASSERT_TRUE(out[i].converged);
            worst = std::max(worst, std::abs(out[i].height - trochoid_height(pts[i].x, k, a, q, omega, t, phase)));
        }
        EXPECT_LT(worst, 1e-3) << "t = " << t;
    }
}

// For random fold-free sets up to sum(QkA) = 0.95, every query converges and the rest
// position it reports maps forward onto the query point (checked in double with the
// Lagrangian evaluator): residual < 0.1 mm and height error < 1 mm.
TEST(EulerianQuery, ConvergesOnSteepSetsUpToFoldMeasure095) {
    for (int n : {1, 2, 8, 32, 64}) {
        for (double fold : {0.5, 0.8, 0.95}) {
            for (std::uint64_t seed : {1u, 2u, 3u}) {
                const WaterBody body = make_body(random_waves(n, fold, seed * 100 + static_cast<std::uint64_t>(n)));
                ASSERT_NEAR(body.waves().fold_measure(), fold, 1e-9);
                std::mt19937_64 rng(seed);
                std::vector<glm::dvec2> pts(1500);
                for (auto& p : pts)
                    p = {static_cast<double>(rng() % 200000) * 0.01 - 1000.0,
                         static_cast<double>(rng() % 200000) * 0.01 - 1000.0};
                const double t = 17.25 * static_cast<double>(seed);
                std::vector<SurfacePoint> out(pts.size());
                ASSERT_TRUE(query_surface(body, t, pts, out).ok());
                double worst_residual = 0.0, worst_height = 0.0;
                for (std::size_t i = 0; i < pts.size(); ++i) {
                    ASSERT_TRUE(out[i].converged) << n << " waves, fold " << fold << ", point " << i;
                    const glm::dvec2 rest = pts[i] - out[i].displacement;
                    const LagrangianSample s = evaluate_lagrangian(body.waves(), rest, t);
                    const glm::dvec2 landed = rest + glm::dvec2(s.displacement.x, s.displacement.z);
                    worst_residual = std::max(worst_residual, glm::length(landed - pts[i]));
                    // Height at the exact rest position (double Newton with backtracking).
                    const glm::dvec2 exact = exact_rest_position(body.waves(), t, pts[i]);
                    const double exact_h = evaluate_lagrangian(body.waves(), exact, t).displacement.y;
                    worst_height = std::max(worst_height, std::abs(out[i].height - exact_h));
                }
                EXPECT_LT(worst_residual, 1e-4) << n << " waves, fold " << fold;
                EXPECT_LT(worst_height, 1e-3) << n << " waves, fold " << fold;
            }
        }
    }
}

// The fixed-point reference loop is measurably worse on steep seas (why it is replaced).
TEST(EulerianQuery, FixedPointReferenceIsLessAccurateOnSteepSeas) {
    const WaterBody body = make_body(random_waves(16, 0.9, 77));
    double worst_ref = 0.0, worst_newton = 0.0;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec2 p{i * 0.37, i * -0.21};
        const glm::dvec2 exact = exact_rest_position(body.waves(), 5.0, p);
        const double h = evaluate_lagrangian(body.waves(), exact, 5.0).displacement.y;
        worst_ref = std::max(worst_ref, std::abs(reference::fixed_point_height(body.waves(), 5.0, p) - h));
        worst_newton = std::max(worst_newton, std::abs(query_point(body, 5.0, p).height - h));
    }
    EXPECT_LT(worst_newton, 1e-4);
    EXPECT_GT(worst_ref, 10.0 * worst_newton);
}

// Eulerian normals agree with central differences of queried heights within 0.05 degrees.
TEST(EulerianQuery, NormalsMatchFiniteDifferencesOfHeights) {
    const WaterBody body = make_body(random_waves(12, 0.7, 5));
    const double h = 1e-3;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec2 p{i * 1.3 - 100.0, i * 0.7 - 50.0};
        const SurfacePoint s = query_point(body, 2.0, p);
        const double dhdx = (query_point(body, 2.0, p + glm::dvec2(h, 0)).height -
                             query_point(body, 2.0, p - glm::dvec2(h, 0)).height) /
                            (2 * h);
        const double dhdz = (query_point(body, 2.0, p + glm::dvec2(0, h)).height -
                             query_point(body, 2.0, p - glm::dvec2(0, h)).height) /
                            (2 * h);
        const glm::dvec3 fd = glm::normalize(glm::dvec3(-dhdx, 1.0, -dhdz));
        const double angle = std::acos(std::min(1.0, glm::dot(fd, s.normal))) * 180.0 / kPi;
        EXPECT_LT(angle, 0.05) << "point " << i;
    }
}

TEST(EulerianQuery, StillWaterIsFlatAtTheLevel) {
    const WaterBody body = make_body({}, 2.5);
    const SurfacePoint s = query_point(body, 10.0, {3.0, 4.0});
    EXPECT_DOUBLE_EQ(s.height, 2.5);
    EXPECT_DOUBLE_EQ(s.normal.y, 1.0);
    EXPECT_DOUBLE_EQ(s.jacobian, 1.0);
    EXPECT_EQ(s.iterations, 1);
}

TEST(EulerianQuery, RejectsMismatchedSpans) {
    const WaterBody body = make_body(random_waves(3, 0.3, 1));
    std::vector<glm::dvec2> pts(5);
    std::vector<double> h(4);
    const Status st = query_heights(body, 0.0, pts, h);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::invalid_argument);
    std::vector<double> none;
    EXPECT_TRUE(query_heights(body, 0.0, {}, none).ok());
}

// Bit-identical results for 1, 2, 3 and 8 threads (each point is solved on its own).
TEST(EulerianQuery, DeterministicAcrossThreadCounts) {
    const WaterBody body = make_body(random_waves(32, 0.8, 9));
    std::vector<glm::dvec2> pts(50001);
    for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = {std::sin(i * 0.1) * 300.0, std::cos(i * 0.07) * 300.0};
    const auto one = surface_on_threads(body, 123.0, pts, 1);
    for (unsigned threads : {2u, 3u, 8u}) expect_bitwise_equal(one, surface_on_threads(body, 123.0, pts, threads));
    // Heights-only and full queries give the same heights.
    std::vector<double> heights(pts.size());
    ASSERT_TRUE(query_heights(body, 123.0, pts, heights).ok());
    for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(heights[i], one[i].height);
}

// The baseline (SSE2) and AVX2 kernels agree within 10 micrometres in height and 0.05
// degrees in the normal (they round differently and stop at different sub-tolerance steps).
TEST(EulerianQuery, KernelsAgree) {
#if defined(TIDEWATER_HAVE_AVX2_KERNEL)
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "CPU has no AVX2+FMA";
    const WaterBody body = make_body(random_waves(24, 0.9, 4));
    const auto waves = detail::prepare_waves<float>(body.waves(), 42.0, 0.0);
    detail::KernelInput in;
    in.waves = &waves;
    std::vector<glm::dvec2> pts(4099);
    for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = {i * 0.71 - 1500.0, i * -0.13 + 80.0};
    std::vector<SurfacePoint> a(pts.size()), b(pts.size());
    detail::kernel_sse2::solve(in, pts.data(), pts.size(), a.data(), nullptr);
    detail::kernel_avx2::solve(in, pts.data(), pts.size(), b.data(), nullptr);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        ASSERT_NEAR(a[i].height, b[i].height, 1e-5) << i;
        ASSERT_LT(std::acos(std::min(1.0, glm::dot(a[i].normal, b[i].normal))) * 180.0 / kPi, 0.05) << i;
    }
#else
    GTEST_SKIP() << "this build has only the baseline kernel";
#endif
}

}  // namespace
}  // namespace tidewater
