// PNG reading and writing for heightmaps, baked fields and rendered frames
// (internal: the tools and tests use it; hosts read and write images their own way).
// Writes are atomic: a temporary file beside the target is renamed over it
// only when complete, so a failure never leaves a half-written image.
// Threading: reentrant.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
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

/// Writes RGBA8 pixels (row-major from the top row) as PNG.
Status write_png_rgba8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba);

/// Writes a 16-bit greyscale PNG (heightmaps, baked fields).
Status write_png_gray16(const std::filesystem::path& path, const Gray16Image& image);

}  // namespace tidewater::detail
