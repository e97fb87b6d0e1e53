// The terrain's level of detail (private): CDLOD (Strugar 2009, "Continuous
// Distance-Dependent Level of Detail for Rendering Heightmaps"). An implicit quadtree over
// the region the terrain is drawn on; a node of level L is a patch of kTerrainPatchQuads²
// quads of finest_quad * 2^L. Each level is used out to a range that keeps a quad
// under kTerrainQuadPixels on screen, and its vertices slide onto the next level's grid
// over the last part of it (terrain.vert), so levels meet without cracks or pops.
// Threading: pure functions.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "host_device.h"

namespace tidewater::render::detail {

/// Screen size of a quad at the far end of its level's range, px.
inline constexpr double kTerrainQuadPixels = 2.0;
/// A level's range is at least this many of its node sides: neighbours then differ by at
/// most one level and a node's neighbours do not morph along their shared edge (the
/// bound is 2 sqrt(2) / 0.66 = 4.3).
inline constexpr double kTerrainRangeOverNode = 5.0;
/// Where a level's morph starts, as a fraction of the way from the previous range to its own.
inline constexpr double kTerrainMorphStart = 0.66;
/// The most nodes a frame draws (GpuTerrainNode instances per in-flight slot).
inline constexpr std::size_t kMaxTerrainNodes = 8192;
inline constexpr int kMaxTerrainLevels = 24;

/// What the selection needs of the terrain (TerrainUpload).
struct TerrainLodGrid {
    glm::dvec2 finest_quad{1.0};  ///< m along x and z: level 0's quad (the height texture's texel)
    glm::dvec2 grid_origin{0.0};  ///< world xz of a texel centre: level 0's vertices sit on them
    glm::dvec2 region_min{0.0};   ///< world xz the terrain is drawn over, m
    glm::dvec2 region_max{0.0};
    double lowest = 0.0;  ///< m: the band the ground lies in
    double highest = 0.0;
};

/// The view it is selected for.
struct TerrainLodView {
    glm::dvec3 camera{0.0};     ///< world, m
    glm::dvec2 origin{0.0};     ///< the render origin O, world xz, m
    glm::mat4 view_proj{1.0f};  ///< world relative to O to clip (reversed Z)
    double pixel_angle = 1e-3;  ///< radians per pixel at the centre of the view
};

/// The nodes to draw: whole patches, then for each quadrant (0: -x -z, 1: +x -z, 2: -x +z,
/// 3: +x +z) the patches of which only that quarter is drawn.
struct TerrainSelection {
    std::vector<gpu::GpuTerrainNode> nodes;  ///< whole, then quadrant 0, 1, 2, 3
    std::array<std::uint32_t, 5> first{};    ///< first node of each group
    std::array<std::uint32_t, 5> count{};
    int levels = 0;
    bool truncated = false;  ///< more than kMaxTerrainNodes were wanted; the rest are not drawn
};

/// The range of level L, m: beyond it a coarser level draws.
double terrain_lod_range(const TerrainLodGrid& grid, double pixel_angle, int level);

/// The LOD distance of a point: horizontal distance with the camera's height above or
/// below the ground's band (terrain.vert computes the same per vertex).
double terrain_lod_distance(const TerrainLodGrid& grid, const TerrainLodView& view, glm::dvec2 xz);

TerrainSelection select_terrain_nodes(const TerrainLodGrid& grid, const TerrainLodView& view);

/// Where terrain.vert puts vertex `grid` (0 to kTerrainPatchQuads along x and z) of
/// `node`: slid toward the next level's grid by its morph. xz relative to O, like the
/// node and `camera_xz` (the C++ twin of terrain.vert, for tests and tools).
glm::dvec2 terrain_vertex_xz(const gpu::GpuTerrainNode& node, glm::dvec2 grid, glm::dvec2 camera_xz);

}  // namespace tidewater::render::detail
