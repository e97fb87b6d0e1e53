// The probe under the cursor: the first point where a ray meets the water or the
// terrain, found by marching the ray against the CPU query surface at the frame's time
// and bisecting the crossing, so it answers what the frame draws.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <tidewater/world_query.hpp>

namespace tidewater::editor {

struct ProbeHit {
    glm::dvec3 point{0.0};  ///< where the ray meets the surface, m
    WorldPoint water;       ///< the water there (body none on land)
    bool on_land = false;
};

/// The hit of the ray from `origin` along unit `direction`, within `reach` m.
std::optional<ProbeHit> probe_ray(const Scene& scene, double time, glm::dvec3 origin, glm::dvec3 direction,
                                  double reach = 20000.0);

}  // namespace tidewater::editor
