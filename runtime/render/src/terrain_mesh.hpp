// The terrain as GPU data (private): the one patch every level-of-detail node draws
// (terrain_lod.hpp), and the terrain's heights as a 16-bit texture sampled from
// tidewater::Terrain, the function the CPU queries use.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {

/// kTerrainPatchQuads² quads: vertices in grid units (0 to kTerrainPatchQuads along x and
/// z), triangles listed quadrant by quadrant (0: -x -z, 1: +x -z, 2: -x +z, 3: +x +z) so
/// that a node can draw one quarter.
struct TerrainPatch {
    std::vector<glm::vec2> vertices;
    std::vector<std::uint32_t> indices;
    std::uint32_t quadrant_indices = 0;  ///< indices of one quadrant
};
TerrainPatch build_terrain_patch();

/// Heights on a grid of texel centres, stored as 16-bit values over [lowest, highest].
/// A heightmap's texels sit on its own pixel centres (every pixel, unless the memory it
/// may take says fewer); a procedural terrain is sampled at kProceduralTexels² over its
/// extent.
struct TerrainHeights {
    std::uint32_t width = 0, height = 0;          ///< texels
    glm::dvec2 corner{0.0};                       ///< world xz of the texture's outer corner, m
    glm::dvec2 first{0.0};                        ///< world xz of its first texel's centre, m
    glm::dvec2 texel{1.0};                        ///< m along x and z
    double lowest = 0.0, highest = 1.0;           ///< m: texel values 0 and 65535
    std::vector<std::uint16_t> texels;            ///< rows along +z
    double fade = 0.0;                            ///< m beyond the outermost texel centres (0: the edge extends)
    double seabed = 0.0;                          ///< m, where the fade ends
    glm::dvec2 region_min{0.0}, region_max{0.0};  ///< world xz the terrain is drawn over
    /// Bytes of the texture.
    std::uint64_t bytes() const { return 2ull * width * height; }
};

inline constexpr std::uint32_t kProceduralTexels = 2048;

/// Samples the terrain (with its cuts). The texture takes at most `max_bytes` (a
/// heightmap is then sampled on every k-th pixel centre, k as small as fits).
TerrainHeights sample_terrain_heights(const Terrain& terrain, std::uint64_t max_bytes);

/// The texels of a height texture that an edit changes, sampled and encoded as
/// sample_terrain_heights does over the texture's own height range: `width` x `height`
/// texels from (i0, j0), rows along +z (none: nothing changed).
struct HeightTexturePatch {
    std::uint32_t i0 = 0, j0 = 0, width = 0, height = 0;
    std::vector<std::uint16_t> texels;
};

/// The patch that takes `sampled` (sample_terrain_heights of `before`, its texels not
/// needed) to `after`, when `after` is `before`'s heightmap with pixels changed and every
/// changed height lies within the texture's range. nullopt otherwise: sample it anew.
std::optional<HeightTexturePatch> height_texture_patch(const TerrainHeights& sampled, const Terrain& before,
                                                       const Terrain& after);

}  // namespace tidewater::render::detail
