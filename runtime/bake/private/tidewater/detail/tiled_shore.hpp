// The shoreline bake in tiles, for a farm (docs/scale-out.md, "Tiled bakes"): the distance
// field's grid is cut into tiles x tiles square tiles, and
//   1. each tile's contour is extracted (extract_tile_contour): the cells of the contour
//      at the water level that lie in the tile;
//   2. one step stitches every tile's cells into the whole shoreline (stitch_shoreline):
//      chained, simplified and classified as bake_shore does in one piece;
//   3. each tile's exact signed distance, gradient and depth are baked against the whole
//      shoreline (bake_tile_distances), so that distances stay exact across tiles.
// assemble_shore_field puts the tiles together: the field bake_shore makes in one piece,
// value for value. The shore model is then marched over it once (bake_scene_on_shoreline):
// a wave's phase is carried in from where it enters the domain, so the march is not split.
// Internal to Tidewater::bake and its tools. Threading: every function is reentrant.
// Units: metres.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <span>
#include <vector>

#include "tidewater/detail/contour_cell.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::tiled {

/// Where the tiles lie: the distance field's grid over the terrain's extent, cut into
/// `tiles` x `tiles` squares of block() texels (a multiple of 32, the distance fill's
/// block, so that a tile is filled exactly as the whole grid is there).
struct ShoreTiling {
    int resolution = 0;  ///< Texels per side of the whole grid.
    int tiles = 0;       ///< Tiles per side.
    glm::dvec2 corner{0.0};
    double texel = 1.0;

    static constexpr int kBlockMultiple = 32;
    /// Fails unless 1 <= tiles and resolution (8 to 8192) is a multiple of 32 * tiles.
    static Result<ShoreTiling> over(const Terrain& terrain, int resolution, int tiles);

    int block() const { return resolution / tiles; }
    int count() const { return tiles * tiles; }
    /// Tile t's first texel, along x and z (tiles numbered in rows along +z).
    int first_i(int t) const { return (t % tiles) * block(); }
    int first_j(int t) const { return (t / tiles) * block(); }
    /// The whole grid as a field with no values (corner, texel, resolution).
    ShoreField grid() const;
};

struct TileContour {
    int tile = 0;
    std::vector<detail::ContourCell> cells;  ///< sorted by (j, i)
    std::size_t mixed_cells = 0;             ///< cells holding land and water (the noise check)
};

/// The cells of the contour at `water_level` in tile `tile` (cells whose lower-left texel
/// is the tile's). Fails naming where the terrain is not finite.
Result<TileContour> extract_tile_contour(const Terrain& terrain, double water_level, const ShoreTiling& tiling,
                                         int tile, unsigned threads);

/// Fails unless `contour` could be tile `tile`'s of `tiling`: its cells in the tile, edges
/// 0 to 3, points finite and in their cells, sorted. For contours read back from files.
Status check_tile_contour(const ShoreTiling& tiling, const TileContour& contour);

/// The whole shoreline from every tile's contour (one per tile, any order): the field's
/// shorelines, segment_count, simplify_tolerance, polygons and holes, its grids empty.
/// `simplify_tolerance` 0: half a texel, as bake_shore. Fails on a noisy terrain as bake_shore does.
Result<ShoreField> stitch_shoreline(const ShoreTiling& tiling, std::vector<TileContour> contours,
                                    double simplify_tolerance, unsigned threads);

/// A tile's exact signed distance, gradient and depth (block()^2 each, row-major); the
/// gradient as the unit vectors of the field's 16-bit angles (SharedDirections).
struct TileDistances {
    int tile = 0;
    std::vector<float> signed_distance, gradient_x, gradient_z, depth;
};

/// Tile `tile`'s distances against `shorelines` (the stitched ones): every texel's value is
/// the one bake_shore gives it over the whole grid.
Result<TileDistances> bake_tile_distances(const Terrain& terrain, double water_level, const ShoreTiling& tiling,
                                          int tile, const ShoreField& stitched, unsigned threads);

/// The whole field: `stitched`'s shoreline with every tile's grids in place, each tile got
/// from `tile(t)` in turn and let go once copied (a farm's merge holds one tile's files at a
/// time beside the field).
Result<ShoreField> assemble_shore_field(const ShoreTiling& tiling, ShoreField stitched,
                                        const std::function<Result<TileDistances>(int tile)>& tile);

/// The terrain the ocean's shore is baked over: the scene's, carved by its rivers (the
/// water bodies' bake, as bake_scene makes it).
Result<Terrain> shore_terrain(const Scene& scene);

/// bake_scene with the ocean's distance field given (assembled from tiles) instead of baked:
/// the lakes, rivers and the shore model are baked as bake_scene bakes them. Fails unless
/// the field covers the terrain's extent at the scene's distance resolution.
Result<std::shared_ptr<const Scene>> bake_scene_on_shoreline(const Scene& scene, const SceneBakeOptions& options,
                                                             std::shared_ptr<const ShoreField> shoreline);

}  // namespace tidewater::tiled
