// The march's amplitude dispersion read from a table (parabolic_waves.hpp) against
// Kirby and Dalrymple's composite solved at each point, over shallow and intermediate
// water and heights up to the depth, at several scales (the table has no units).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "shore/parabolic_waves.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::detail {
namespace {

TEST(AmplitudeDispersion, TheTableIsTheSolveWithinTwoMillionths) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0, largest_shift = 0.0;
    for (int n = 0; n < 200000; ++n) {
        const double period = 0.5 + 19.5 * unit(rng);  // s: a flume's to a swell's
        const double omega = kTwoPi / period;
        // Depths from nearly dry to past the table (sqrt(omega^2 h / g) up to 2.2).
        const double s = 2.2 * unit(rng) + 1e-3;
        const double depth = s * s * kGravity / (omega * omega);
        const double amplitude = 0.55 * depth * unit(rng);  // heights up to 1.1 h
        const double k = wavenumber_at_depth(omega, depth);
        const double solved = amplitude_dispersed_wavenumber(omega, depth, amplitude, k);
        const double read = tabulated_amplitude_dispersed_wavenumber(omega, depth, amplitude, k);
        worst = std::max(worst, std::abs(read - solved) / solved);
        largest_shift = std::max(largest_shift, std::abs(solved - k) / k);
    }
    std::printf("amplitude dispersion: table within %.2e of the solve; the dispersion shifts k by up to %.3f\n", worst,
                largest_shift);
    EXPECT_LT(worst, 2e-6);
    EXPECT_GT(largest_shift, 0.1);  // the range compared is where it matters
}

}  // namespace
}  // namespace tidewater::detail
