// Ripples (noise detail) and the simulation clock.
#include <cmath>
#include <limits>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

TEST(Ripples, GradientMatchesFiniteDifferences) {
    RippleSpec spec;
    spec.amplitude = 0.05;
    spec.wavelength = 0.7;
    spec.octaves = 4;
    const RippleField field(spec);
    const double h = 1e-6;
    for (int i = 0; i < 500; ++i) {
        const glm::dvec2 p{i * 0.0137 - 3.0, i * 0.0291 + 1.0};
        const RippleSample s = field.sample(p, 2.5);
        const double dx =
            (field.sample(p + glm::dvec2(h, 0), 2.5).height - field.sample(p - glm::dvec2(h, 0), 2.5).height) / (2 * h);
        const double dz =
            (field.sample(p + glm::dvec2(0, h), 2.5).height - field.sample(p - glm::dvec2(0, h), 2.5).height) / (2 * h);
        EXPECT_NEAR(s.slope.x, dx, 1e-5) << i;
        EXPECT_NEAR(s.slope.y, dz, 1e-5) << i;
    }
}

TEST(Ripples, DeterministicBoundedAndSeeded) {
    RippleSpec spec;
    spec.amplitude = 0.02;
    spec.octaves = 3;
    const RippleField a(spec), b(spec);
    spec.seed += 1;
    const RippleField c(spec);
    const double bound = 0.02 * (1.0 + 1.0 / 2 + 1.0 / 3);
    double max_abs = 0.0, differ = 0.0;
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec2 p{i * 0.031, i * -0.017};
        const double ha = a.sample(p, 1.0).height;
        EXPECT_EQ(ha, b.sample(p, 1.0).height);
        max_abs = std::max(max_abs, std::abs(ha));
        differ = std::max(differ, std::abs(ha - c.sample(p, 1.0).height));
    }
    EXPECT_LE(max_abs, bound);
    EXPECT_GT(max_abs, 0.2 * bound);  // not trivially flat
    EXPECT_GT(differ, 1e-3);
}

TEST(Ripples, NoiseIsZeroOnLatticeAndPeriodic) {
    for (int i = -3; i < 3; ++i) {
        EXPECT_NEAR(gradient_noise({i * 1.0, 2.0}, 5).value, 0.0, 1e-15);
        const glm::dvec2 p{i * 0.37 + 0.1, 0.77};
        EXPECT_NEAR(gradient_noise(p, 5).value, gradient_noise(p + glm::dvec2(256.0, -512.0), 5).value, 1e-12);
    }
}

TEST(Ripples, ZeroAmplitudeIsDisabled) {
    const RippleField off{RippleSpec{}};
    EXPECT_FALSE(off.enabled());
    EXPECT_EQ(off.sample({1.0, 2.0}, 3.0).height, 0.0);
}

TEST(Clock, AdvancesPausesAndScales) {
    Clock clock(5.0);
    clock.advance(0.5);
    EXPECT_DOUBLE_EQ(clock.now(), 5.5);
    clock.pause();
    clock.advance(10.0);
    EXPECT_DOUBLE_EQ(clock.now(), 5.5);
    EXPECT_TRUE(clock.paused());
    clock.resume();
    EXPECT_TRUE(clock.set_scale(2.0));
    clock.advance(0.25);
    EXPECT_DOUBLE_EQ(clock.now(), 6.0);
    EXPECT_FALSE(clock.set_scale(-1.0));
    EXPECT_FALSE(clock.set_scale(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_DOUBLE_EQ(clock.scale(), 2.0);
    clock.advance(-3.0);  // a negative frame time never rewinds the sea
    clock.advance(std::numeric_limits<double>::infinity());
    EXPECT_DOUBLE_EQ(clock.now(), 6.0);
    EXPECT_TRUE(clock.set_scale(0.0));
    clock.advance(1.0);
    EXPECT_DOUBLE_EQ(clock.now(), 6.0);
}

// A body's time offset shifts its waves in time: offset 5 at t equals no offset at t + 5.
TEST(Clock, WaterBodyOffsetShiftsTime) {
    const auto waves = test::random_waves(6, 0.5, 3);
    const WaterBody shifted = test::make_body(waves, 0.0, 5.0);
    const WaterBody plain = test::make_body(waves, 0.0, 0.0);
    for (double t : {0.0, 1.25, 100.0}) {
        EXPECT_DOUBLE_EQ(query_point(shifted, t, {3.0, 4.0}).height, query_point(plain, t + 5.0, {3.0, 4.0}).height);
    }
}

}  // namespace
}  // namespace tidewater
