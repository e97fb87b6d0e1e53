#include "surface_probe.hpp"

#include <algorithm>
#include <cmath>

namespace tidewater::editor {

namespace {

/// Height of what the ray can hit at xz: the water where there is water, else the terrain.
double surface_at(const Scene& scene, double time, glm::dvec2 xz, WorldPoint& water) {
    water = query_world_point(scene, time, xz);
    const double ground = scene.terrain.height_at(xz);
    return water.body.kind != BodyKind::none ? std::max(water.surface.height, ground) : ground;
}

}  // namespace

std::optional<ProbeHit> probe_ray(const Scene& scene, double time, glm::dvec3 origin, glm::dvec3 direction,
                                  double reach) {
    WorldPoint water;
    auto above = [&](double t) {
        const glm::dvec3 p = origin + t * direction;
        return p.y - surface_at(scene, time, {p.x, p.z}, water);
    };
    // March with steps that grow with distance (a pixel's footprint), then bisect.
    double t0 = 0.0, f0 = above(0.0);
    if (f0 <= 0.0) return std::nullopt;  // the eye is under the surface
    for (double t = 1.0; t < reach; t += std::max(1.0, 0.01 * t)) {
        const double f = above(t);
        if (f <= 0.0) {
            double lo = t0, hi = t;
            for (int i = 0; i < 40; ++i) {
                const double mid = 0.5 * (lo + hi);
                (above(mid) > 0.0 ? lo : hi) = mid;
            }
            ProbeHit hit;
            hit.point = origin + hi * direction;
            surface_at(scene, time, {hit.point.x, hit.point.z}, water);
            hit.water = water;
            hit.on_land = water.body.kind == BodyKind::none || !water.surface.wet;
            return hit;
        }
        t0 = t;
        f0 = f;
    }
    return std::nullopt;
}

}  // namespace tidewater::editor
