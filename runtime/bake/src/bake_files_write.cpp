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
    const FieldEncoding e = encoding_of(values);
    const std::string file = name + ".png";
    const auto width = static_cast<std::size_t>(nx);
    // Encoded a row at a time: a field of 8192² is written without a 128 MiB image of it.
    if (auto st = write_png_gray16_rows(
            dir / file, nx, nz,
            [&](int j, std::uint16_t* samples) {
                const float* in = values.data() + static_cast<std::size_t>(j) * width;
                for (std::size_t i = 0; i < width; ++i) samples[i] = e.encode(static_cast<double>(in[i]));
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
