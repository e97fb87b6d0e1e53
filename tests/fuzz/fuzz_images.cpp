// PNG images: 16-bit greyscale heightmaps (read_png_gray16), any PNG as RGBA (reference
// frames), and distance textures (16-bit slices stacked down the image). Corrupt,
// truncated and oversized images give an Error naming the file, before a large allocation.
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "fuzz_files.hpp"
#include "tidewater/detail/distance_texture_png.hpp"
#include "tidewater/detail/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tidewater;
    const auto path = fuzz::scratch_file("fuzz.png", fuzz::as_text(data, size));
    (void)detail::read_png_gray16(path);
    (void)detail::read_png_rgba8(path);
    // A distance texture of 1, 2 or 4 slices, as a clip volume's file may ask.
    const std::uint32_t slices = size > 0 ? 1u << (data[size - 1] % 3) : 1u;
    (void)detail::read_distance_texture_png(path, slices, 2.5);
    return 0;
}
