// Boat wakes against Kelvin's theory: the wedge, its wavelengths and its decay.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "host_device.h"
#include "test_helpers.hpp"
#include "tidewater/detail/wake_water.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/wakes.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kKelvinAngle = 19.4712206;    // asin(1/3), degrees
constexpr double kCuspWaveAngle = 35.2643897;  // the cusp waves' direction from the track, atan(1/sqrt(2)), degrees

/// A boat at speed U on deep, calm water with a hull whose length Froude number is 0.4,
/// sailing +x from the origin; its wake at `time`, and where its bow shoulders are.
struct KelvinCase {
    double speed, lambda;  ///< U, and the transverse wavelength 2 pi U^2 / g
    double time;           ///< clock time of the wake, s
    SceneBoat boat;
    Wakes wakes;
    WaterBody calm = test::make_body({});
    glm::dvec2 apex{0.0};  ///< the wedge's apex: the bow shoulders, on the track

    KelvinCase(double u, double sailed_wavelengths) : speed(u), lambda(kTwoPi * u * u / kGravity) {
        const double length = u * u / (0.16 * kGravity);
        boat.name = "test";
        boat.path = {{0.0, 0.0}, {1.0e5, 0.0}};
        boat.speed = u;
        boat.hull = {length, 0.25 * length, 0.1 * length};
        time = sailed_wavelengths * lambda / u;
        scripted_boat_wake(boat, 0, time, wakes);
        // Linear waves (the theory's), and no stern chain (it churns foam, not waves).
        std::erase_if(wakes.chains,
                      [](const WakeChain& c) { return c.points.empty() || c.points.front().strength == 0.0; });
        for (WakeChain& c : wakes.chains)
            for (DisturbancePoint& p : c.points) p.steepness = 0.0;
        apex = {u * time + 0.25 * length, 0.0};
    }

    /// Heights at world points.
    std::vector<double> heights(const std::vector<glm::dvec2>& points) const {
        std::vector<double> h(points.size());
        QueryOptions options;
        options.wakes = &wakes;
        options.threads = 0;
        EXPECT_TRUE(query_heights(calm, time, points, h, options).ok());
        return h;
    }
    glm::dvec2 behind(double distance, double angle_deg) const {
        return apex + distance * glm::dvec2(-std::cos(angle_deg * kDeg), std::sin(angle_deg * kDeg));
    }
    /// The wake's envelope at `distance` behind the apex for each angle: the largest
    /// |eta| over one transverse wavelength along the ray.
    std::vector<double> envelope(double distance, const std::vector<double>& angles) const {
        std::vector<glm::dvec2> points;
        const int samples = 24;
        for (double a : angles)
            for (int s = 0; s <= samples; ++s)
                points.push_back(behind(distance + lambda * (double(s) / samples - 0.5), a));
        const std::vector<double> h = heights(points);
        std::vector<double> env(angles.size(), 0.0);
        for (std::size_t i = 0; i < angles.size(); ++i)
            for (int s = 0; s <= samples; ++s)
                env[i] = std::max(env[i], std::abs(h[i * (samples + 1) + static_cast<std::size_t>(s)]));
        return env;
    }
    /// The angle (degrees) of the strongest envelope between lo and hi, and its value.
    std::pair<double, double> peak(double distance, double lo, double hi, double step = 0.1) const {
        std::vector<double> angles;
        for (double a = lo; a <= hi + 1e-9; a += step) angles.push_back(a);
        const std::vector<double> env = envelope(distance, angles);
        const auto best = std::max_element(env.begin(), env.end());
        return {angles[static_cast<std::size_t>(best - env.begin())], *best};
    }
};

/// Mean distance between successive upward zero crossings of h sampled every `step`.
double crossing_wavelength(const std::vector<double>& h, double step) {
    std::vector<double> at;
    for (std::size_t i = 0; i + 1 < h.size(); ++i)
        if (h[i] < 0.0 && h[i + 1] >= 0.0) at.push_back((double(i) + h[i] / (h[i] - h[i + 1])) * step);
    if (at.size() < 2) return 0.0;
    return (at.back() - at.front()) / double(at.size() - 1);
}

/// Least-squares slope of log(y) against log(x).
double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Kelvin's wedge at U = 3, 5 and 8 m/s (hull Froude number 0.4): 20 to 30 transverse
// wavelengths behind the bow, the strongest crest near the cusp line lies within 1 degree
// of 19.47 degrees, and the wake's outer edge (where the envelope falls to half that
// crest's) within 1 degree beyond it; on the track the transverse wavelength is
// 2 pi U^2 / g within 3%, and at the cusp the waves (running 35.26 degrees off the
// track) are 2/3 of it within 5%.
TEST(Wakes, KelvinWedgeAngleAndWavelengths) {
    for (const double u : {3.0, 5.0, 8.0}) {
        const KelvinCase k(u, 69.0);
        ASSERT_TRUE(k.wakes.validate().ok()) << k.wakes.validate().error().message;
        for (const double x : {20.0, 25.0, 30.0}) {
            const auto [angle, height] = k.peak(x * k.lambda, 14.0, 23.0);
            // The outer edge: from the crest outward, where the envelope halves.
            std::vector<double> outward;
            for (double a = angle; a <= 26.0; a += 0.05) outward.push_back(a);
            const std::vector<double> env = k.envelope(x * k.lambda, outward);
            double edge = outward.back();
            for (std::size_t i = 0; i < env.size(); ++i)
                if (env[i] < 0.5 * height) {
                    edge = outward[i];
                    break;
                }
            std::printf("U = %.0f m/s, %2.0f wavelengths behind: crest %.2f deg (%.3f m), outer edge %.2f deg\n", u, x,
                        angle, height, edge);
            EXPECT_NEAR(angle, kKelvinAngle, 1.0) << "U " << u << ", " << x << " wavelengths";
            EXPECT_NEAR(edge, kKelvinAngle + 0.5, 1.0) << "U " << u << ", " << x << " wavelengths";
        }
        // Transverse waves on the track, 4 to 14 wavelengths behind.
        const double step = k.lambda / 64.0;
        std::vector<glm::dvec2> track;
        for (double s = 4.0 * k.lambda; s <= 14.0 * k.lambda; s += step) track.push_back(k.behind(s, 0.0));
        const double transverse = crossing_wavelength(k.heights(track), step);
        // The cusp waves run 35.26 degrees off the track (forward and out), so along a ray
        // alpha degrees off the track behind the boat their crests are a wavelength /
        // cos(35.26 + alpha degrees) apart: measured along the ray of the strongest cusp
        // crest, 12 to 20 wavelengths behind.
        const double ray = k.peak(16.0 * k.lambda, 17.0, 21.0, 0.05).first;
        std::vector<glm::dvec2> line;
        const double fine = k.lambda / 128.0;
        for (double s = 12.0 * k.lambda; s <= 20.0 * k.lambda; s += fine) line.push_back(k.behind(s, ray));
        const double cusp_wavelength =
            crossing_wavelength(k.heights(line), fine) * std::cos((kCuspWaveAngle + ray) * kDeg);
        std::printf("U = %.0f m/s: transverse wavelength %.3f m (2 pi U^2 / g = %.3f), cusp %.3f m (ratio %.3f)\n", u,
                    transverse, k.lambda, cusp_wavelength, cusp_wavelength / k.lambda);
        EXPECT_NEAR(transverse / k.lambda, 1.0, 0.03) << "U " << u;
        EXPECT_NEAR(cusp_wavelength / k.lambda, 2.0 / 3.0, 0.05 * 2.0 / 3.0) << "U " << u;
    }
}

/// Kelvin's integral for the same source (the steady far field of a moving pressure
/// patch, Havelock 1908; DLMF 36.13 without the source): at (xi, y) in the boat's frame
/// (xi < 0 behind the source), up to a constant,
///     eta = Re int_{-pi/2}^{pi/2} sec^4 t F(k0 sec^2 t) exp(i k0 sec^2 t (xi cos t + y sin t)) dt,
/// F the patch's transform, k0 = g / U^2, by the trapezoid rule on a grid fine enough for
/// the phase.
double kelvin_integral(double k0, double size, double xi, double y) {
    const double r = std::hypot(xi, y);
    const int n = std::max(4000, static_cast<int>(40.0 * k0 * r));
    double sum = 0.0;
    for (int i = 1; i < n; ++i) {
        const double t = -0.5 * kPi + kPi * double(i) / n;
        const double sec2 = 1.0 / (std::cos(t) * std::cos(t));
        const double k = k0 * sec2;
        const double filter = std::exp(-k * k * size * size / (4.0 * kPi * kPi));
        if (filter < 1e-12) continue;
        sum += sec2 * sec2 * filter * std::cos(k * (xi * std::cos(t) + y * std::sin(t)));
    }
    return sum * kPi / n;
}

// Decay: along the cusp line the wake's crest falls as r^(-1/3), off it (6 degrees, the
// transverse waves) as r^(-1/2). Fitted over 15 to 50 wavelengths behind the bow at
// U = 3 m/s, each exponent is within 0.05 of the theory's and of what the same
// measurement gives on Kelvin's integral for the same source (which at these distances
// is still -0.30 at the cusp: the Airy peak narrows slowly).
TEST(Wakes, CuspAndTransverseWavesDecayAsKelvinsIntegral) {
    const KelvinCase k(3.0, 115.0);
    std::vector<double> r, cusp, off;
    for (const double x : {15.0, 20.0, 30.0, 40.0, 50.0}) {
        r.push_back(x * k.lambda);
        cusp.push_back(k.peak(x * k.lambda, 15.0, 22.0).second);
        off.push_back(k.envelope(x * k.lambda, {6.0})[0]);
    }
    const double cusp_exponent = log_slope(r, cusp), off_exponent = log_slope(r, off);
    std::printf("decay exponents: cusp %.3f (theory -1/3), off the cusp %.3f (theory -1/2)\n", cusp_exponent,
                off_exponent);
    // The same measurement on Kelvin's integral.
    const double k0 = kGravity / (k.speed * k.speed), size = boat_wake_shape(k.boat.hull).bow_size;
    auto integral_envelope = [&](double distance, double angle) {
        double e = 0.0;
        for (int s = 0; s <= 24; ++s) {
            const double d = distance + k.lambda * (s / 24.0 - 0.5);
            e = std::max(e,
                         std::abs(kelvin_integral(k0, size, -d * std::cos(angle * kDeg), d * std::sin(angle * kDeg))));
        }
        return e;
    };
    std::vector<double> integral_cusp, integral_off;
    for (const double d : r) {
        double best = 0.0;
        for (double a = 15.0; a <= 22.0; a += 0.1) best = std::max(best, integral_envelope(d, a));
        integral_cusp.push_back(best);
        integral_off.push_back(integral_envelope(d, 6.0));
    }
    const double integral_cusp_exponent = log_slope(r, integral_cusp),
                 integral_off_exponent = log_slope(r, integral_off);
    std::printf("Kelvin's integral: cusp %.3f, off the cusp %.3f\n", integral_cusp_exponent, integral_off_exponent);
    EXPECT_NEAR(cusp_exponent, integral_cusp_exponent, 0.05);
    EXPECT_NEAR(off_exponent, integral_off_exponent, 0.05);
    EXPECT_NEAR(cusp_exponent, -1.0 / 3.0, 0.05);
    EXPECT_NEAR(off_exponent, -0.5, 0.05);
}

/// Heights of `wakes` on calm water at `time`.
std::vector<double> wake_heights(const Wakes& wakes, double time, const std::vector<glm::dvec2>& points) {
    std::vector<double> h(points.size());
    QueryOptions options;
    options.wakes = &wakes;
    options.threads = 0;
    EXPECT_TRUE(query_heights(test::make_body({}), time, points, h, options).ok());
    return h;
}

double largest(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

/// A grid behind a boat that sailed +x to `head`: 4 to 24 hull lengths back, out to 12 beside.
std::vector<glm::dvec2> grid_behind(glm::dvec2 head, double length) {
    std::vector<glm::dvec2> points;
    for (double x = 4.0; x <= 24.0; x += 0.37)  // 0.37 hull lengths: not a multiple of the spacing
        for (double z = -12.0; z <= 12.0; z += 0.37) points.push_back(head + length * glm::dvec2(-x, z));
    return points;
}

// No scallops: the chains' points (every L / 8) give the wake of a continuous track. The
// same boat with points four times as dense differs by under 5% of the wake's height.
TEST(Wakes, PointSpacingLeavesNoScallops) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {5000.0, 0.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    const double time = 120.0;
    Wakes wakes;
    scripted_boat_wake(boat, 0, time, wakes);
    // Four times as dense: every segment split in four, strength and emission time linear.
    Wakes dense = wakes;
    for (WakeChain& c : dense.chains) {
        std::vector<DisturbancePoint> points;
        for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
            for (int j = 0; j < 4; ++j) {
                DisturbancePoint p = c.points[i];
                const double f = j / 4.0;
                p.position = glm::mix(c.points[i].position, c.points[i + 1].position, f);
                p.emitted = glm::mix(c.points[i].emitted, c.points[i + 1].emitted, f);
                points.push_back(p);
            }
        points.push_back(c.points.back());
        c.points = points;
    }
    std::erase_if(dense.chains, [](const WakeChain& c) { return c.points.front().strength == 0.0; });
    std::erase_if(wakes.chains, [](const WakeChain& c) { return c.points.front().strength == 0.0; });
    const auto grid = grid_behind({boat.speed * time, 0.0}, boat.hull.length);
    const std::vector<double> a = wake_heights(wakes, time, grid), b = wake_heights(dense, time, grid);
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    std::printf("wake height %.3f m; points every L/8 against L/32: %.4f m apart at most (%.2f%%)\n", largest(b), worst,
                100.0 * worst / largest(b));
    EXPECT_GT(largest(b), 0.05);
    EXPECT_LT(worst, 0.05 * largest(b));
}

// The same wake whatever the frame rate: a host feeding the boat's poses at 30, 60 or 144
// frames a second (BoatWakeEmitter) lays the same points as the scripted boat, and the
// surfaces agree within 1 mm.
TEST(Wakes, FrameRateDoesNotChangeTheWake) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {300.0, 0.0}, {600.0, 200.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    const double time = 100.0;
    Wakes scripted;
    scripted_boat_wake(boat, 3, time, scripted);
    const auto grid = grid_behind({450.0, 100.0}, 10.0);
    const std::vector<double> reference = wake_heights(scripted, time, grid);
    ASSERT_GT(largest(reference), 0.05) << "the grid is in the wake";
    for (const double rate : {30.0, 60.0, 144.0}) {
        BoatWakeEmitter emitter(boat.hull, 3);
        const int frames = static_cast<int>(std::round(time * rate));
        for (int f = 0; f <= frames; ++f) {
            const double t = f / rate;
            glm::dvec2 at;
            double heading = 0.0;
            boat.pose_at(t, at, heading);
            ASSERT_TRUE(emitter.advance(at, heading, t).ok());
        }
        Wakes fed;
        emitter.append_to(fed, time);
        const std::vector<double> h = wake_heights(fed, time, grid);
        double worst = 0.0;
        for (std::size_t i = 0; i < h.size(); ++i) worst = std::max(worst, std::abs(h[i] - reference[i]));
        std::printf("%.0f frames/s: %zu points against %zu scripted; surfaces %.5f m apart at most\n", rate,
                    fed.point_count(), scripted.point_count(), worst);
        EXPECT_LT(worst, 1e-3) << rate << " frames/s";
    }
}

// Points appearing at the bow and expiring at the tail change the surface by under 1 mm:
// just before and just after a point is laid, and just before and after the oldest point
// ages out, the wake differs by less than 1 mm (the waves themselves move 10 us apart).
TEST(Wakes, PointsAppearAndExpireWithoutAJump) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {5000.0, 0.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    const BoatWakeShape shape = boat_wake_shape(boat.hull);
    const double laid = 100.0 * shape.bow_spacing / boat.speed;  // the 100th bow point
    const double eps = 1e-5;
    auto jump = [&](double t, const std::vector<glm::dvec2>& points) {
        Wakes before, after;
        scripted_boat_wake(boat, 0, t - eps, before);
        scripted_boat_wake(boat, 0, t + eps, after);
        const std::vector<double> a = wake_heights(before, t - eps, points), b = wake_heights(after, t + eps, points);
        double worst = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
        // Whether a bow point was laid or dropped in between.
        const WakeChain &b0 = before.chains.front(), &a0 = after.chains.front();
        const bool laid_or_dropped = b0.points.front().emitted != a0.points.front().emitted ||
                                     b0.points[b0.points.size() - 2].emitted != a0.points[a0.points.size() - 2].emitted;
        return std::pair{worst, laid_or_dropped};
    };
    std::vector<glm::dvec2> near_bow;
    for (double x = -30.0; x <= 30.0; x += 1.3)
        for (double z = -30.0; z <= 30.0; z += 1.3)
            near_bow.push_back(glm::dvec2(boat.speed * laid, 0.0) + glm::dvec2(x, z));
    const auto [appear, changed] = jump(laid, near_bow);
    // The oldest bow point (laid at time 0) ages out at the chains' max age.
    const double expiry = 360.0;
    std::vector<glm::dvec2> near_tail;
    for (double x = -60.0; x <= 60.0; x += 2.1)
        for (double z = -60.0; z <= 60.0; z += 2.1) near_tail.push_back(glm::dvec2(x, z));
    const auto [expire, dropped] = jump(expiry, near_tail);
    std::printf("a point laid: the wake moves %.6f m; a point expiring: %.6f m\n", appear, expire);
    EXPECT_TRUE(changed);
    EXPECT_TRUE(dropped);
    EXPECT_LT(appear, 1e-3);
    EXPECT_LT(expire, 1e-3);
}

// Where a chain's waves can be felt (detail::wake_reach, the boxes the renderer culls
// by): just outside each box of a tug's wake, on a course with a turn, the full sum is
// under 1 mm; inside, the wake is there.
TEST(Wakes, OutsideTheirReachTheChainsCancel) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {600.0, 0.0}, {900.0, 300.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    const double time = 200.0;
    Wakes wakes;
    scripted_boat_wake(boat, 0, time, wakes);
    std::erase_if(wakes.chains, [](const WakeChain& c) { return c.points.front().strength == 0.0; });
    const auto prepared = detail::prepare_wakes<double>(wakes, time);
    ASSERT_EQ(prepared.boxes.size(), 2u);
    std::vector<glm::dvec2> ring;
    for (const glm::dvec4& b : prepared.boxes) {
        const glm::dvec2 lo = prepared.origin + glm::dvec2(b.x, b.y) - 5.0,
                         hi = prepared.origin + glm::dvec2(b.z, b.w) + 5.0;
        for (double f = 0.0; f <= 1.0; f += 0.01) {
            ring.push_back({glm::mix(lo.x, hi.x, f), lo.y});
            ring.push_back({glm::mix(lo.x, hi.x, f), hi.y});
            ring.push_back({lo.x, glm::mix(lo.y, hi.y, f)});
            ring.push_back({hi.x, glm::mix(lo.y, hi.y, f)});
        }
    }
    // Points outside one box may lie in the other's: keep those outside both.
    std::erase_if(ring, [&](glm::dvec2 p) {
        for (const glm::dvec4& b : prepared.boxes) {
            const glm::dvec2 r = p - prepared.origin;
            if (r.x >= b.x && r.x <= b.z && r.y >= b.y && r.y <= b.w) return true;
        }
        return false;
    });
    ASSERT_GT(ring.size(), 100u);
    const std::vector<double> outside = wake_heights(wakes, time, ring);
    std::vector<glm::dvec2> track;
    for (double x = 100.0; x <= 500.0; x += 3.0) track.push_back({x, 20.0});
    const std::vector<double> inside = wake_heights(wakes, time, track);
    std::size_t worst = 0;
    for (std::size_t i = 0; i < outside.size(); ++i)
        if (std::abs(outside[i]) > std::abs(outside[worst])) worst = i;
    std::printf("beyond the wakes' reach: %.6f m at most over %zu points (at %.0f, %.0f); in the wake %.3f m\n",
                largest(outside), ring.size(), ring[worst].x, ring[worst].y, largest(inside));
    EXPECT_LT(largest(outside), 1e-3);
    EXPECT_GT(largest(inside), 0.03);
}

// The walk skips a segment where it cannot be felt (detail::wake_reach_disc), point by
// point, as the renderer's vertices do: over the whole wake of a tug with a 45 degree
// turn, at three times, that changes the water by under 1 mm, and skips most segments.
TEST(Wakes, SegmentsAreSkippedOnlyWhereTheyCannotBeFelt) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {600.0, 0.0}, {900.0, 300.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    double worst = 0.0, largest_height = 0.0, felt_share = 0.0;
    int samples = 0;
    for (double time : {90.0, 200.0, 300.0}) {
        Wakes wakes;
        scripted_boat_wake(boat, 0, time, wakes);
        auto culled = detail::prepare_wakes<double>(wakes, time);
        auto full = culled;
        full.cull = false;
        ASSERT_EQ(culled.reach2.size(), culled.x.size());
        for (double x = -200.0; x <= 1100.0; x += 7.3)
            for (double z = -400.0; z <= 700.0; z += 7.3) {
                const glm::dvec2 r = glm::dvec2(x, z) - culled.origin;
                detail::SurfaceSums<double> a, b;
                detail::add_wakes<true>(a, culled, r.x, r.y);
                detail::add_wakes<true>(b, full, r.x, r.y);
                worst = std::max({worst, std::abs(a.eta - b.eta), std::abs(a.dx - b.dx), std::abs(a.dz - b.dz)});
                largest_height = std::max(largest_height, std::abs(b.eta));
                std::size_t felt = 0, terms = 0;
                for (std::size_t i = 0; i < culled.x.size(); ++i) {
                    if (!culled.linked[i]) continue;
                    const double dx = r.x - culled.reach_x[i], dz = r.y - culled.reach_z[i];
                    felt += dx * dx + dz * dz <= culled.reach2[i] ? 1 : 0;
                    ++terms;
                }
                felt_share += terms ? double(felt) / double(terms) : 0.0;
                ++samples;
            }
    }
    std::printf(
        "skipping segments beyond their reach: %.6f m at most (wake up to %.3f m); %.0f%% of segments summed on "
        "average\n",
        worst, largest_height, 100.0 * felt_share / samples);
    EXPECT_GT(largest_height, 0.1);
    EXPECT_LT(worst, 1e-3);
    EXPECT_LT(felt_share / samples, 0.75);
}

// A wake queried just after a mark was laid: the boat's head point (age 0) and that mark
// (33 ns old) make a segment whose wavevector's square is subnormal in float. A point its
// reach misses, in one batch with a point it reaches, gets the same height as alone (the
// SIMD kernels' inverse square root estimate once took the subnormal for zero: NaN).
TEST(Wakes, AWakeJustLaidLeavesItsBatchNeighboursAlone) {
    SceneBoat boat;
    boat.path = {{0.0, 0.0}, {2000.0, 0.0}};
    boat.speed = 5.0;
    boat.hull = {20.0, 6.0, 1.5};
    Wakes before;
    scripted_boat_wake(boat, 0, 100.0, before);
    double mark = 0.0;  // the last mark laid before the head at 100 s
    for (const WakeChain& c : before.chains)
        if (c.points.size() >= 2) mark = std::max(mark, c.points[c.points.size() - 2].emitted);
    ASSERT_GT(mark, 90.0);
    const double time = mark + 1.0 / 3.0e7;
    Wakes wakes;
    scripted_boat_wake(boat, 0, time, wakes);
    glm::dvec2 bow;
    double heading = 0.0;
    boat.pose_at(time, bow, heading);
    const glm::dvec2 near = bow + glm::dvec2(-5.0, 4.0), far = bow + glm::dvec2(-400.0, 350.0);
    const std::vector<double> both = wake_heights(wakes, time, {far, near});
    const std::vector<double> far_alone = wake_heights(wakes, time, {far}),
                              near_alone = wake_heights(wakes, time, {near});
    std::printf("a wake 33 ns after a mark: %.6f m far off (%.6f alone), %.6f m at the bow (%.6f alone)\n", both[0],
                far_alone[0], both[1], near_alone[0]);
    EXPECT_TRUE(std::isfinite(both[0]) && std::isfinite(both[1]));
    EXPECT_EQ(both[0], far_alone[0]);
    EXPECT_EQ(both[1], near_alone[0]);
}

std::string scene_with_boats(const std::string& boats) {
    return R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -40}}, "ocean": "pool_calm", "boats": )" +
           boats + "}";
}

// A scene's boats: query_world adds their wakes (the wake column is their share of the
// height), and a boat can leave its own wake out (emitter = its index).
TEST(Wakes, SceneBoatsJoinTheWorldQueries) {
    auto scene =
        parse_scene(scene_with_boats(R"([{"name": "tug", "path": [[0, 0], [2000, 0]], "speed": 5.0, "length": 20.0,
                                                    "beam": 6.0, "draft": 1.5, "start": 0.0}])"),
                    "s.json");
    ASSERT_TRUE(scene) << scene.error().message;
    ASSERT_EQ(scene->boats.size(), 1u);
    auto baked = bake_scene(*scene);
    ASSERT_TRUE(baked) << baked.error().message;
    const double time = 60.0;  // the tug is at x = 300
    std::vector<glm::dvec2> points;
    for (double x = 100.0; x <= 280.0; x += 7.0)
        for (double z = -60.0; z <= 60.0; z += 7.0) points.push_back({x, z});
    std::vector<WorldPoint> with(points.size()), without(points.size());
    ASSERT_TRUE(query_world(**baked, time, points, with).ok());
    QueryOptions own;
    own.exclude_emitter = 0;
    ASSERT_TRUE(query_world(**baked, time, points, without, own).ok());
    double biggest = 0.0, mismatch = 0.0, rest = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        biggest = std::max(biggest, std::abs(with[i].surface.wake));
        mismatch =
            std::max(mismatch, std::abs(with[i].surface.height - without[i].surface.height - with[i].surface.wake));
        rest = std::max(rest, std::abs(without[i].surface.wake));
    }
    std::printf(
        "the tug's wake: up to %.3f m; the heights with and without it differ by the wake column within %.4f m\n",
        biggest, mismatch);
    EXPECT_GT(biggest, 0.1);
    EXPECT_EQ(rest, 0.0);
    // The pool's ripples are small: the height with the wake is the height without it plus
    // the wake (the solved points differ by the wake's sideways displacement).
    EXPECT_LT(mismatch, 0.02);
}

// Bad boats and wakes are refused with the file and JSON path (or the field).
TEST(Wakes, BadBoatsAndWakesAreRefusedByName) {
    const std::string good = R"("name": "tug", "path": [[0, 0], [500, 0]], "length": 20, "beam": 6, "draft": 1.5)";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"[{" + good + R"(, "speed": -5}])", "s.json: /boats/0/speed"},
        {R"([{"name": "tug", "path": [[0, 0], [500, 0]], "speed": 5, "length": -20, "beam": 6, "draft": 1.5}])",
         "s.json: /boats/0/length"},
        {R"([{"name": "tug", "path": [[0, 0]], "speed": 5, "length": 20, "beam": 6, "draft": 1.5}])",
         "s.json: /boats/0/path"},
        {"[{" + good + R"(, "speed": "nan"}])", "s.json: /boats/0/speed"},
        {"[{" + good + R"(, "speed": 5, "hull": 3}])", "hull"},
        {R"([{"name": "skiff", "path": [[0, 0], [500, 0]], "speed": 20, "length": 3, "beam": 1.5, "draft": 0.3}])",
         "s.json: /boats/0"},
    };
    for (const auto& [boats, expected] : cases) {
        auto scene = parse_scene(scene_with_boats(boats), "s.json");
        ASSERT_FALSE(scene) << boats;
        EXPECT_NE(scene.error().message.find(expected), std::string::npos) << scene.error().message;
    }
    Wakes wakes;
    wakes.chains.push_back({});
    wakes.chains[0].points.resize(2);
    wakes.chains[0].points[1].emitted = 1.0;
    wakes.chains[0].points[1].source_size = std::nan("");
    const Status nan_size = wakes.validate("w");
    ASSERT_FALSE(nan_size.ok());
    EXPECT_NE(nan_size.error().message.find("w: chains[0].points[1]: source_size"), std::string::npos)
        << nan_size.error().message;
    wakes.chains[0].points[1].source_size = 1.0;
    wakes.chains[0].points[1].emitted = 0.0;
    const Status order = wakes.validate("w");
    ASSERT_FALSE(order.ok());
    EXPECT_NE(order.error().message.find("not after"), std::string::npos) << order.error().message;
    wakes.chains[0].points[1].emitted = 1.0;
    wakes.chains[0].points.resize(gpu::kMaxWakePoints + 1);
    for (std::size_t i = 0; i < wakes.chains[0].points.size(); ++i) wakes.chains[0].points[i].emitted = double(i);
    const Status many = wakes.validate("w");
    ASSERT_FALSE(many.ok());
    EXPECT_NE(many.error().message.find("4097 disturbance points"), std::string::npos) << many.error().message;
    // A query with bad wakes is refused the same way.
    std::vector<glm::dvec2> p{{0.0, 0.0}};
    std::vector<double> h(1);
    QueryOptions options;
    options.wakes = &wakes;
    const Status refused = query_heights(test::make_body({}), 1.0, p, h, options);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("query: wakes"), std::string::npos) << refused.error().message;
    BoatWakeEmitter emitter(BoatHull{}, 1);
    ASSERT_TRUE(emitter.advance({0.0, 0.0}, 0.0, 1.0).ok());
    EXPECT_FALSE(emitter.advance({1.0, 0.0}, 0.0, 1.0).ok()) << "time must increase";
    EXPECT_FALSE(emitter.advance({std::nan(""), 0.0}, 0.0, 2.0).ok());
}

}  // namespace
}  // namespace tidewater
