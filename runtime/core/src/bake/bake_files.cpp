#include "bake/bake_files.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>

#include "tidewater/detail/image_io.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

namespace {

namespace fs = std::filesystem;

/// value = (pixel - zero) * step. 0 is exact whenever the range holds it, and every
/// value in [lo, hi] is within step / 2.
struct Encoding {
    double step = 1.0;
    std::int64_t zero = 0;

    static Encoding covering(double lo, double hi) {
        Encoding e;
        e.step = hi > lo ? (hi - lo) / 65534.0 : std::max(std::abs(lo), 1.0) / 65534.0;
        e.zero = std::llround(-lo / e.step);
        return e;
    }
    std::uint16_t encode(double v) const {
        return static_cast<std::uint16_t>(std::clamp<std::int64_t>(std::llround(v / step) + zero, 0, 65535));
    }
    double decode(std::uint16_t p) const { return static_cast<double>(static_cast<std::int64_t>(p) - zero) * step; }
};

}  // namespace

Result<nlohmann::json> write_field_png(const fs::path& dir, const std::string& name, const std::vector<float>& values, int nx, int nz,
                                       const char* unit) {
    if (values.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz))
        return Error{ErrorCode::internal, fmt::format("field {}: {} values for a {}x{} grid", name, values.size(), nx, nz)};
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    const Encoding e = Encoding::covering(values.empty() ? 0.0 : static_cast<double>(*lo), values.empty() ? 0.0 : static_cast<double>(*hi));
    Gray16Image img;
    img.width = nx;
    img.height = nz;
    img.pixels.resize(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) img.pixels[k] = e.encode(static_cast<double>(values[k]));
    const std::string file = name + ".png";
    if (auto st = write_png_gray16(dir / file, img); !st) return st.error();
    return nlohmann::json{{"file", file}, {"unit", unit}, {"zero_pixel", e.zero}, {"step", e.step}, {"max_error", 0.5 * e.step}};
}

Result<std::vector<float>> read_field_png(const fs::path& dir, const ObjectReader& fields, std::string_view name, int nx, int nz) {
    if (!fields.has(name)) return fields.error(name, "is missing");
    auto r = ObjectReader::open(fields.at(name), fields.source(), fields.child_path(name));
    if (!r) return r.error();
    std::string file;
    if (auto st = r->string("file", file, true); !st) return st.error();
    if (file.empty() || file.find('/') != std::string::npos || file.find('\\') != std::string::npos)
        return r->error("file", "must be a file name inside the bake folder");
    double step = 0.0, zero = 0.0;
    if (auto st = r->number("step", step, true); !st) return st.error();
    if (auto st = r->number("zero_pixel", zero, true); !st) return st.error();
    if (!(step > 0.0) || !std::isfinite(step)) return r->error("step", "must be a finite number > 0");
    if (zero != std::floor(zero) || std::abs(zero) > 1e15) return r->error("zero_pixel", "must be an integer");
    auto img = read_png_gray16(dir / file);
    if (!img) return img.error();
    if (img->width != nx || img->height != nz)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: the image is {}x{}, the bake's grid is {}x{}", (dir / file).string(), img->width, img->height, nx, nz)};
    Encoding e;
    e.step = step;
    e.zero = static_cast<std::int64_t>(zero);
    std::vector<float> values(img->pixels.size());
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<float>(e.decode(img->pixels[k]));
    return values;
}

double field_png_step(const ObjectReader& fields, std::string_view name) { return fields.at(name).at("step").get<double>(); }

Result<nlohmann::json> read_sidecar(const fs::path& path, int version) {
    auto text = read_text_file(path.string());
    if (!text) return text.error();
    auto doc = parse_json_text(*text, path.string());
    if (!doc) return doc.error();
    auto root = ObjectReader::open(*doc, path.string(), "");
    if (!root) return root.error();
    std::int64_t found = 0;
    if (auto st = root->integer("version", found, 1, 1000, true); !st) return st.error();
    if (found != version) return root->error("version", fmt::format("{} is not supported (this build reads version {})", found, version));
    return doc;
}

Status write_text_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text << "\n";
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", path.string())};
    return {};
}

}  // namespace tidewater::detail
