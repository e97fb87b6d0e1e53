#include "terrain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "host_device.h"
#include "tidewater/detail/parallel.hpp"

namespace tidewater::render::detail {

TerrainPatch build_terrain_patch() {
    constexpr std::uint32_t p = gpu::kTerrainPatchQuads, n = p + 1, half = p / 2;
    TerrainPatch patch;
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) patch.vertices.emplace_back(static_cast<float>(i), static_cast<float>(j));
    for (std::uint32_t q = 0; q < 4; ++q) {
        const std::uint32_t i0 = (q & 1u) * half, j0 = (q >> 1) * half;
        for (std::uint32_t j = j0; j < j0 + half; ++j)
            for (std::uint32_t i = i0; i < i0 + half; ++i) {
                const std::uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
                for (std::uint32_t idx : {a, c, b, b, c, d}) patch.indices.push_back(idx);
            }
    }
    patch.quadrant_indices = static_cast<std::uint32_t>(patch.indices.size() / 4);
    return patch;
}

TerrainHeights sample_terrain_heights(const Terrain& terrain, std::uint64_t max_bytes) {
    TerrainHeights t;
    glm::dvec2 first{0.0};  // world xz of the first texel centre
    if (const auto* map = std::get_if<HeightmapTerrain>(&terrain.shape())) {
        // Every k-th pixel centre, k the smallest whose texture fits.
        const std::uint32_t w = static_cast<std::uint32_t>(map->image->width),
                            h = static_cast<std::uint32_t>(map->image->height);
        std::uint32_t k = 1;
        auto texels = [&](std::uint32_t pixels) { return (pixels - 2) / k + 2; };
        while (k < 64 && 2ull * texels(w) * texels(h) > max_bytes) ++k;
        t.width = texels(w);
        t.height = texels(h);
        t.texel = map->size / glm::dvec2(t.width - 1, t.height - 1);
        first = map->center - 0.5 * map->size;
        const HeightmapEdgeFade fade = heightmap_edge_fade(*map);
        t.fade = fade.distance;
        t.seabed = fade.seabed;
        t.region_min = first - glm::dvec2(fade.distance);
        t.region_max = map->center + 0.5 * map->size + glm::dvec2(fade.distance);
    } else {
        const double half = terrain.extent_half_size();
        t.width = t.height = kProceduralTexels;
        t.texel = glm::dvec2(2.0 * half / kProceduralTexels);
        first = terrain.extent_center() - glm::dvec2(half) + 0.5 * t.texel;
        t.region_min = terrain.extent_center() - glm::dvec2(half);
        t.region_max = terrain.extent_center() + glm::dvec2(half);
    }
    t.corner = first - 0.5 * t.texel;
    std::vector<float> heights(static_cast<std::size_t>(t.width) * t.height);
    tidewater::detail::parallel_chunks(t.height, 8, 0, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j)
            for (std::uint32_t i = 0; i < t.width; ++i)
                heights[j * t.width + i] =
                    static_cast<float>(terrain.height_at(first + glm::dvec2(i, static_cast<double>(j)) * t.texel));
    });
    const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
    t.lowest = static_cast<double>(*lo);
    t.highest = std::max(static_cast<double>(*hi), t.lowest + 1e-3);
    if (t.fade > 0.0) t.lowest = std::min(t.lowest, t.seabed);
    const double to_code = 65535.0 / (t.highest - t.lowest);
    t.texels.resize(heights.size());
    for (std::size_t k = 0; k < heights.size(); ++k)
        t.texels[k] = static_cast<std::uint16_t>(std::lround((static_cast<double>(heights[k]) - t.lowest) * to_code));
    return t;
}

}  // namespace tidewater::render::detail
