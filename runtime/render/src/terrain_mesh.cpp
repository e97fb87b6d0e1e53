#include "terrain_mesh.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace tidewater::render::detail {

TerrainMesh build_terrain_mesh(const Terrain& terrain, std::uint32_t cells) {
    TerrainMesh mesh;
    mesh.origin = terrain.extent_center();
    const double half = terrain.extent_half_size();
    const double step = 2.0 * half / cells;
    const std::uint32_t n = cells + 1;
    mesh.vertices.reserve(static_cast<std::size_t>(n) * n * 6);
    auto height = [&](double x, double z) { return terrain.height_at(mesh.origin + glm::dvec2(x, z)); };
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double x = -half + i * step, z = -half + j * step;
            const double h = height(x, z);
            // Central differences over one cell: the shading normal.
            const double dx = (height(x + step, z) - height(x - step, z)) / (2.0 * step);
            const double dz = (height(x, z + step) - height(x, z - step)) / (2.0 * step);
            const glm::dvec3 normal = glm::normalize(glm::dvec3(-dx, 1.0, -dz));
            for (double v : {x, h, z, normal.x, normal.y, normal.z}) mesh.vertices.push_back(static_cast<float>(v));
        }
    }
    mesh.indices.reserve(static_cast<std::size_t>(cells) * cells * 6);
    for (std::uint32_t j = 0; j < cells; ++j) {
        for (std::uint32_t i = 0; i < cells; ++i) {
            const std::uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            for (std::uint32_t idx : {a, c, b, b, c, d}) mesh.indices.push_back(idx);
        }
    }
    return mesh;
}

std::vector<float> sample_height_texture(const Terrain& terrain, std::uint32_t size) {
    const glm::dvec2 center = terrain.extent_center();
    const double half = terrain.extent_half_size();
    std::vector<float> heights(static_cast<std::size_t>(size) * size);
    for (std::uint32_t j = 0; j < size; ++j) {
        for (std::uint32_t i = 0; i < size; ++i) {
            const glm::dvec2 p =
                center + glm::dvec2(-half + (i + 0.5) * 2.0 * half / size, -half + (j + 0.5) * 2.0 * half / size);
            heights[static_cast<std::size_t>(j) * size + i] = static_cast<float>(terrain.height_at(p));
        }
    }
    return heights;
}

}  // namespace tidewater::render::detail
