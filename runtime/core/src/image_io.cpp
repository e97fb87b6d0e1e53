// PNG reading: stb (compiled in stb_implementation.cpp from Debian's libstb-dev headers).
// The writers are Tidewater::bake's (image_write.cpp).
#include "tidewater/detail/image_io.hpp"

#include <fmt/format.h>
#include <stb/stb_image.h>

#include <cstdio>

namespace tidewater::detail {

Result<Gray16Image> read_png_gray16(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::FILE* f = std::fopen(name.c_str(), "rb");
    if (!f) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    return read_png_gray16(f, name);
}

Result<Gray16Image> read_png_gray16(std::FILE* f, const std::string& name) {
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
                     fmt::format("{}: expected a 16-bit greyscale PNG (found {} channel(s), {}-bit)", name, channels,
                                 is16 ? 16 : 8)};
    }
    if (w < 1 || h < 1 || static_cast<long long>(w) * h > (1LL << 28)) {
        std::fclose(f);
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {}x{} pixels is out of range (1x1 to 2^28 pixels)", name, w, h)};
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
        if (!std::filesystem::exists(path))
            return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
        return Error{ErrorCode::parse_error, fmt::format("{}: not a readable image ({})", name, stbi_failure_reason())};
    }
    Rgba8Image img;
    img.width = w;
    img.height = h;
    img.pixels.assign(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(data);
    return img;
}

}  // namespace tidewater::detail
