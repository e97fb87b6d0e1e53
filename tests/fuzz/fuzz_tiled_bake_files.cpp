// The files a tiled bake's steps pass each other (tools/cli/tiled_bake_files.hpp): a tile's
// contour cells, the stitched shoreline, a tile's distances. The first byte picks the
// kind and the tile of a 2 x 2 tiling over 256 texels; any bytes give the contents or an
// Error naming the file, never a crash, a hang or an allocation past the file's own size.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_files.hpp"
#include "tidewater/terrain.hpp"
#include "tiled_bake_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tidewater;
    if (size == 0) return 0;
    static const tiled::ShoreTiling tiling = [] {
        return tiled::ShoreTiling::over(Terrain(FlatTerrain{}), 256, 2).value();
    }();
    const int kind = data[0] % 3, tile = (data[0] / 3) % 4;
    const auto path =
        fuzz::scratch_file("tile.bin", std::string_view(reinterpret_cast<const char*>(data + 1), size - 1));
    if (kind == 0) (void)cli::tiled_files::read_contour(path, tiling, tile);
    if (kind == 1) (void)cli::tiled_files::read_shoreline(path, tiling);
    if (kind == 2) (void)cli::tiled_files::read_distances(path, tiling, tile);
    return 0;
}
