// Writing a saved bake's files (internal to Tidewater::bake): fields as 16-bit grey PNGs
// in the encoding bake_files.hpp reads, and plain text files.
#include "tidewater/detail/bake_files_write.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "tidewater/detail/image_write.hpp"

namespace tidewater::detail {

namespace fs = std::filesystem;

namespace {

FieldEncoding encoding_of(const std::vector<float>& values) {
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return FieldEncoding::covering(values.empty() ? 0.0 : static_cast<double>(*lo),
                                   values.empty() ? 0.0 : static_cast<double>(*hi));
}

}  // namespace

void round_to_saved_encoding(std::vector<float>& values) {
    const FieldEncoding e = encoding_of(values);
    for (float& v : values) v = static_cast<float>(e.decode(e.encode(static_cast<double>(v))));
}

Result<nlohmann::json> write_field_png(const fs::path& dir, const std::string& name, const std::vector<float>& values,
                                       int nx, int nz, const char* unit) {
    if (values.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz))
        return Error{ErrorCode::internal,
                     fmt::format("field {}: {} values for a {}x{} grid", name, values.size(), nx, nz)};
    const auto width = static_cast<std::size_t>(nx);
    return write_field_png_rows(
        dir, name,
        [&](int j, float* out) { std::copy_n(values.data() + static_cast<std::size_t>(j) * width, width, out); }, nx,
        nz, unit);
}

Result<nlohmann::json> write_field_png_rows(const fs::path& dir, const std::string& name,
                                            const std::function<void(int, float*)>& row, int nx, int nz,
                                            const char* unit) {
    const auto width = static_cast<std::size_t>(std::max(nx, 0));
    std::vector<float> values(width);
    double lo = 0.0, hi = 0.0;
    for (int j = 0; j < nz; ++j) {
        row(j, values.data());
        const auto [row_lo, row_hi] = std::minmax_element(values.begin(), values.end());
        if (row_lo == values.end()) continue;
        lo = j == 0 ? static_cast<double>(*row_lo) : std::min(lo, static_cast<double>(*row_lo));
        hi = j == 0 ? static_cast<double>(*row_hi) : std::max(hi, static_cast<double>(*row_hi));
    }
    const FieldEncoding e = FieldEncoding::covering(lo, hi);
    const std::string file = name + ".png";
    // Encoded a row at a time: a field of 8192² is written without a 128 MiB image of it.
    if (auto st = write_png_gray16_rows(
            dir / file, nx, nz,
            [&](int j, std::uint16_t* samples) {
                row(j, values.data());
                for (std::size_t i = 0; i < width; ++i) samples[i] = e.encode(static_cast<double>(values[i]));
            },
            true);
        !st)
        return st.error();
    return nlohmann::json{
        {"file", file}, {"unit", unit}, {"zero_pixel", e.zero}, {"step", e.step}, {"max_error", 0.5 * e.step}};
}

Status write_text_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text << "\n";
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", path.string())};
    return {};
}

}  // namespace tidewater::detail
