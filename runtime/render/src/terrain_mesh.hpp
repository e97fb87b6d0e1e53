// The terrain as GPU data (private): a height-field mesh and a height texture
// sampled from tidewater::Terrain, the same function the CPU queries use.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {

struct TerrainMesh {
    std::vector<float> vertices;         // per vertex: position xyz (relative to origin), normal xyz
    std::vector<std::uint32_t> indices;  // triangles
    glm::dvec2 origin{0.0};              // world xz of the mesh's (0, 0)
};

/// A grid of `cells` x `cells` quads over the terrain's extent.
TerrainMesh build_terrain_mesh(const Terrain& terrain, std::uint32_t cells);

/// Heights (m) on a `size` x `size` grid of texel centres over the extent, rows along z.
std::vector<float> sample_height_texture(const Terrain& terrain, std::uint32_t size);

}  // namespace tidewater::render::detail
