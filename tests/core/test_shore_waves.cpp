// Shoreline-aware waves against linear theory, with stated tolerances:
// dispersion on a flat bottom, shoaling and breaking on a planar beach, Snell's
// law at oblique incidence, nothing moving on dry land.
#include <cmath>

#include "test_helpers.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {
namespace {

/// Bake options for a model of `n` x `n` texels.
ShoreWaveOptions grid(int n) {
    ShoreWaveOptions o;
    o.resolution = n;
    return o;
}

TEST(Dispersion, SolvesTheRelationWithItsLimits) {
    for (double omega : {0.3, 1.0, 3.0})
        for (double h : {0.5, 5.0, 50.0, 5000.0}) {
            const double k = wavenumber_at_depth(omega, h);
            EXPECT_NEAR(kGravity * k * std::tanh(k * h) / (omega * omega), 1.0, 1e-12);
        }
    EXPECT_NEAR(wavenumber_at_depth(1.0, 1e4), 1.0 / kGravity, 1e-12);                      // deep: w^2 / g
    EXPECT_NEAR(wavenumber_at_depth(0.05, 1.0) / (0.05 / std::sqrt(kGravity)), 1.0, 1e-3);  // shallow: w / sqrt(g h)
    // Shoaling dips just below 1 at intermediate depth (minimum ~0.913 near kh = 1.3), then grows.
    const double omega = deep_water_omega(100.0);
    double lowest = 10.0;
    for (double h = 1.0; h < 200.0; h *= 1.02) lowest = std::min(lowest, shoaling_coefficient(omega, h));
    EXPECT_NEAR(lowest, 0.913, 0.005);
    // Green's law in shallow water: A ~ h^(-1/4).
    EXPECT_NEAR(shoaling_coefficient(omega, 0.2) / shoaling_coefficient(omega, 0.8), std::pow(4.0, 0.25), 0.03);
}

/// A wave of deep-water frequency omega along +x, amplitude a, steepness q.
WaveSet single_wave(double omega, double a, double q, double direction_deg = 0.0) {
    const WaveSpec spec{direction_deg, deep_water_wavelength(omega), a, q, 0.0};
    return WaveSet::create(std::span<const WaveSpec>(&spec, 1), FoldPolicy::reject, "test").value();
}

// Flat bottom at depth h: the wavelength measured on the surface (zero up-crossings of
// eta along x) equals 2 pi / k(h) within 2% for kh from 0.3 to 3. The waves are low
// (H = h / 100), so that the amplitude's own dispersion (Hedges' c = sqrt(g (h + a)) in
// shallow water, which the diffracted waves keep) stays well inside the tolerance.
TEST(ShoreWaves, FlatBottomWavelengthFollowsLinearDispersion) {
    for (double kh : {0.3, 0.6, 1.0, 2.0, 3.0}) {
        const double wavelength = 200.0, k = kTwoPi / wavelength, h = kh / k;
        const double omega = std::sqrt(kGravity * k * std::tanh(kh));
        const WaveSet set = single_wave(omega, 0.005 * h, 0.0);
        auto shore = bake_shore_waves(set, Terrain(FlatTerrain{-h}), 0.0);
        ASSERT_TRUE(shore.ok()) << shore.error().message;
        std::vector<double> crossings;
        double prev = 0.0;
        for (int i = 0; i <= 30000; ++i) {
            const double x = -1500.0 + i * 0.1;
            const double eta = evaluate_lagrangian_shore(set, **shore, {x, 0.0}, 0.0).displacement.y;
            if (i > 0 && prev < 0.0 && eta >= 0.0) crossings.push_back(x);
            prev = eta;
        }
        ASSERT_GE(crossings.size(), 5u);
        const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
        EXPECT_NEAR(measured / wavelength, 1.0, 0.02) << "kh = " << kh;
    }
}

struct Beach {
    PlaneTerrain plane;
    double shore_x = 0.0;
    double depth(double x) const { return -(plane.height + plane.slope.x * x); }
};

Beach planar_beach() {
    Beach b;
    b.plane.height = -50.0;
    b.plane.slope = {0.02, 0.0};  // rises toward +x; the shore is at x = 2500 m
    b.shore_x = 2500.0;
    return b;
}

/// Largest |eta| and crest-to-trough height at a rest position over one period.
std::pair<double, double> amplitude_and_height(const WaveSet& set, const ShoreWaves& shore, glm::dvec2 rest,
                                               double period) {
    double lo = 1e9, hi = -1e9;
    for (int s = 0; s < 200; ++s) {
        const double eta = evaluate_lagrangian_shore(set, shore, rest, period * s / 200.0).displacement.y;
        lo = std::min(lo, eta);
        hi = std::max(hi, eta);
    }
    return {0.5 * (hi - lo), hi - lo};
}

// Normal incidence: before breaking the amplitude follows sqrt(cg0 / cg(h)) within 10%.
TEST(ShoreWaves, PlanarBeachShoalsAsLinearTheory) {
    const Beach beach = planar_beach();
    const double omega = deep_water_omega(100.0), a0 = 0.3;
    const WaveSet set = single_wave(omega, a0, 0.5);
    auto shore = bake_shore_waves(set, Terrain(beach.plane), 0.0, grid(512));
    ASSERT_TRUE(shore.ok()) << shore.error().message;
    double worst = 0.0;
    int checked = 0;
    for (double h : {40.0, 20.0, 10.0, 6.0, 4.0, 3.0}) {
        const double x = (-beach.plane.height - h) / beach.plane.slope.x;
        const double expected = a0 * shoaling_coefficient(omega, h);
        ASSERT_LT(2 * expected, 0.78 * h * 0.85) << "stay clear of breaking";
        const auto [a, height] = amplitude_and_height(set, **shore, {x, 0.0}, kTwoPi / omega);
        worst = std::max(worst, std::abs(a / expected - 1.0));
        ++checked;
    }
    std::printf("normal incidence: worst shoaling error %.2f%% over %d depths\n", 100.0 * worst, checked);
    EXPECT_LT(worst, 0.10);
}

// Oblique incidence (20 and 40 degrees): before breaking the amplitude follows linear
// shoaling and refraction, a0 sqrt(cg0 / cg(h)) sqrt(cos(theta0) / cos(theta(h))) with
// Snell's sin(theta) = sin(theta0) k0 / k, within 10 %. The march turns with the rays
// here (its own direction stays the offshore one), so this checks its small-angle
// operator away from the march's axis (1.9 % at 40 degrees; physics.md).
TEST(ShoreWaves, ObliqueWavesShoalAndRefractAsLinearTheory) {
    const Beach beach = planar_beach();
    const double omega = deep_water_omega(100.0), a0 = 0.3, k0 = omega * omega / kGravity;
    for (const double theta0 : {20.0, 40.0}) {
        const WaveSet set = single_wave(omega, a0, 0.5, theta0);
        auto shore = bake_shore_waves(set, Terrain(beach.plane), 0.0, grid(512));
        ASSERT_TRUE(shore.ok()) << shore.error().message;
        const double sin0 = std::sin(theta0 * kPi / 180.0);
        double worst = 0.0;
        for (double h : {40.0, 20.0, 10.0, 6.0, 4.0, 3.0}) {
            const double x = (-beach.plane.height - h) / beach.plane.slope.x;
            const double sin_h = sin0 * k0 / wavenumber_at_depth(omega, h);
            const double refraction = std::sqrt(std::sqrt(1.0 - sin0 * sin0) / std::sqrt(1.0 - sin_h * sin_h));
            const double expected = a0 * shoaling_coefficient(omega, h) * refraction;
            const auto [a, height] = amplitude_and_height(set, **shore, {x, 0.0}, kTwoPi / omega);
            std::printf("oblique %.0f deg, %4.1f m of water: a / linear theory %.4f\n", theta0, h, a / expected);
            worst = std::max(worst, std::abs(a / expected - 1.0));
        }
        std::printf("oblique %.0f deg: worst shoaling and refraction error %.2f%%\n", theta0, 100.0 * worst);
        EXPECT_LT(worst, 0.10) << theta0;
    }
}

// Breaking: the height never exceeds Weggel's (1972) breaker index on a 1:50 beach
// (b(m) = 1.56 / (1 + exp(-19.5 m)) = 0.92 for the lowest waves) + 5 cm; the waves break
// between 0.7 h and that index, and the surf zone's heights fall below the breaker's
// H/h as Dally's dissipation takes them toward 0.4 h; foam rises where waves break, and
// nothing moves on dry land. With the rays alone the height is capped at 0.78 h + 5 cm.
TEST(ShoreWaves, BreaksAtTheDepthLimitAndStopsOnLand) {
    const Beach beach = planar_beach();
    const double omega = deep_water_omega(100.0);
    const WaveSet set = single_wave(omega, 1.2, 0.8);
    const double weggel_b = 1.56 / (1.0 + std::exp(-19.5 * beach.plane.slope.x));
    for (const bool diffraction : {true, false}) {
        ShoreWaveOptions options = grid(512);
        options.diffraction = diffraction;
        auto shore = bake_shore_waves(set, Terrain(beach.plane), 0.0, options);
        ASSERT_TRUE(shore.ok()) << shore.error().message;
        const double limit = diffraction ? weggel_b : 0.78;
        double worst_excess = -1e9, foam_in_surf = 0.0, peak = 0.0, peak_h = 0.0, lowest_after = 1e9;
        for (double h = 12.0; h > 0.2; h *= 0.85) {
            const double x = (-beach.plane.height - h) / beach.plane.slope.x;
            const auto [a, height] = amplitude_and_height(set, **shore, {x, 0.0}, kTwoPi / omega);
            worst_excess = std::max(worst_excess, height - (limit * h + 0.05));
            if (height / h > peak) {
                peak = height / h;
                peak_h = h;
            }
            if (h < 0.7 * peak_h) lowest_after = std::min(lowest_after, height / h);
            LocalShore local;
            (void)evaluate_lagrangian_shore(set, **shore, {x, 0.0}, 0.0, &local);
            if (1.2 * shoaling_coefficient(omega, h) > 0.39 * h * 1.3)
                foam_in_surf = std::max(foam_in_surf, local.breaking);
        }
        std::printf("%s: breaks at H/h %.3f in %.2f m; lowest H/h inshore %.3f\n",
                    diffraction ? "diffracted" : "rays alone", peak, peak_h, lowest_after);
        EXPECT_LE(worst_excess, 0.0) << "height above " << limit << " h + 5 cm";
        EXPECT_GT(peak, 0.7);
        EXPECT_GT(foam_in_surf, 0.5) << "foam where the waves break";
        if (diffraction) {
            EXPECT_LT(lowest_after, 0.6) << "the surf zone dissipates below the breaker's H/h";
        }
    }
    auto shore = bake_shore_waves(set, Terrain(beach.plane), 0.0, grid(512));
    ASSERT_TRUE(shore.ok()) << shore.error().message;
    for (double x : {2510.0, 2600.0, 2900.0}) {
        for (double t : {0.0, 1.7, 4.2}) {
            const LagrangianSample s = evaluate_lagrangian_shore(set, **shore, {x, 0.0}, t);
            EXPECT_EQ(s.displacement.x, 0.0);
            EXPECT_EQ(s.displacement.y, 0.0);
            EXPECT_EQ(glm::length(s.velocity), 0.0);
        }
    }
}

// Oblique incidence (30 and 60 degrees): the along-shore wavenumber stays k0 sin(theta0)
// within 2% and the cross-shore one is sqrt(k(h)^2 - k_along^2) (Snell's law).
// With the second-order fast-marching stencil the along-shore error at 2 m depth (where
// the wave is 32 m long) is 1.7% at 23 m texels, 0.45% at 11.7 m (512 over 6 km, used
// here, the default island's texel size) and 0.12% at 5.9 m; first order gave 3% at 11.7 m.
TEST(ShoreWaves, ObliqueIncidenceFollowsSnellsLaw) {
    const Beach beach = planar_beach();
    const double omega = deep_water_omega(80.0), k0 = omega * omega / kGravity;
    for (double theta0 : {30.0, 60.0}) {
        // Low waves: linear theory (the amplitude's own dispersion would turn them further).
        const WaveSet set = single_wave(omega, 0.02, 0.5, theta0);
        auto shore = bake_shore_waves(set, Terrain(beach.plane), 0.0, grid(512));
        ASSERT_TRUE(shore.ok()) << shore.error().message;
        const double along = k0 * std::sin(theta0 * kPi / 180.0);
        double worst_along = 0.0, worst_cross = 0.0;
        for (double h : {30.0, 15.0, 8.0, 4.0, 2.0}) {
            const double x = (-beach.plane.height - h) / beach.plane.slope.x;
            std::vector<LocalWave> lw(1);
            (void)(*shore)->sample({x, 0.0}, lw);
            const double k = wavenumber_at_depth(omega, h);
            worst_along = std::max(worst_along, std::abs(lw[0].wavevector.y / along - 1.0));
            worst_cross = std::max(worst_cross, std::abs(lw[0].wavevector.x / std::sqrt(k * k - along * along) - 1.0));
        }
        std::printf("oblique %.0f deg: along-shore error %.2f%%, cross-shore error %.2f%%\n", theta0, 100 * worst_along,
                    100 * worst_cross);
        EXPECT_LT(worst_along, 0.02) << theta0;
        EXPECT_LT(worst_cross, 0.02) << theta0;
    }
}

TEST(ShoreWaves, BodyRefusesAShoreBakedForOtherWaves) {
    const WaveSet one = single_wave(deep_water_omega(50.0), 0.3, 0.5);
    auto shore = bake_shore_waves(one, Terrain(planar_beach().plane), 0.0, grid(64));
    ASSERT_TRUE(shore.ok());
    const WaterBody two = test::make_body(test::random_waves(2, 0.3, 1));
    auto refused = two.with_shore(*shore);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("baked for 1 waves"), std::string::npos) << refused.error().message;
    EXPECT_TRUE(two.with_shore(nullptr).ok());
}

}  // namespace
}  // namespace tidewater
