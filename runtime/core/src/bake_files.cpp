// Reading saved bakes' files: sidecars and 16-bit PNG fields (the writers are Tidewater::bake's).
#include "tidewater/detail/bake_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tidewater/detail/image_io.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

namespace fs = std::filesystem;

Result<std::vector<float>> read_field_png(const fs::path& dir, const ObjectReader& fields, std::string_view name,
                                          int nx, int nz) {
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
        return Error{ErrorCode::invalid_argument, fmt::format("{}: the image is {}x{}, the bake's grid is {}x{}",
                                                              (dir / file).string(), img->width, img->height, nx, nz)};
    FieldEncoding e;
    e.step = step;
    e.zero = static_cast<std::int64_t>(zero);
    std::vector<float> values(img->pixels.size());
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<float>(e.decode(img->pixels[k]));
    return values;
}

double field_png_step(const ObjectReader& fields, std::string_view name) {
    return fields.at(name).at("step").get<double>();
}

Result<nlohmann::json> read_sidecar(const fs::path& path, int version) {
    auto text = read_text_file(path.string());
    if (!text) return text.error();
    auto doc = parse_json_text(*text, path.string());
    if (!doc) return doc.error();
    auto root = ObjectReader::open(*doc, path.string(), "");
    if (!root) return root.error();
    std::int64_t found = 0;
    if (auto st = root->integer("version", found, 1, 1000, true); !st) return st.error();
    if (found != version)
        return root->error(
            "version",
            fmt::format("{} is not supported (this build reads version {}): re-run tidewater bake", found, version));
    return doc;
}

}  // namespace tidewater::detail
