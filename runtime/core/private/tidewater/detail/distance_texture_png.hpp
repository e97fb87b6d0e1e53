// A distance texture as a 16-bit greyscale PNG (the scene's "distance_texture" volumes;
// docs/scene-format.md): `slices` slices stacked from the top, each size.x wide and
// size.y tall, slice k holding z index k and its top row the highest y. A pixel's value v
// is the distance range * (2 v / 65535 - 1), so 32768 is the surface within range / 65535.
// The reader is the runtime's; the writer (tools, tests) is Tidewater::bake's.
// Threading: reentrant.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>

#include "tidewater/clip_volume.hpp"

namespace tidewater::detail {

inline constexpr double kDistanceTextureLevels = 65535.0;

inline double distance_of_texel(std::uint16_t value, double range) {
    return range * (2.0 * value / kDistanceTextureLevels - 1.0);
}
inline std::uint16_t texel_of_distance(double distance, double range) {
    const double v = std::round((distance / range + 1.0) * 0.5 * kDistanceTextureLevels);
    return static_cast<std::uint16_t>(std::clamp(v, 0.0, kDistanceTextureLevels));
}

/// Fails, naming the file, for a PNG that is not 16-bit greyscale, whose height is not a
/// multiple of `slices`, or whose sides are outside DistanceTexture's (checked before the
/// pixels are read).
Result<std::shared_ptr<const DistanceTexture>> read_distance_texture_png(const std::filesystem::path& path,
                                                                         std::uint32_t slices, double range);

}  // namespace tidewater::detail
