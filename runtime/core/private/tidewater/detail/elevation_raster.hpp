// Elevation rasters other than 16-bit PNG: what GDAL reads (GeoTIFF, ESRI ASCII grids and
// the other raster formats it knows) and raw 16-bit heightmaps. Each becomes the
// HeightmapTerrain every part of Tidewater samples. Errors name the file and why, and are
// found before anything the size of the raster is allocated.
// Threading: reentrant (GDAL's error handler is per thread).
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

/// The most pixels a terrain raster may have (16384² : a 16 km world at 1 m).
inline constexpr std::int64_t kMaxTerrainPixels = std::int64_t{1} << 28;

/// Heights read from a raster, in metres, before they are quantised.
struct ElevationGrid {
    int width = 0;
    int height = 0;
    /// Row-major; row 0 is the smallest z (the north edge of a north-up raster: x is east,
    /// y up, so z points south). nodata pixels already filled.
    std::vector<float> heights;
    /// Metres between pixel centres along x and z; 0 where the file has no georeference.
    glm::dvec2 pixel_size{0.0};
    std::size_t filled = 0;   ///< nodata pixels filled from their nearest valid neighbour.
    std::string coordinates;  ///< How the georeference was read, for messages and docs.
};

/// Reads band 1 of a raster GDAL can open. Integer and floating-point bands are accepted,
/// with the band's scale, offset and unit (metres or feet) applied. nodata (and NaN)
/// pixels take the value of the nearest valid pixel. Projected coordinates keep their
/// metres; geographic ones become local metres by an equirectangular projection about
/// the raster's centre latitude (spherical Earth, R = 6371008.8 m), for rasters up to
/// 5 degrees across. `depth` reads the values as depths, positive down.
Result<ElevationGrid> read_gdal_elevation(const std::filesystem::path& path, bool depth,
                                          std::int64_t max_pixels = kMaxTerrainPixels);

/// Reads a headerless raw 16-bit heightmap of width x height pixels (row 0 first),
/// little- or big-endian. The file's size must match exactly.
Result<Gray16Image> read_raw16(const std::filesystem::path& path, int width, int height, bool big_endian,
                               std::int64_t max_pixels = kMaxTerrainPixels);

/// Replaces every pixel `invalid` marks with the value of its nearest valid pixel (in
/// 4-connected steps; ties go to the first reached). Returns how many were filled; false
/// in `any_valid` when no pixel is valid (nothing is changed).
std::size_t fill_invalid(int width, int height, std::vector<float>& values, const std::vector<std::uint8_t>& invalid,
                         bool& any_valid);

/// Heights quantised to 16 bits over their own range (steps of range / 65535 m), as a
/// heightmap spanning `size` centred on `center`.
HeightmapTerrain quantise_heightmap(const ElevationGrid& grid, std::string file, glm::dvec2 size, glm::dvec2 center);

}  // namespace tidewater::detail
