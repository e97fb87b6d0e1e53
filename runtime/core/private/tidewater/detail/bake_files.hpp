// The files of a saved bake (internal; read here, written by Tidewater::bake's
// bake_files_write.hpp), shared by the saved shore bakes and the saved
// lakes and rivers: JSON sidecars, and fields as 16-bit grey PNGs with their encoding in
// a sidecar entry: value = (pixel - zero_pixel) * step, so 0 is exact whenever the range
// holds it and every value is within step / 2 of the bake. Image row j is texel row j (+z).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/detail/json_reader.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

inline constexpr const char* kFieldEncoding =
    "16-bit grey PNG, value = (pixel - zero_pixel) * step; image row j is texel row j (+z), samples at texel centres";

/// A field's encoding: value = (pixel - zero) * step. 0 is exact whenever the range holds it, and every
/// value in [lo, hi] is within step / 2.
struct FieldEncoding {
    double step = 1.0;
    std::int64_t zero = 0;

    static FieldEncoding covering(double lo, double hi) {
        FieldEncoding e;
        e.step = hi > lo ? (hi - lo) / 65534.0 : std::max(std::abs(lo), 1.0) / 65534.0;
        e.zero = std::llround(-lo / e.step);
        return e;
    }
    std::uint16_t encode(double v) const {
        return static_cast<std::uint16_t>(std::clamp<std::int64_t>(std::llround(v / step) + zero, 0, 65535));
    }
    double decode(std::uint16_t p) const { return static_cast<double>(static_cast<std::int64_t>(p) - zero) * step; }
};

/// Reads and decodes the field `name` of the sidecar object `fields`, checking that its
/// image is nx by nz. Errors name the sidecar's JSON path or the image file.
Result<std::vector<float>> read_field_png(const std::filesystem::path& dir, const ObjectReader& fields,
                                          std::string_view name, int nx, int nz);

/// The step of a field read by read_field_png (for tolerances).
double field_png_step(const ObjectReader& fields, std::string_view name);

/// Reads and parses a sidecar and checks its "version" is `version`. Readers opened on
/// the result must not outlive it. Errors name the file (and the field).
Result<nlohmann::json> read_sidecar(const std::filesystem::path& path, int version);

}  // namespace tidewater::detail
