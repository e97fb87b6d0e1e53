// The parabolic march (shore/parabolic_waves.hpp) asks the random sea's height only where a
// point's turn can read it: the rows are the same as when every point is given it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "shore/parabolic_waves.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::detail {
namespace {

/// A component of a random sea (T = 4 s, deep-water length 25 m) over 30 m of water, then
/// 15 m, then up a beach with a shoal on it.
ParabolicInput beach_component() {
    ParabolicInput in;
    in.grid = {240, 48, 1.0, 1.0};
    in.omega = kTwoPi / 4.0;
    in.depth_row = [](int step, std::span<float> depth) {
        for (std::size_t j = 0; j < depth.size(); ++j) {
            const double x = step, y = static_cast<double>(j) - 24.0;
            const double shelf = x < 60.0 ? 30.0 : x < 80.0 ? 30.0 - 0.75 * (x - 60.0) : 15.0;
            const double beach = x < 140.0 ? shelf : 15.0 - 0.15 * (x - 140.0);
            const double shoal = 3.0 * std::exp(-((x - 170.0) * (x - 170.0) + y * y) / 200.0);
            depth[j] = static_cast<float>(beach - shoal);
        }
    };
    in.incident_amplitude = 0.25;
    in.incident_in_deep_water = true;
    in.sea_over_component = 2.5;
    in.sea_period = 5.0;
    in.random_sea = true;
    return in;
}

/// Where the sea stands 2.5 m high over the 15 m shelf: a random sea starts to break
/// there (over 0.146 of the depth), though the water is deep for the component.
bool squall(int step, std::size_t j) {
    return step >= 90 && step < 130 && j < 16;
}

/// The sea's height: 35 % of the depth, at most 0.8 m; 2.5 m in the squall.
double sea_height(const ParabolicInput& in, int step, std::size_t j) {
    if (squall(step, j)) return 2.5;
    std::vector<float> depth(static_cast<std::size_t>(in.grid.across));
    in.depth_row(step, depth);
    return std::min(0.8, 0.35 * std::max(0.0, static_cast<double>(depth[j])));
}

TEST(ParabolicMarch, AsksTheSeasHeightOnlyWhereATurnReadsItAndMarchesTheSame) {
    // Every point given the sea's height, as a march without a bound is.
    ParabolicInput every = beach_component();
    every.sea_height_row = [&every](int step, std::span<float> height, std::span<const char>) {
        for (std::size_t j = 0; j < height.size(); ++j) height[j] = static_cast<float>(sea_height(every, step, j));
    };
    // Only the points asked, under the sea's highest: the rest poisoned, so that a read of
    // one would show in the rows.
    ParabolicInput asked = beach_component();
    std::size_t points = 0, given = 0, given_over_30_m = 0, squall_points = 0, squall_given = 0;
    asked.sea_height_row = [&](int step, std::span<float> height, std::span<const char> ask) {
        for (std::size_t j = 0; j < height.size(); ++j) {
            ++points;
            height[j] =
                ask[j] ? static_cast<float>(sea_height(asked, step, j)) : std::numeric_limits<float>::quiet_NaN();
            given += ask[j] ? 1 : 0;
            given_over_30_m += ask[j] && step < 60 ? 1 : 0;
            squall_points += squall(step, j) ? 1 : 0;
            squall_given += ask[j] && squall(step, j) ? 1 : 0;
        }
    };
    asked.sea_height_bound = 2.5;

    ParabolicMarch a(every), b(asked);
    ASSERT_TRUE(a.started() && b.started());
    std::size_t rows = 0;
    do {
        const ParabolicRow ra = a.row(), rb = b.row();
        ASSERT_EQ(ra.step, rb.step);
        for (std::size_t j = 0; j < ra.amplitude.size(); ++j) {
            ASSERT_EQ(ra.amplitude[j], rb.amplitude[j]) << "row " << ra.step << ", point " << j;
            ASSERT_EQ(ra.broken[j], rb.broken[j]) << "row " << ra.step << ", point " << j;
        }
        ASSERT_EQ(a.phase(), b.phase());
        ++rows;
        const bool more = a.advance();
        ASSERT_EQ(more, b.advance());
        if (!more) break;
    } while (true);
    EXPECT_EQ(rows, 240u);
    // Over 30 m nothing 2.5 m high breaks: no point there is asked. In the squall every
    // point is (the sea breaks there), and so are the beach's shallows. With a bound under
    // the squall's 2.5 m the rows differ from row 91 on.
    EXPECT_EQ(given_over_30_m, 0u);
    EXPECT_EQ(squall_given, squall_points);
    EXPECT_LT(given, points);
    std::printf("the sea's height asked at %zu of %zu points\n", given, points);
}

}  // namespace
}  // namespace tidewater::detail
