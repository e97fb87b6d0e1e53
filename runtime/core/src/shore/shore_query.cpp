#include "shore_query.hpp"

#include <algorithm>
#include <cmath>

namespace tidewater {

double crest_foam(double jacobian) {
    const double t = std::clamp((0.75 - jacobian) / 0.4, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace tidewater

namespace tidewater::detail {

void solve_points_shore(const WaterBody& body, const ShoreWaves& shore, double local_time, const glm::dvec2* points,
                        std::size_t n, SurfacePoint* full, double* heights) {
    const WaveSet& set = body.waves();
    const double radius = set.max_horizontal_displacement() * 1.001 + 1e-6;
    constexpr int kMaxIterations = 60;
    for (std::size_t q = 0; q < n; ++q) {
        const glm::dvec2 p = points[q];
        glm::dvec2 x0 = p;
        LocalShore local;
        LagrangianSample s;
        glm::dvec2 step{0.0}, last_x0 = x0;
        double last_f2 = 1e300;
        int it = 0;
        bool converged = false;
        for (; it < kMaxIterations; ++it) {
            s = evaluate_lagrangian_shore(set, shore, x0, local_time, &local);
            const glm::dvec2 f = x0 + glm::dvec2(s.displacement.x, s.displacement.z) - p;
            const double f2 = f.x * f.x + f.y * f.y;
            // The Newton step from this evaluation: the results below are carried along it.
            const double det = s.jxx * s.jzz - s.jxz * s.jxz;
            step = {(s.jxz * f.y - s.jzz * f.x) / det, (s.jxz * f.x - s.jxx * f.y) / det};
            if (f2 < 1e-12) {
                converged = true;
                ++it;
                break;
            }
            // Near the waterline the shore fields change within a texel and Newton (which
            // treats them as constant) can overshoot: step back halfway when |F| grows.
            if (f2 > last_f2) {
                x0 = 0.5 * (x0 + last_x0);
                step = glm::dvec2(0.0);
                continue;
            }
            last_f2 = f2;
            last_x0 = x0;
            x0 += step;
            const glm::dvec2 e = x0 - p;
            const double r2 = e.x * e.x + e.y * e.y;
            if (r2 > radius * radius) x0 = p + e * (radius / std::sqrt(r2));
        }
        const double height = body.level() + s.displacement.y + s.slope.x * step.x + s.slope.y * step.y;
        if (heights) {
            heights[q] = height;
            continue;
        }
        SurfacePoint& o = full[q];
        o.height = height;
        o.normal = s.normal;
        o.velocity = s.velocity;
        o.jacobian = s.jacobian;
        o.displacement = p - (x0 + step);
        o.iterations = it;
        o.converged = converged;
        o.depth = local.depth;
        o.shore_distance = local.shore_distance;
        o.foam = std::max(local.breaking, crest_foam(s.jacobian));
    }
}

}  // namespace tidewater::detail
