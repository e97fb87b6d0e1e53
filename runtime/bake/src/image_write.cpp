// PNG writing: stb writes 8-bit RGBA, libpng's simplified API 16-bit greyscale. Writes are
// atomic: a temporary file beside the target is renamed over it only when complete.
#include "tidewater/detail/image_write.hpp"

#include <fmt/format.h>
#include <png.h>
#include <stb/stb_image_write.h>
#include <unistd.h>

#include <cstdio>

namespace tidewater::detail {

namespace {

/// Encodes with `encode(temp_path)` and renames onto `path` on success.
template <typename Encode>
Status write_atomically(const std::filesystem::path& path, const Encode& encode) {
    std::filesystem::path temp = path;
    temp += fmt::format(".tmp-{}", ::getpid());
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
    return write_atomically(path, [&](const std::string& temp) {
        png_image png{};
        png.version = PNG_IMAGE_VERSION;
        png.width = static_cast<png_uint_32>(image.width);
        png.height = static_cast<png_uint_32>(image.height);
        png.format = PNG_FORMAT_LINEAR_Y;  // one 16-bit channel, samples written as given
        const int ok = png_image_write_to_file(&png, temp.c_str(), 0, image.pixels.data(), 0, nullptr);
        png_image_free(&png);
        return ok != 0;
    });
}

}  // namespace tidewater::detail
