// Elevation rasters: whatever GDAL opens (GeoTIFF, ESRI ASCII grids, ...), read as heights
// and as depths, and headerless 16-bit heightmaps of a size the input's first bytes give.
// Bad rasters (not a raster, an unsupported type, over the pixel limit, all nodata) give
// an Error naming the file, before a large allocation.
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"
#include "tidewater/detail/elevation_raster.hpp"

namespace {
// Small enough that the fuzzer reaches the limit's checks with small inputs.
constexpr std::int64_t kFuzzMaxPixels = std::int64_t{1} << 20;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tidewater;
    const auto path = fuzz::scratch_file("fuzz.raster", fuzz::as_text(data, size));
    (void)detail::read_gdal_elevation(path, false, kFuzzMaxPixels);
    (void)detail::read_gdal_elevation(path, true, kFuzzMaxPixels);
    if (size >= 4) {
        // Width and height from the first bytes, as a scene's "raw16" keys give them.
        const int width = 1 + data[0] % 64, height = 1 + data[1] % 64;
        (void)detail::read_raw16(path, width, height, (data[2] & 1) != 0, kFuzzMaxPixels);
        (void)detail::read_raw16(path, 1 << 20, 1 << 20, false, kFuzzMaxPixels);  // over the limit
    }
    return 0;
}
