// Heave, pitch and roll of a hull on the surface.
#include <cmath>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

TEST(FloatingBody, StillWaterIsLevel) {
    const WaterBody body = test::make_body({}, 1.5);
    FloatingBody hull = FloatingBody::four_point(12.0, 4.0);
    hull.position = {10.0, -3.0};
    auto att = hull_attitude(body, hull, 7.0);
    ASSERT_TRUE(att.ok());
    EXPECT_NEAR(att->heave, 1.5, 1e-12);
    EXPECT_NEAR(att->pitch, 0.0, 1e-12);
    EXPECT_NEAR(att->roll, 0.0, 1e-12);
}

// A long wave (lambda = 400 m) along +x under a 4 m hull: the hull follows the local
// slope. Heading 0: pitch = atan(slope) within 2%; heading 90: the same slope is roll.
TEST(FloatingBody, FollowsTheLocalSlope) {
    const double lambda = 400.0, a = 3.0, k = kTwoPi / lambda;
    const WaterBody body = test::make_body({{0.0, lambda, a, 0.0, 0.0}});
    // At t = 0, x = 0: theta = 0, the surface rises toward +x with slope k*A.
    FloatingBody hull = FloatingBody::four_point(4.0, 2.0);
    auto att = hull_attitude(body, hull, 0.0);
    ASSERT_TRUE(att.ok());
    EXPECT_NEAR(att->pitch, std::atan(k * a), 0.02 * std::atan(k * a));  // bow (+x) up
    EXPECT_NEAR(att->roll, 0.0, 1e-6);
    EXPECT_NEAR(att->heave, 0.0, 1e-3);

    hull.heading_deg = 90.0;  // bow toward +z, starboard toward -x
    att = hull_attitude(body, hull, 0.0);
    ASSERT_TRUE(att.ok());
    EXPECT_NEAR(att->pitch, 0.0, 1e-6);
    // Starboard lies toward -x, which is lower: starboard down is positive roll.
    EXPECT_NEAR(att->roll, std::atan(k * a), 0.02 * std::atan(k * a));
}

TEST(FloatingBody, RejectsDegenerateHulls) {
    const WaterBody body = test::make_body({}, 0.0);
    FloatingBody hull;
    hull.hull_points = {{1, 0}, {-1, 0}};
    auto att = hull_attitude(body, hull, 0.0);
    ASSERT_FALSE(att.ok());
    EXPECT_NE(att.error().message.find("at least 3"), std::string::npos);
    hull.hull_points = {{1, 0}, {-1, 0}, {3, 0}};
    att = hull_attitude(body, hull, 0.0);
    ASSERT_FALSE(att.ok());
    EXPECT_NE(att.error().message.find("collinear"), std::string::npos);
    hull.hull_points = {{1, 0}, {-1, 0}, {0, std::nan("")}};
    EXPECT_FALSE(hull_attitude(body, hull, 0.0).ok());
}

}  // namespace
}  // namespace tidewater
