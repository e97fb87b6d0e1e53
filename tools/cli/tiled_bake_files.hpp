// The files a tiled bake's steps pass to each other (tiled_bake.hpp): a tile's contour
// cells, the stitched shoreline and a tile's distances, each a little-endian binary file
// with a magic word, a version and the tile it belongs to. Reading refuses, naming the
// file and what is wrong, a file that is truncated, too long, of another tile or tiling,
// or holds values no bake makes (not finite, out of their cell or grid). Job-internal:
// the merge's output is an ordinary bake folder. Threading: reentrant.
#pragma once

#include <filesystem>

#include "tidewater/detail/tiled_shore.hpp"
#include "tidewater/result.hpp"

namespace tidewater::cli::tiled_files {

Status write_contour(const std::filesystem::path& path, const tiled::TileContour& contour);
Result<tiled::TileContour> read_contour(const std::filesystem::path& path, const tiled::ShoreTiling& tiling, int tile);

/// The stitched shoreline: its lines and counts (the field's grids are not kept).
Status write_shoreline(const std::filesystem::path& path, const ShoreField& stitched);
Result<ShoreField> read_shoreline(const std::filesystem::path& path, const tiled::ShoreTiling& tiling);

Status write_distances(const std::filesystem::path& path, const tiled::TileDistances& tile);
Result<tiled::TileDistances> read_distances(const std::filesystem::path& path, const tiled::ShoreTiling& tiling,
                                            int tile);

}  // namespace tidewater::cli::tiled_files
