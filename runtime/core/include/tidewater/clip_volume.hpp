// Clip volumes: where the water is removed. Inside one the renderer draws no water surface
// and no light through water (a boat's dry hold, a barge's hull, a submarine's hatch, a
// pool drained for a cutscene), and the queries report the surface there dry
// (SurfacePoint::wet = false, no submersion). A scene's volumes ("clip_volumes") stay put;
// a host passes moving ones per call (QueryOptions::clip_volumes, render::FrameInfo::
// clip_volumes); a float's hull clips by its shape (render::float_draws). Boxes, spheres,
// capsules and convex meshes (the planes of their faces).
//
// The signed distance below is the one definition: shaders/clip_volumes.glsl is its GLSL
// twin, and a point is inside where it is negative.
//
// Units: metres, world frame (y up). Threading: plain values.
#pragma once

#include <array>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

struct ClipVolume {
    enum class Shape {
        box,      ///< `half_extents` along the volume's axes, turned by `orientation`
        sphere,   ///< `radius` about `center`
        capsule,  ///< the points within `radius` of the segment from `center - axis` to
                  ///< `center + axis`, axis = orientation * (0, half_length, 0)
        convex,   ///< the points behind every one of `planes` (a convex mesh's faces)
    };
    /// The most planes a convex volume may have (host_device.h kMaxClipPlanesPerVolume).
    static constexpr std::size_t kMaxPlanes = 24;
    Shape shape = Shape::box;
    glm::dvec3 center{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< the volume's axes to world
    glm::dvec3 half_extents{0.5};                ///< box
    double radius = 0.5;                         ///< sphere, capsule
    double half_length = 0.5;                    ///< capsule: half the segment's length
    /// convex: in the volume's frame (relative to `center`, before `orientation`), each plane
    /// xyz its outward unit normal n and w its offset: inside where dot(n, local) < w for all.
    std::vector<glm::dvec4> planes = {};

    static ClipVolume box(glm::dvec3 center, glm::dvec3 half_extents, glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
    static ClipVolume sphere(glm::dvec3 center, double radius);
    static ClipVolume capsule(glm::dvec3 center, double half_length, double radius,
                              glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
    /// The convex volume behind `planes` (xyz an outward normal, normalised here; w its offset).
    static ClipVolume convex(glm::dvec3 center, std::vector<glm::dvec4> planes,
                             glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
    /// The convex volume a closed, convex, outward-wound triangle mesh bounds (`vertices` in
    /// the volume's frame, m): one plane per face, coplanar triangles merged. Fails, naming
    /// what, for a mesh that is open, concave, degenerate or of more than kMaxPlanes faces.
    static Result<ClipVolume> convex_mesh(glm::dvec3 center, std::span<const glm::dvec3> vertices,
                                          std::span<const std::array<std::uint32_t, 3>> triangles,
                                          glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
};

/// The signed distance from `p` to the volume's surface, m: negative inside (exact for the
/// sphere and capsule; the box's is exact outside and the distance to the nearest face
/// inside; a convex volume's is the distance to the nearest face inside and the largest
/// distance in front of a face outside, never more than the true distance).
double clip_distance(const ClipVolume& volume, glm::dvec3 p);

/// Whether `p` lies inside any of `volumes` (strictly: clip_distance < 0).
bool inside_any(std::span<const ClipVolume> volumes, glm::dvec3 p);

/// Fails unless every size is finite, positive and at most 1e5 m, the centre within 1e7 m
/// and the orientation a finite, non-zero quaternion (a convex volume: 4 to kMaxPlanes
/// planes with unit normals and offsets within 1e5 m); `context` names the volume.
Status validate(const ClipVolume& volume, const std::string& context);

}  // namespace tidewater
