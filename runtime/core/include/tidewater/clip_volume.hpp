// Clip volumes: where the water is removed. Inside one the renderer draws no water surface
// and no light through water (a boat's dry hold, a barge's hull, a submarine's hatch, a
// pool drained for a cutscene), and the queries report the surface there dry
// (SurfacePoint::wet = false, no submersion). A scene's volumes ("clip_volumes") stay put;
// a host passes moving ones per call (QueryOptions::clip_volumes, render::FrameInfo::
// clip_volumes); a float's hull clips by its shape (render::float_draws). Boxes, spheres,
// capsules, convex meshes (the planes of their faces) and signed-distance textures (any
// shape, a concave hold or a catamaran's hulls, sampled on a grid over a box).
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
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

/// A signed-distance texture: the distance to a volume's surface (m, negative inside)
/// sampled at size.x * size.y * size.z points spanning the volume's box from -half_extents
/// to +half_extents inclusive. Sample (i, j, k) lies at -h + 2h * (i, j, k) / (size - 1) in
/// the volume's frame and is distances[i + size.x * (j + size.y * k)]. Between samples the
/// distance is trilinear; outside the box it is the box's nearest point's plus the distance
/// to it. Made only by create, so a texture a volume holds is always valid; immutable, so
/// volumes (and threads) share it: the renderer uploads a texture again only when a frame's
/// volumes hold another one.
class DistanceTexture {
  public:
    static constexpr std::uint32_t kMinSide = 2, kMaxSide = 128;      ///< samples along each axis
    static constexpr std::size_t kMaxSamples = std::size_t{1} << 21;  ///< 128^3: 8 MiB of floats

    /// Fails, naming what, unless each side is kMinSide to kMaxSide, `distances` holds
    /// exactly their product of finite values within 1e5 m, and some sample is negative
    /// (a texture that is nowhere inside clips nothing).
    static Result<std::shared_ptr<const DistanceTexture>> create(glm::uvec3 size, std::vector<float> distances);

    glm::uvec3 size() const { return size_; }
    std::span<const float> distances() const { return distances_; }
    /// The distance at `local` (the volume's frame, m) for a box of `half_extents`.
    double distance(glm::dvec3 local, glm::dvec3 half_extents) const;

  private:
    DistanceTexture(glm::uvec3 size, std::vector<float> distances) : size_(size), distances_(std::move(distances)) {}
    glm::uvec3 size_;
    std::vector<float> distances_;
};

struct ClipVolume {
    enum class Shape {
        box,               ///< `half_extents` along the volume's axes, turned by `orientation`
        sphere,            ///< `radius` about `center`
        capsule,           ///< the points within `radius` of the segment from `center - axis` to
                           ///< `center + axis`, axis = orientation * (0, half_length, 0)
        convex,            ///< the points behind every one of `planes` (a convex mesh's faces)
        distance_texture,  ///< where `texture`, spanning the box of `half_extents`, is negative
    };
    /// The most planes a convex volume may have (host_device.h kMaxClipPlanesPerVolume).
    static constexpr std::size_t kMaxPlanes = 24;
    Shape shape = Shape::box;
    glm::dvec3 center{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< the volume's axes to world
    glm::dvec3 half_extents{0.5};                ///< box; the box a distance texture spans
    double radius = 0.5;                         ///< sphere, capsule
    double half_length = 0.5;                    ///< capsule: half the segment's length
    /// convex: in the volume's frame (relative to `center`, before `orientation`), each plane
    /// xyz its outward unit normal n and w its offset: inside where dot(n, local) < w for all.
    std::vector<glm::dvec4> planes = {};
    /// distance_texture: its samples, shared (the volume may be copied every frame for free).
    std::shared_ptr<const DistanceTexture> texture = nullptr;

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
    /// The volume where `texture`, spanning the box of `half_extents` about `center`, is negative.
    static ClipVolume distance_texture(glm::dvec3 center, glm::dvec3 half_extents,
                                       std::shared_ptr<const DistanceTexture> texture,
                                       glm::dquat orientation = {1.0, 0.0, 0.0, 0.0});
};

/// The signed distance from `p` to the volume's surface, m: negative inside (exact for the
/// sphere and capsule; the box's is exact outside and the distance to the nearest face
/// inside; a convex volume's is the distance to the nearest face inside and the largest
/// distance in front of a face outside, never more than the true distance; a distance
/// texture's is its samples' trilinear blend, as exact as they are).
double clip_distance(const ClipVolume& volume, glm::dvec3 p);

/// Whether `p` lies inside any of `volumes` (strictly: clip_distance < 0).
bool inside_any(std::span<const ClipVolume> volumes, glm::dvec3 p);

/// Fails unless every size is finite, positive and at most 1e5 m, the centre within 1e7 m
/// and the orientation a finite, non-zero quaternion (a convex volume: 4 to kMaxPlanes
/// planes with unit normals and offsets within 1e5 m; a distance texture: a texture and a
/// box as a box's); `context` names the volume.
Status validate(const ClipVolume& volume, const std::string& context);

}  // namespace tidewater
