#include "terrain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "host_device.h"
#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater::render::detail {

namespace {

/// A height's texel value in a texture over [lowest, highest].
std::uint16_t height_code(float height, double lowest, double highest) {
    return static_cast<std::uint16_t>(
        std::lround((static_cast<double>(height) - lowest) * (65535.0 / (highest - lowest))));
}

/// The terrain's height at texel (i, j) of the texture `grid` (its size, first texel centre
/// and texel). Where the texels are a heightmap's pixels and nothing is cut into it, the
/// pixel's own height: what Terrain::height_at gives at its centre, without the search.
float texel_height(const Terrain& terrain, const TerrainHeights& grid, std::uint32_t i, std::size_t j) {
    const auto* map = std::get_if<HeightmapTerrain>(&terrain.shape());
    if (map && terrain.cuts().empty() && grid.width == static_cast<std::uint32_t>(map->image->width) &&
        grid.height == static_cast<std::uint32_t>(map->image->height)) {
        const double raw = map->image->pixels[j * grid.width + i];
        return static_cast<float>(map->min_height + (map->max_height - map->min_height) * raw / 65535.0);
    }
    return static_cast<float>(terrain.height_at(grid.first + glm::dvec2(i, static_cast<double>(j)) * grid.texel));
}

}  // namespace

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
    t.first = first;
    std::vector<float> heights(static_cast<std::size_t>(t.width) * t.height);
    tidewater::detail::parallel_chunks(t.height, 8, 0, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j)
            for (std::uint32_t i = 0; i < t.width; ++i) heights[j * t.width + i] = texel_height(terrain, t, i, j);
    });
    const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
    t.lowest = static_cast<double>(*lo);
    t.highest = std::max(static_cast<double>(*hi), t.lowest + 1e-3);
    if (t.fade > 0.0) t.lowest = std::min(t.lowest, t.seabed);
    t.texels.resize(heights.size());
    for (std::size_t k = 0; k < heights.size(); ++k) t.texels[k] = height_code(heights[k], t.lowest, t.highest);
    return t;
}

std::optional<HeightTexturePatch> height_texture_patch(const TerrainHeights& sampled, const Terrain& before,
                                                       const Terrain& after) {
    const auto pixels = tidewater::detail::changed_pixels(before, after);
    if (!pixels) return std::nullopt;
    HeightTexturePatch patch;
    if (!*pixels) return patch;
    // The texels whose centres lie where the changed pixels reach (clamped: the texture's
    // outermost texels carry the edge on into the fade).
    const auto [lo, hi] = tidewater::detail::pixels_reach(std::get<HeightmapTerrain>(before.shape()), **pixels);
    auto first_texel = [](double x, double first, double texel, std::uint32_t n) {
        return static_cast<std::uint32_t>(std::clamp(std::floor((x - first) / texel), 0.0, n - 1.0));
    };
    auto last_texel = [](double x, double first, double texel, std::uint32_t n) {
        return static_cast<std::uint32_t>(std::clamp(std::ceil((x - first) / texel), 0.0, n - 1.0));
    };
    patch.i0 = first_texel(lo.x, sampled.first.x, sampled.texel.x, sampled.width);
    patch.j0 = first_texel(lo.y, sampled.first.y, sampled.texel.y, sampled.height);
    patch.width = last_texel(hi.x, sampled.first.x, sampled.texel.x, sampled.width) - patch.i0 + 1;
    patch.height = last_texel(hi.y, sampled.first.y, sampled.texel.y, sampled.height) - patch.j0 + 1;
    patch.texels.resize(static_cast<std::size_t>(patch.width) * patch.height);
    for (std::uint32_t j = 0; j < patch.height; ++j)
        for (std::uint32_t i = 0; i < patch.width; ++i) {
            const float h = texel_height(after, sampled, patch.i0 + i, patch.j0 + j);
            // Beyond the texture's range the whole texture is encoded anew.
            if (!(static_cast<double>(h) >= sampled.lowest && static_cast<double>(h) <= sampled.highest))
                return std::nullopt;
            patch.texels[static_cast<std::size_t>(j) * patch.width + i] =
                height_code(h, sampled.lowest, sampled.highest);
        }
    return patch;
}

}  // namespace tidewater::render::detail
