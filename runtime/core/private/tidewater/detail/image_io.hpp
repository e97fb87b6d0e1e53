// PNG reading for heightmaps, baked fields and reference frames (internal: hosts read
// images their own way). The writers are Tidewater::bake's (image_write.hpp).
// Threading: reentrant.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

/// An 8-bit RGBA image, row-major from the top row.
struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

/// Reads any PNG as 8-bit RGBA (rendered frames, reference images).
Result<Rgba8Image> read_png_rgba8(const std::filesystem::path& path);

/// Reads a 16-bit greyscale PNG. 8-bit, colour or corrupt files are errors naming the file.
Result<Gray16Image> read_png_gray16(const std::filesystem::path& path);
/// The same from a file already open for reading (closed here); `name` names it in errors.
Result<Gray16Image> read_png_gray16(std::FILE* file, const std::string& name);

}  // namespace tidewater::detail
