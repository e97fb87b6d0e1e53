#include "tidewater/floating_body.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tidewater/constants.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {

FloatingBody FloatingBody::four_point(double length, double beam) {
    FloatingBody b;
    b.hull_points = {{0.5 * length, 0.0}, {-0.5 * length, 0.0}, {0.0, -0.5 * beam}, {0.0, 0.5 * beam}};
    return b;
}

namespace {

/// The hull points in world xz, or an error naming a bad one.
Result<std::vector<glm::dvec2>> hull_world_points(const FloatingBody& hull) {
    const std::size_t n = hull.hull_points.size();
    if (n < 3) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("floating body: {} hull points given, at least 3 needed", n)};
    }
    const double rad = hull.heading_deg * (kPi / 180.0);
    const glm::dvec2 forward{std::cos(rad), std::sin(rad)};
    const glm::dvec2 starboard{-forward.y, forward.x};  // +z when heading along +x
    std::vector<glm::dvec2> world(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 b = hull.hull_points[i];
        if (!std::isfinite(b.x) || !std::isfinite(b.y)) {
            return Error{ErrorCode::invalid_argument, fmt::format("floating body: hull point {} is not finite", i)};
        }
        world[i] = hull.position + b.x * forward + b.y * starboard;
    }
    return world;
}

/// The plane through the surface heights under the hull points.
Result<HullAttitude> fit_attitude(const FloatingBody& hull, const std::vector<double>& heights) {
    const std::size_t n = hull.hull_points.size();
    // Least squares for y = h + a*x + b*z in the body frame: 3x3 normal equations.
    double sxx = 0, sxz = 0, szz = 0, sx = 0, sz = 0, sy = 0, sxy = 0, szy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = hull.hull_points[i].x, z = hull.hull_points[i].y, y = heights[i];
        sxx += x * x;
        sxz += x * z;
        szz += z * z;
        sx += x;
        sz += z;
        sy += y;
        sxy += x * y;
        szy += z * y;
    }
    const double m[3][3] = {{static_cast<double>(n), sx, sz}, {sx, sxx, sxz}, {sz, sxz, szz}};
    const double rhs[3] = {sy, sxy, szy};
    auto det3 = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det3(m);
    const double span = sxx + szz;
    if (!(std::abs(d) > 1e-12 * span * span * static_cast<double>(n))) {
        return Error{ErrorCode::invalid_argument,
                     "floating body: hull points are collinear; a plane needs spread in both axes"};
    }
    double sol[3];
    for (int c = 0; c < 3; ++c) {
        double mc[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) mc[r][k] = k == c ? rhs[r] : m[r][k];
        sol[c] = det3(mc) / d;
    }
    HullAttitude att;
    att.heave = sol[0];
    att.pitch = std::atan(sol[1]);  // bow (+x) higher -> positive pitch
    att.roll = std::atan(-sol[2]);  // starboard (+z) lower -> positive roll
    return att;
}

}  // namespace

Result<HullAttitude> hull_attitude(const WaterBody& body, const FloatingBody& hull, double time) {
    auto world = hull_world_points(hull);
    if (!world) return world.error();
    std::vector<double> heights(world->size());
    if (auto st = query_heights(body, time, *world, heights); !st) return st.error();
    return fit_attitude(hull, heights);
}

Result<HullAttitude> hull_attitude(const Scene& scene, const FloatingBody& hull, double time) {
    auto world = hull_world_points(hull);
    if (!world) return world.error();
    std::vector<WorldPoint> water(world->size());
    if (auto st = query_world(scene, time, *world, water); !st) return st.error();
    std::vector<double> heights(world->size());
    glm::dvec2 current{0.0};
    for (std::size_t i = 0; i < water.size(); ++i) {
        heights[i] = water[i].surface.height;
        current += water[i].flow;
    }
    auto att = fit_attitude(hull, heights);
    if (att) att->current = current / static_cast<double>(water.size());
    return att;
}

}  // namespace tidewater
