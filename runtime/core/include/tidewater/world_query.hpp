// Queries of a whole scene: which water body a point is in (the ocean, a lake or a
// river), its surface there and its current, for gameplay, buoyancy and drift.
//
// Each point belongs to at most one body, from the baked rivers' texel fields and the
// lakes' extents; the ocean takes the rest where the terrain is below its level.
// - River: the river's falling surface with its preset's waves riding the current
//   (directions relative to downstream); velocity = current + orbital velocity.
// - Plume (still water where a river runs in): the lake's or ocean's waves, the river's
//   waves fading out and its current fading to nothing.
// - Lake: the lake's waves at its level, feeling its own shores.
// - Ocean: exactly what query_surface gives for the scene's ocean.
// Wakes ride the ocean and the lakes: the scene's boats (Scene::boats; boat i is emitter
// i for QueryOptions::exclude_emitter) and any QueryOptions::wakes. Rivers carry none.
// On land (no body) the result is the ocean's where the scene has one (as for
// query_surface, wet = false); in an inland scene it is the terrain: height = terrain
// height, depth 0, no waves, wet = false.
//
// Units: metres, seconds; heights are world y. SurfacePoint::depth is the still water
// column at the point: its body's rest surface minus the terrain (carved by the rivers),
// from the shore model within its coastal band, else from the terrain (< 0 on land).
// Threading: reentrant and deterministic, as query_surface; the scene is only read.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string_view>

#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

enum class BodyKind : std::uint8_t { none, ocean, lake, river };

/// A body of a scene: the ocean, Scene::lakes[index] or Scene::rivers[index].
struct BodyRef {
    BodyKind kind = BodyKind::none;
    int index = -1;  ///< into the scene's lakes or rivers (-1 for none and the ocean)
    bool operator==(const BodyRef&) const = default;
};

struct WorldPoint {
    /// The surface; its velocity is the current plus the waves' orbital velocity.
    SurfacePoint surface;
    BodyRef body;          ///< Where the point is; none on land.
    glm::dvec2 flow{0.0};  ///< The current alone (depth-averaged, x and z), m/s.
};

/// The name of a body of `scene`: "ocean", a lake's or river's name, "" for none.
std::string_view body_name(const Scene& scene, BodyRef body);

/// How light travels through a body's water (tidewater/water_optics.hpp): its preset's
/// optics, else its kind's default (Jerlov II for the ocean, 3C for lakes and rivers; none:
/// the ocean's).
WaterOptics optics_of(const Scene& scene, BodyRef body);

/// The water of `scene` at each point (x, z) at clock time `time` (each body's time
/// offset is added). A scene with lakes or rivers must be baked (Scene::baked()).
/// `out.size()` must equal `points.size()`.
Status query_world(const Scene& scene, double time, std::span<const glm::dvec2> points, std::span<WorldPoint> out,
                   const QueryOptions& options = {});

/// Single-point convenience wrapper of query_world (a default WorldPoint on error).
WorldPoint query_world_point(const Scene& scene, double time, glm::dvec2 point);

/// Whether a point in space lies under a body's surface, and how far under.
struct Submersion {
    BodyRef body;        ///< The body whose water is at the point's xz (query_world); none over land.
    double depth = 0.0;  ///< The surface's height there minus the point's y, m: > 0 under the surface.
    /// Under a body's surface: a body is there, its water stands above the terrain (wet) and
    /// the point lies below the surface.
    bool under = false;
};

/// The submersion of each point (x, y, z) of `scene` at clock time `time`, from query_world's
/// surface at the point's xz: the answer the renderer uses for its camera each frame
/// (render::RendererStats::camera), so a host that asks it of the same camera (or of the corners
/// of its near plane, render::near_plane_corners) switches its audio and post-processing on
/// the frame the picture changes. Wakes as in query_world. `out.size()` must equal
/// `points.size()`. Threading and errors as query_world.
Status query_submersion(const Scene& scene, double time, std::span<const glm::dvec3> points, std::span<Submersion> out,
                        const QueryOptions& options = {});

}  // namespace tidewater
