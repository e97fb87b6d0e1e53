// PNG I/O: stb (compiled in stb_implementation.cpp from Debian's libstb-dev headers) reads
// and writes 8-bit; libpng's simplified API writes 16-bit greyscale.
#include "tidewater/detail/image_io.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <png.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <unistd.h>

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

Result<Gray16Image> read_png_gray16(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::FILE* f = std::fopen(name.c_str(), "rb");
    if (!f) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    int w = 0, h = 0, channels = 0;
    const int ok = stbi_info_from_file(f, &w, &h, &channels);
    const bool is16 = ok && stbi_is_16_bit_from_file(f);
    if (!ok) {
        std::fclose(f);
        return Error{ErrorCode::parse_error, fmt::format("{}: not a readable image ({})", name, stbi_failure_reason())};
    }
    if (!is16 || channels != 1) {
        std::fclose(f);
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: expected a 16-bit greyscale PNG (found {} channel(s), {}-bit)", name,
                                 channels, is16 ? 16 : 8)};
    }
    if (w < 1 || h < 1 || static_cast<long long>(w) * h > (1LL << 28)) {
        std::fclose(f);
        return Error{ErrorCode::schema_error, fmt::format("{}: {}x{} pixels is out of range (1x1 to 2^28 pixels)", name, w, h)};
    }
    stbi_us* data = stbi_load_from_file_16(f, &w, &h, &channels, 1);
    std::fclose(f);
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
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(name.c_str(), &w, &h, &channels, 4);
    if (!data) {
        if (!std::filesystem::exists(path)) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
        return Error{ErrorCode::parse_error, fmt::format("{}: not a readable image ({})", name, stbi_failure_reason())};
    }
    Rgba8Image img;
    img.width = w;
    img.height = h;
    img.pixels.assign(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(data);
    return img;
}

Status write_png_rgba8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        return Error{ErrorCode::invalid_argument, fmt::format("{}: {}x{} RGBA needs {} bytes, got {}", path.string(),
                                                              width, height, std::size_t(width) * std::size_t(height) * 4, rgba.size())};
    }
    return write_atomically(path, [&](const std::string& temp) {
        return stbi_write_png(temp.c_str(), width, height, 4, rgba.data(), width * 4) != 0;
    });
}

Status write_png_gray16(const std::filesystem::path& path, const Gray16Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
        return Error{ErrorCode::invalid_argument, fmt::format("{}: image size and pixel count disagree", path.string())};
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
