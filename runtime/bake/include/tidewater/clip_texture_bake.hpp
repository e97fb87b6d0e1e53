// Distance textures from closed triangle meshes (Tidewater::bake): the clip volume of any
// shape, a concave one included (a hold with bulkheads, a catamaran's twin hulls), for
// ClipVolume::distance_texture and the scene's "distance_texture" volumes
// (`tidewater clip-texture` writes one from an OBJ file).
//
// Units: metres, the mesh's own frame. Threading: reentrant; a bake uses the library's
// workers (oneTBB).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "tidewater/clip_volume.hpp"
#include "tidewater/result.hpp"

namespace tidewater {

struct TriangleMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into vertices
};

/// Reads a Wavefront OBJ's vertices and faces (polygons fanned into triangles; normals,
/// texture coordinates and materials ignored). Fails naming the file for one that cannot
/// be read, has no faces, an index out of range or a coordinate that is not finite.
Result<TriangleMesh> read_obj_mesh(const std::filesystem::path& path);

/// The box a texture of `mesh` spans: its bounds grown by `margin` m on every side
/// (centre and half extents, the mesh's frame).
struct TextureBox {
    glm::dvec3 center{0.0};
    glm::dvec3 half_extents{0.0};
};
TextureBox texture_box(const TriangleMesh& mesh, double margin);

/// The signed distance to `mesh`'s surface at `size` samples spanning `box` (negative
/// inside: the mesh is closed, every edge shared by two faces; its winding does not
/// matter). Fails, naming what, for an empty, open or degenerate mesh, a box that is not
/// finite and positive, or sides outside DistanceTexture's.
Result<std::shared_ptr<const DistanceTexture>> bake_distance_texture(const TriangleMesh& mesh, const TextureBox& box,
                                                                     glm::uvec3 size);

}  // namespace tidewater
