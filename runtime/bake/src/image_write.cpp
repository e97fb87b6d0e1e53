// PNG writing: stb writes 8-bit RGBA, libpng 16-bit greyscale a row at a time. Writes are
// atomic: a temporary file beside the target is renamed over it only when complete.
#include "tidewater/detail/image_write.hpp"

#include <fmt/format.h>
#include <png.h>
#include <stb/stb_image_write.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

#include "tidewater/detail/atomic_sibling.hpp"
#include "tidewater/detail/distance_texture_png.hpp"

namespace tidewater::detail {

namespace {

/// libpng's row writer into an open file; false on any libpng error (it longjmps here,
/// past nothing that needs destroying: `samples` belongs to the caller).
bool write_gray16_rows(std::FILE* file, int width, int height, const std::function<void(int, std::uint16_t*)>& row,
                       std::uint16_t* samples, bool smooth) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 16, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (smooth) {
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
        png_set_compression_level(png, 4);
    }
    png_write_info(png, info);
    png_set_swap(png);  // PNG stores 16-bit samples big-endian; ours are the host's (little-endian)
    for (int j = 0; j < height; ++j) {
        row(j, samples);
        png_write_row(png, reinterpret_cast<png_const_bytep>(samples));
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

/// Encodes with `encode(temp_path)` and renames onto `path` on success.
template <typename Encode>
Status write_atomically(const std::filesystem::path& path, const Encode& encode) {
    const std::filesystem::path temp = detail::temporary_sibling(path);
    if (!encode(temp.string())) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        return Error{ErrorCode::io_error, fmt::format("{}: cannot write PNG", path.string())};
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return Error{ErrorCode::io_error, fmt::format("{}: cannot replace file", path.string())};
    }
    return {};
}

}  // namespace

Status write_png_rgba8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba) {
    if (width <= 0 || height <= 0 ||
        rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {}x{} RGBA needs {} bytes, got {}", path.string(), width, height,
                                 std::size_t(width) * std::size_t(height) * 4, rgba.size())};
    }
    return write_atomically(path, [&](const std::string& temp) {
        return stbi_write_png(temp.c_str(), width, height, 4, rgba.data(), width * 4) != 0;
    });
}

Status write_png_gray16(const std::filesystem::path& path, const Gray16Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: image size and pixel count disagree", path.string())};
    }
    const auto width = static_cast<std::size_t>(image.width);
    return write_png_gray16_rows(path, image.width, image.height, [&](int j, std::uint16_t* samples) {
        std::copy_n(image.pixels.data() + static_cast<std::size_t>(j) * width, width, samples);
    });
}

Status write_png_gray16_rows(const std::filesystem::path& path, int width, int height,
                             const std::function<void(int, std::uint16_t*)>& row, bool smooth) {
    if (width <= 0 || height <= 0)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {}x{} is not an image", path.string(), width, height)};
    std::vector<std::uint16_t> samples(static_cast<std::size_t>(width));
    return write_atomically(path, [&](const std::string& temp) {
        std::FILE* file = std::fopen(temp.c_str(), "wb");
        if (!file) return false;
        const bool written = write_gray16_rows(file, width, height, row, samples.data(), smooth);
        return std::fclose(file) == 0 && written;
    });
}

Status write_distance_texture_png(const std::filesystem::path& path, const DistanceTexture& texture, double range) {
    if (!(std::isfinite(range) && range > 0.0))
        return Error{ErrorCode::invalid_argument, fmt::format("{}: range {} must be positive", path.string(), range)};
    const glm::uvec3 size = texture.size();
    const std::span<const float> d = texture.distances();
    return write_png_gray16_rows(path, static_cast<int>(size.x), static_cast<int>(size.y * size.z),
                                 [&](int row, std::uint16_t* samples) {
                                     const std::size_t k = static_cast<std::size_t>(row) / size.y;
                                     const std::size_t j = size.y - 1 - static_cast<std::size_t>(row) % size.y;
                                     for (std::size_t i = 0; i < size.x; ++i)
                                         samples[i] = texel_of_distance(d[i + size.x * (j + size.y * k)], range);
                                 });
}

}  // namespace tidewater::detail
