// Writing a saved bake's files (internal to Tidewater::bake); bake_files.hpp reads them.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tidewater/detail/bake_files.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

/// Writes `values` (nx by nz, rows along +z) as dir/name.png; returns its sidecar entry
/// (file, unit, zero_pixel, step, max_error).
Result<nlohmann::json> write_field_png(const std::filesystem::path& dir, const std::string& name,
                                       const std::vector<float>& values, int nx, int nz, const char* unit);

/// As write_field_png, the field's rows made by `row(j, values)` (nx values of row j) as
/// they are needed, twice (its range, then its pixels): a field held in another form is
/// written without a float copy of it.
Result<nlohmann::json> write_field_png_rows(const std::filesystem::path& dir, const std::string& name,
                                            const std::function<void(int, float*)>& row, int nx, int nz,
                                            const char* unit);

/// Rounds `values` to the encoding write_field_png would save them with, so a field that
/// other baked values were fitted to reads back from a saved bake as it was baked.
void round_to_saved_encoding(std::vector<float>& values);

/// Writes text to a file, failing with the path when it cannot.
Status write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace tidewater::detail
