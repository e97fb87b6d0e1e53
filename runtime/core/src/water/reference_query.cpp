// The scalar double path of the one water evaluation and Newton solver (the accuracy
// yardstick of the SIMD kernel), and the seed project's fixed-point loop (the
// benchmark baseline).
#include <array>

#include "kernel/kernel_waves.hpp"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/newton.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/query.hpp"
#include "water/body_at.hpp"
#include "water/open_sea_water.hpp"
#include "water/river_solve.hpp"
#include "water/shore_water.hpp"

namespace tidewater::reference {

SurfacePoint query_point(const WaterBody& body, double time, glm::dvec2 point) {
    const auto waves = detail::prepare_body_waves<double>(body, time);
    std::array<double, kMaxWaves> base{};
    detail::base_phases(waves, point.x, point.y, base.data(), 1);
    SurfacePoint o;
    detail::NewtonResult<double> r;
    const ShoreWaves* shore = body.shore() && !body.shore()->trivial() ? body.shore().get() : nullptr;
    double breaking = 0.0;
    std::array<double, detail::kFoamLags> lagged{};
    if (shore) {
        detail::ShoreWater<double> water(waves, *shore, &point.x, &point.y, base.data());
        r = detail::solve_rest_offset<true, double>(water, waves.tolerance, waves.radius);
        o.depth = shore_far_to_infinite(water.depth_at_point);
        o.shore_distance = shore_far_to_infinite(water.shore_distance_at_point);
        breaking = water.breaking;
        lagged = detail::lagged_jacobians(water.lagged(r.ex, r.ez));
    } else {
        detail::OpenSeaWater<double> water(waves, base.data());
        r = detail::solve_rest_offset<true, double>(water, waves.tolerance, waves.radius);
        lagged = detail::lagged_jacobians(water.lagged(r.ex, r.ez));
    }
    const detail::PointState<double> p = detail::point_state(r);
    o.height = waves.level + p.eta;
    o.wet = detail::surface_wet(o.height, waves.level, o.depth);
    o.normal = {p.nx, p.ny, p.nz};
    o.displacement = {p.disp_x, p.disp_z};
    o.velocity = {r.sums.vx, r.sums.vy, r.sums.vz};
    o.jacobian = p.jacobian;
    o.iterations = static_cast<int>(r.iterations);
    o.converged = r.converged != 0.0;
    o.foam = detail::surface_foam(breaking, p.jacobian, lagged, waves.whitecap_jacobian);
    return o;
}

WorldPoint query_world_point(const Scene& scene, double time, glm::dvec2 point) {
    const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
    const detail::WaterBodiesBake* bodies = scene.bake ? scene.bake->bodies.get() : nullptr;
    if (has_bodies && (bodies == nullptr || !scene.baked())) return WorldPoint{};
    const detail::BodyFinder finder(scene, bodies);
    const detail::PointBody at = finder.find(point);
    const detail::EvaluationKey key = finder.evaluation_key(at.evaluation);
    SurfacePoint surface;
    switch (key.kind) {
        case detail::EvaluationKind::land:
            surface = detail::land_surface(scene, point);
            break;
        case detail::EvaluationKind::ocean:
            surface = reference::query_point(scene.ocean, time, point);
            break;
        case detail::EvaluationKind::lake:
            surface = reference::query_point(scene.lakes[static_cast<std::size_t>(key.lake)].body, time, point);
            break;
        case detail::EvaluationKind::river: {
            detail::PreparedWaves<double> river_waves, still_waves;
            const auto in = detail::prepare_river_input<double>(scene, *bodies, key, time, river_waves, still_waves);
            detail::solve_river_batch<double>(in, &point, 1, &surface);
            break;
        }
    }
    return detail::world_point(scene, key, at, surface, at.flow);
}

void fixed_point_heights(const WaveSet& set, double local_time, std::span<const glm::dvec2> points,
                         std::span<double> heights) {
    const auto waves = detail::prepare_waves<double>(set, local_time, 0.0);
    std::array<double, kMaxWaves> base{};
    for (std::size_t p = 0; p < points.size() && p < heights.size(); ++p) {
        detail::base_phases(waves, points[p].x, points[p].y, base.data(), 1);
        const detail::OpenSeaWater<double> water(waves, base.data());
        // Four passes of x0 = p - d(x0), then eta(x0). (The original divided the
        // horizontal sum by the wave count, which is wrong.)
        double ex = 0.0, ez = 0.0;
        for (int it = 0; it < 4; ++it) {
            const auto s = water.evaluate<false>(ex, ez);
            ex = -s.dx;
            ez = -s.dz;
        }
        heights[p] = water.evaluate<false>(ex, ez).eta;
    }
}

double fixed_point_height(const WaveSet& set, double local_time, glm::dvec2 point) {
    double height = 0.0;
    fixed_point_heights(set, local_time, std::span<const glm::dvec2>(&point, 1), std::span<double>(&height, 1));
    return height;
}

}  // namespace tidewater::reference
