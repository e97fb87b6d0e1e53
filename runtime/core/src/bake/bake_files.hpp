// The files of a saved bake (private), shared by the saved shore bakes and the saved
// lakes and rivers: JSON sidecars, and fields as 16-bit grey PNGs with their encoding in
// a sidecar entry: value = (pixel - zero_pixel) * step, so 0 is exact whenever the range
// holds it and every value is within step / 2 of the bake. Image row j is texel row j (+z).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "json_reader.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

inline constexpr const char* kFieldEncoding =
    "16-bit grey PNG, value = (pixel - zero_pixel) * step; image row j is texel row j (+z), samples at texel centres";

/// Writes `values` (nx by nz, rows along +z) as dir/name.png; returns its sidecar entry
/// (file, unit, zero_pixel, step, max_error).
Result<nlohmann::json> write_field_png(const std::filesystem::path& dir, const std::string& name, const std::vector<float>& values,
                                       int nx, int nz, const char* unit);

/// Reads and decodes the field `name` of the sidecar object `fields`, checking that its
/// image is nx by nz. Errors name the sidecar's JSON path or the image file.
Result<std::vector<float>> read_field_png(const std::filesystem::path& dir, const ObjectReader& fields, std::string_view name, int nx,
                                          int nz);

/// The step of a field read by read_field_png (for tolerances).
double field_png_step(const ObjectReader& fields, std::string_view name);

/// Reads and parses a sidecar and checks its "version" is `version`. Readers opened on
/// the result must not outlive it. Errors name the file (and the field).
Result<nlohmann::json> read_sidecar(const std::filesystem::path& path, int version);

/// Writes text to a file, failing with the path when it cannot.
Status write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace tidewater::detail
