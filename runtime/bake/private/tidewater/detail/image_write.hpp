// PNG writing for baked fields, heightmaps and rendered frames (internal to
// Tidewater::bake; the tools and tests use it, hosts write images their own way).
// Writes are atomic: a temporary file beside the target is renamed over it only when
// complete, so a failure never leaves a half-written image. Threading: reentrant.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>

#include "tidewater/clip_volume.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

/// Writes RGBA8 pixels (row-major from the top row) as PNG.
Status write_png_rgba8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba);

/// Writes a 16-bit greyscale PNG (heightmaps, baked fields).
Status write_png_gray16(const std::filesystem::path& path, const Gray16Image& image);

/// Writes a 16-bit greyscale PNG of `width` x `height` samples a row at a time:
/// `row(j, samples)` fills row j (from the top) with its `width` samples, so that a large
/// field is written without an image of it in memory.
/// `smooth`: the rows are neighbouring rows of a smooth field (a baked grid), so each is
/// filtered against the one above (PNG's Up filter) and compressed at zlib level 4: on a
/// 4096² distance field three times faster than libpng's default choice, and as small.
Status write_png_gray16_rows(const std::filesystem::path& path, int width, int height,
                             const std::function<void(int, std::uint16_t*)>& row, bool smooth = false);

/// Writes a distance texture as the 16-bit PNG the scene's "distance_texture" volumes read
/// (distance_texture_png.hpp): its slices stacked from the top, the distances over
/// [-range, range] m (those beyond it clamped).
Status write_distance_texture_png(const std::filesystem::path& path, const DistanceTexture& texture, double range);

}  // namespace tidewater::detail
