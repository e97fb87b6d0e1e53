// Battjes and Janssen's share of broken waves (parabolic_waves.hpp), which every component
// of a random sea dissipates by in the surf zone: the root of 1 - Q_b = -b^2 ln Q_b
// (b = H_rms / H_max), held to near double precision, growing with b from nought at 0.2
// to 1 at 1.
#include <gtest/gtest.h>

#include <cmath>

#include "shore/parabolic_waves.hpp"

namespace tidewater::detail {
namespace {

TEST(BrokenShare, IsTheRootOfBattjesAndJanssensBalance) {
    double last = 0.0;
    for (double b = 0.201; b < 1.0; b += 0.001) {
        const double q = broken_share(b);
        ASSERT_GT(q, 0.0) << "b " << b;
        ASSERT_LT(q, b * b) << "b " << b;  // the root lies below the balance's turning point
        // The balance itself, relative to the terms' size.
        EXPECT_NEAR((1.0 - q) / (-b * b * std::log(q)), 1.0, 1e-12) << "b " << b;
        EXPECT_GT(q, last) << "b " << b;
        last = q;
    }
    EXPECT_EQ(broken_share(0.2), 0.0);
    EXPECT_EQ(broken_share(0.1), 0.0);
    EXPECT_EQ(broken_share(1.0), 1.0);
    EXPECT_EQ(broken_share(2.0), 1.0);
    EXPECT_EQ(broken_share(std::nan("")), 0.0);
    // Near 1 the share nears 1; at b = 0.5 it is the fixed point of Q = exp(-4 (1 - Q)),
    // 0.0198274 (that iteration converges there: its slope is 4 Q, 0.08).
    EXPECT_GT(broken_share(0.99), 0.9);
    EXPECT_NEAR(broken_share(0.5), 0.0198274, 1e-7);
}

}  // namespace
}  // namespace tidewater::detail
