// The shore physics has no length or time of its own: Hansen & Svendsen's flume (a regular
// wave of T = 3.33 s from 0.36 m of water up a 1:34 slope) at 1:1, and the same flume
// scaled by 10 and 100 in length (by sqrt(10) and 10 in time), give the same wave-height
// profile over depth. (Before, waves died out over the last 0.5 m of depth whatever the
// scene, so at the laboratory's scale they faded up the slope instead of shoaling.)
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "../baked_scene.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

constexpr std::array<double, 6> kStations = {0.0, 3.0, 6.0, 8.0, 9.0, 10.0};  // m from the toe at 1:1

/// The flume at `scale`: its wave heights at the stations over one period, over H0's.
std::array<double, 6> height_profile(double scale) {
    const double period = 3.33 * std::sqrt(scale);
    const double deep_wavelength = kGravity * period * period / (2.0 * kPi);
    const std::string json = fmt::format(
        R"({{"version": 1, "water_level": 0, "shore": {{"resolution": 512}},
            "terrain": {{"plane": {{"height": {}, "slope": [{}, 0], "half_size": {}}}}},
            "ocean": {{"waves": [{{"direction": 0, "wavelength": {}, "amplitude": {}, "steepness": 0}}]}}}})",
        -0.36 * scale, 1.0 / 34.0, 40.0 * scale, deep_wavelength, 0.0175 * scale);
    auto scene = test::baked(parse_scene(json, fmt::format("flume_1to{}.json", scale)));
    std::array<double, 6> h{};
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    if (!scene.ok()) return h;
    for (std::size_t s = 0; s < kStations.size(); ++s) {
        double lo = 1e9, hi = -1e9;
        for (int n = 0; n < 64; ++n) {
            const double y = query_world_point(*scene, period * n / 64.0, {kStations[s] * scale, 0.0}).surface.height;
            lo = std::min(lo, y);
            hi = std::max(hi, y);
        }
        h[s] = (hi - lo) / (2.0 * 0.0175 * scale);
    }
    return h;
}

TEST(ShoreScale, AFlumeScaledByFroudeGivesTheSameHeightProfile) {
    const auto lab = height_profile(1.0), ten = height_profile(10.0), hundred = height_profile(100.0);
    double worst = 0.0;
    for (std::size_t s = 0; s < kStations.size(); ++s) {
        std::printf("x = %4.1f m (1:1): H/H0 %.4f at 1:1, %.4f at 1:10, %.4f at 1:100\n", kStations[s], lab[s], ten[s],
                    hundred[s]);
        worst = std::max({worst, std::abs(ten[s] / lab[s] - 1.0), std::abs(hundred[s] / lab[s] - 1.0)});
    }
    std::printf("largest difference from the laboratory scale: %.3f %%\n", 100.0 * worst);
    EXPECT_LT(worst, 0.01);
    // The waves shoal up the slope (as linear theory says they grow toward breaking), not fade.
    EXPECT_GT(lab[3], 1.2 * lab[0]);
    EXPECT_GT(lab[0], 1.1);
}

}  // namespace
}  // namespace tidewater
