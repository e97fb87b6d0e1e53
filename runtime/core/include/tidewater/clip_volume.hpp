// Clip volumes: where the water is removed. Inside one the renderer draws no water surface
// and no light through water (a boat's dry hold, a barge's hull, a submarine's hatch, a
// pool drained for a cutscene), and the queries report the surface there dry
// (SurfacePoint::wet = false, no submersion). A scene's volumes ("clip_volumes") stay put;
// a host passes moving ones per call (QueryOptions::clip_volumes, render::FrameInfo::
// clip_volumes); a float's hull clips by its shape (render::float_draws).
//
// The signed distance below is the one definition: shaders/clip_volumes.glsl is its GLSL
// twin, and a point is inside where it is negative.
//
// Units: metres, world frame (y up). Threading: plain values.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater {

struct ClipVolume {
    enum class Shape {
        box,      ///< `half_extents` along the volume's axes, turned by `orientation`
        sphere,   ///< `radius` about `center`
        capsule,  ///< the points within `radius` of the segment from `center - axis` to
                  ///< `center + axis`, axis = orientation * (0, half_length, 0)
    };
    Shape shape = Shape::box;
    glm::dvec3 center{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< the volume's axes to world
    glm::dvec3 half_extents{0.5};                ///< box
    double radius = 0.5;                         ///< sphere, capsule
    double half_length = 0.5;                    ///< capsule: half the segment's length

    static ClipVolume box(glm::dvec3 center, glm::dvec3 half_extents, glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
    static ClipVolume sphere(glm::dvec3 center, double radius);
    static ClipVolume capsule(glm::dvec3 center, double half_length, double radius,
                              glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
};

/// The signed distance from `p` to the volume's surface, m: negative inside (exact for the
/// sphere and capsule; the box's is exact outside and the distance to the nearest face inside).
double clip_distance(const ClipVolume& volume, glm::dvec3 p);

/// Whether `p` lies inside any of `volumes` (strictly: clip_distance < 0).
bool inside_any(std::span<const ClipVolume> volumes, glm::dvec3 p);

/// Fails unless every size is finite, positive and at most 1e5 m, the centre within 1e7 m
/// and the orientation a finite, non-zero quaternion; `context` names the volume.
Status validate(const ClipVolume& volume, const std::string& context);

}  // namespace tidewater
