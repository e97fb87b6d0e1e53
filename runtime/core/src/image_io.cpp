// PNG reading: stb (compiled in stb_implementation.cpp from Debian's libstb-dev headers).
// The writers are Tidewater::bake's (image_write.cpp).
#include "tidewater/detail/image_io.hpp"

#include <fmt/format.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>

namespace tidewater::detail {

namespace {

/// Pixels an image may hold: 2^28 (16384^2).
constexpr long long kMaxImagePixels = 1LL << 28;

std::uint32_t big_endian_u32(const unsigned char* b) {
    return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | std::uint32_t{b[3]};
}

/// The most bytes deflate can expand one compressed byte into.
constexpr long long kMaxDeflateRatio = 1032;

/// Bytes of filtered scanlines an IHDR's image decodes to (Adam7's passes add a filter
/// byte a row of each pass: 8 rows' worth at most), in double: the header's sides and
/// depth are whatever the file says.
double png_raw_bytes(const unsigned char* ihdr) {
    const double w = big_endian_u32(ihdr), h = big_endian_u32(ihdr + 4);
    const int depth = ihdr[8], colour = ihdr[9];
    const int channels = colour == 2 ? 3 : colour == 4 ? 2 : colour == 6 ? 4 : 1;
    return (h + 8.0) * (1.0 + std::ceil(w * channels * depth / 8.0));
}

/// Whether `f` is a PNG whose chunks all lie within the file, up to IEND, and whose pixels
/// could come from its compressed data: stb sizes its buffers by a chunk's declared length
/// and by the image's size before decoding, so a 100-byte file that declares a 1 GB chunk,
/// or a 2^28-pixel image, would allocate 1 GB. Leaves `f` at its start.
Status png_chunks_fit(std::FILE* f, const std::string& name) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    auto error = [&](const std::string& why) {
        return Error{ErrorCode::parse_error, fmt::format("{}: {}", name, why)};
    };
    if (std::fseek(f, 0, SEEK_END) != 0) return error("cannot read the file");
    const long size = std::ftell(f);
    std::rewind(f);
    unsigned char head[8];
    if (size < 8 || std::fread(head, 1, 8, f) != 8 || !std::equal(head, head + 8, kSignature))
        return error("not a readable image (no PNG signature)");
    long at = 8;
    long long compressed = 0;
    double raw = 0.0;
    for (;;) {
        unsigned char chunk[8];
        if (std::fread(chunk, 1, 8, f) != 8) return error("corrupt PNG (it ends before its IEND chunk)");
        const std::uint32_t length = big_endian_u32(chunk);
        if (length > 0x7FFFFFFFu || static_cast<long long>(at) + 12 + length > size)
            return error(fmt::format("corrupt PNG (a chunk at byte {} declares {} bytes, past the end of the file)", at,
                                     length));
        if (std::equal(chunk + 4, chunk + 8, "IEND")) break;
        if (std::equal(chunk + 4, chunk + 8, "IDAT")) {
            // stb copies the first IDAT's bytes into a buffer it has not made yet when the
            // chunk is empty; no encoder writes one.
            if (length == 0 && compressed == 0)
                return error(fmt::format("corrupt PNG (an empty IDAT chunk at byte {}, before any image data)", at));
            compressed += length;
        }
        unsigned char ihdr[13];
        if (at == 8 && std::equal(chunk + 4, chunk + 8, "IHDR") && length == 13) {
            if (std::fread(ihdr, 1, 13, f) != 13) return error("cannot read the file");
            raw = png_raw_bytes(ihdr);
        }
        at += 12 + static_cast<long>(length);
        if (std::fseek(f, at, SEEK_SET) != 0) return error("cannot read the file");
    }
    if (raw > static_cast<double>(kMaxDeflateRatio * compressed + 4096))
        return error(fmt::format("corrupt PNG (its pixels take {} bytes, more than its {} compressed bytes can hold)",
                                 raw, compressed));
    std::rewind(f);
    return {};
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using OpenFile = std::unique_ptr<std::FILE, FileCloser>;

/// A PNG's size and channels from its header, once its chunks are checked and before any
/// pixel is decoded.
struct PngHeader {
    int width = 0, height = 0, channels = 0;
    bool sixteen_bit = false;
};
Result<PngHeader> checked_png_header(std::FILE* f, const std::string& name) {
    if (auto fits = png_chunks_fit(f, name); !fits) return fits.error();
    PngHeader h;
    if (!stbi_info_from_file(f, &h.width, &h.height, &h.channels))
        return Error{ErrorCode::parse_error, fmt::format("{}: not a readable image ({})", name, stbi_failure_reason())};
    h.sixteen_bit = stbi_is_16_bit_from_file(f) != 0;
    return h;
}

Status check_pixels(const PngHeader& h, const std::string& name) {
    if (h.width < 1 || h.height < 1 || static_cast<long long>(h.width) * h.height > kMaxImagePixels)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {}x{} pixels is out of range (1x1 to 2^28 pixels)", name, h.width, h.height)};
    return {};
}

}  // namespace

Result<Gray16Image> read_png_gray16(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::FILE* f = std::fopen(name.c_str(), "rb");
    if (!f) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    return read_png_gray16(f, name);
}

Result<Gray16Image> read_png_gray16(std::FILE* f, const std::string& name) {
    const OpenFile file(f);
    auto header = checked_png_header(f, name);
    if (!header) return header.error();
    if (!header->sixteen_bit || header->channels != 1)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: expected a 16-bit greyscale PNG (found {} channel(s), {}-bit)", name,
                                 header->channels, header->sixteen_bit ? 16 : 8)};
    if (auto st = check_pixels(*header, name); !st) return st.error();
    int w = 0, h = 0, channels = 0;
    stbi_us* data = stbi_load_from_file_16(f, &w, &h, &channels, 1);
    if (!data) return Error{ErrorCode::parse_error, fmt::format("{}: corrupt PNG ({})", name, stbi_failure_reason())};
    Gray16Image img;
    img.width = w;
    img.height = h;
    img.pixels.assign(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    stbi_image_free(data);
    return img;
}

Result<Rgba8Image> read_png_rgba8(const std::filesystem::path& path) {
    const std::string name = path.string();
    const OpenFile file(std::fopen(name.c_str(), "rb"));
    if (!file) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    auto header = checked_png_header(file.get(), name);
    if (!header) return header.error();
    if (auto st = check_pixels(*header, name); !st) return st.error();
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load_from_file(file.get(), &w, &h, &channels, 4);
    if (!data) return Error{ErrorCode::parse_error, fmt::format("{}: corrupt PNG ({})", name, stbi_failure_reason())};
    Rgba8Image img;
    img.width = w;
    img.height = h;
    img.pixels.assign(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(data);
    return img;
}

}  // namespace tidewater::detail
