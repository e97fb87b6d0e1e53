// The scene's "terrain" object -> Terrain. Heightmaps come as 16-bit PNG, raw 16-bit
// files or any raster GDAL reads. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/scene_json_parts.hpp"
#include "tidewater/detail/elevation_raster.hpp"
#include "tidewater/detail/image_io.hpp"

namespace tidewater::detail {

namespace {

constexpr double kMaxTerrainSize = 1e6;  // m along a side

enum class HeightmapFormat { png16, raw16, raster };

Result<HeightmapFormat> heightmap_format(const ObjectReader& r, const std::filesystem::path& path) {
    if (r.has("format")) {
        std::string f;
        if (auto st = r.string("format", f); !st) return st.error();
        if (f == "png16") return HeightmapFormat::png16;
        if (f == "raw16") return HeightmapFormat::raw16;
        if (f == "raster") return HeightmapFormat::raster;
        return r.error("format", fmt::format("\"{}\": expected \"png16\", \"raw16\" or \"raster\"", f));
    }
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return HeightmapFormat::png16;
    if (ext == ".raw" || ext == ".r16") return HeightmapFormat::raw16;
    return HeightmapFormat::raster;
}

/// A 16-bit heightmap whose codes map linearly onto `range`; read as depths, the codes
/// are turned over so that the same heightmap holds heights.
void apply_range(HeightmapTerrain& t, glm::dvec2 range, bool depth) {
    if (!depth) {
        t.min_height = range.x;
        t.max_height = range.y;
        return;
    }
    auto image = std::make_shared<Gray16Image>(*t.image);
    for (std::uint16_t& p : image->pixels) p = static_cast<std::uint16_t>(65535u - p);
    t.image = std::move(image);
    t.min_height = -range.y;
    t.max_height = -range.x;
}

Error in_file_field(const ObjectReader& r, Error e) {
    e.message = fmt::format("{}: {}", r.context("file"), e.message);
    return e;
}

Result<Terrain> read_heightmap(const ObjectReader& r, const std::filesystem::path& base_dir) {
    if (auto st = r.allow_only({"file", "format", "size", "height_range", "center", "values", "raw"}); !st)
        return st.error();
    std::string file;
    if (auto st = r.string("file", file, true); !st) return st.error();
    std::filesystem::path path = file;
    if (path.is_relative() && !base_dir.empty()) path = base_dir / path;
    auto format = heightmap_format(r, path);
    if (!format) return format.error();

    bool depth = false;
    if (r.has("values")) {
        std::string v;
        if (auto st = r.string("values", v); !st) return st.error();
        if (v != "elevation" && v != "depth")
            return r.error("values",
                           fmt::format("\"{}\": expected \"elevation\" (up) or \"depth\" (positive down)", v));
        depth = v == "depth";
    }
    glm::dvec2 size{0.0}, center{0.0};
    const bool sized = r.has("size");
    if (auto st = read_pair(r, "size", size, *format != HeightmapFormat::raster, kMaxTerrainSize); !st)
        return st.error();
    if (sized && (size.x <= 0.0 || size.y <= 0.0)) return r.error("size", "both sizes must be > 0 m");
    if (auto st = read_pair(r, "center", center, false, 1e7); !st) return st.error();
    if (*format == HeightmapFormat::raster && r.has("height_range"))
        return r.error("height_range", "a raster's values are metres: height_range is for 16-bit PNG and raw files");
    if (*format != HeightmapFormat::raw16 && r.has("raw"))
        return r.error("raw", "only a raw16 heightmap takes \"raw\"");

    if (*format == HeightmapFormat::raster) {
        auto grid = read_gdal_elevation(path, depth);
        if (!grid) return in_file_field(r, std::move(grid).error());
        if (!sized) {
            if (grid->pixel_size.x <= 0.0)
                return r.error("size", fmt::format("{} has no georeference: give its size in metres", path.string()));
            size = grid->pixel_size * glm::dvec2(grid->width - 1, grid->height - 1);
            if (size.x > kMaxTerrainSize || size.y > kMaxTerrainSize)
                return r.error("file", fmt::format("{}: {:.0f} x {:.0f} m is larger than {} m a side", path.string(),
                                                   size.x, size.y, kMaxTerrainSize));
        }
        return Terrain(quantise_heightmap(*grid, path.string(), size, center));
    }

    glm::dvec2 range{0.0};
    if (auto st = read_pair(r, "height_range", range, true, kMaxAbsHeight); !st) return st.error();
    if (!(range.x < range.y)) return r.error("height_range", "expected [lowest, highest] with lowest < highest");
    Result<Gray16Image> image = Error{};
    if (*format == HeightmapFormat::raw16) {
        if (!r.has("raw")) return r.error("raw", "required {\"width\", \"height\"} (and \"byte_order\") is missing");
        auto raw = ObjectReader::open(r.at("raw"), r.source(), r.child_path("raw"));
        if (!raw) return raw.error();
        if (auto st = raw->allow_only({"width", "height", "byte_order"}); !st) return st.error();
        std::int64_t w = 0, h = 0;
        if (auto st = raw->integer("width", w, 2, 65536, true); !st) return st.error();
        if (auto st = raw->integer("height", h, 2, 65536, true); !st) return st.error();
        std::string order = "little";
        if (auto st = raw->string("byte_order", order); !st) return st.error();
        if (order != "little" && order != "big")
            return raw->error("byte_order", fmt::format("\"{}\": expected \"little\" or \"big\"", order));
        image = read_raw16(path, static_cast<int>(w), static_cast<int>(h), order == "big");
    } else {
        image = read_png_gray16(path);
    }
    if (!image) return in_file_field(r, std::move(image).error());
    if (image->width < 2 || image->height < 2)
        return r.error("file", fmt::format("{}: {}x{} pixels: a heightmap needs at least 2x2", path.string(),
                                           image->width, image->height));
    HeightmapTerrain t;
    t.file = path.string();
    t.size = size;
    t.center = center;
    t.image = std::make_shared<const Gray16Image>(std::move(image).value());
    apply_range(t, range, depth);
    return Terrain(t);
}

Status read_knolls(const ObjectReader& r, std::vector<Knoll>& out) {
    if (!r.has("knolls")) return {};
    const nlohmann::json& list = r.at("knolls");
    if (!list.is_array())
        return r.error("knolls", fmt::format("expected an array of objects, found {}", detail::json_type_name(list)));
    if (list.size() > 256) return r.error("knolls", fmt::format("{} knolls: at most 256", list.size()));
    for (std::size_t i = 0; i < list.size(); ++i) {
        auto k = ObjectReader::open(list[i], r.source(), r.child_path("knolls") + "/" + std::to_string(i));
        if (!k) return k.error();
        if (auto st = k->allow_only({"at", "radius", "height"}); !st) return st;
        Knoll knoll;
        if (auto st = read_pair(*k, "at", knoll.at, true, 1e7); !st) return st;
        if (auto st = k->number("radius", knoll.radius, true); !st) return st;
        if (auto st = check_range(*k, "radius", knoll.radius, 1.0, 10000.0, " m"); !st) return st;
        if (auto st = k->number("height", knoll.height, true); !st) return st;
        if (auto st = check_range(*k, "height", knoll.height, 0.1, 2000.0, " m"); !st) return st;
        out.push_back(knoll);
    }
    return {};
}

Result<Terrain> read_island(const ObjectReader& r) {
    if (auto st = r.allow_only({"seed", "radius", "height", "seabed", "center", "knolls"}); !st) return st.error();
    IslandTerrain t;
    std::int64_t seed = t.seed;
    if (auto st = r.integer("seed", seed, 0, 0xffffffffLL); !st) return st.error();
    t.seed = static_cast<std::uint32_t>(seed);
    if (auto st = r.number("radius", t.radius); !st) return st.error();
    if (auto st = check_range(r, "radius", t.radius, 50.0, 50000.0, " m"); !st) return st.error();
    if (auto st = r.number("height", t.height); !st) return st.error();
    if (auto st = check_range(r, "height", t.height, 1.0, 2000.0, " m"); !st) return st.error();
    if (auto st = r.number("seabed", t.seabed); !st) return st.error();
    if (auto st = check_range(r, "seabed", t.seabed, -10000.0, -1.0, " m"); !st) return st.error();
    if (auto st = read_pair(r, "center", t.center, false, 1e7); !st) return st.error();
    if (auto st = read_knolls(r, t.knolls); !st) return st.error();
    return Terrain(t);
}

/// An unbounded terrain's "half_size": the square its bakes span about the origin, m.
Status read_half_size(const ObjectReader& shape, double& half_size) {
    if (auto st = shape.number("half_size", half_size); !st) return st;
    return check_range(shape, "half_size", half_size, 1e-3, kMaxTerrainSize, " m");
}

}  // namespace

Result<Terrain> read_terrain(const ObjectReader& scene, const std::filesystem::path& base_dir) {
    auto r = ObjectReader::open(scene.at("terrain"), scene.source(), "/terrain");
    if (!r) return r.error();
    if (auto st = r->allow_only({"flat", "plane", "heightmap", "island"}); !st) return st.error();
    const int shapes = int(r->has("flat")) + int(r->has("plane")) + int(r->has("heightmap")) + int(r->has("island"));
    if (shapes != 1) {
        return Error{
            ErrorCode::schema_error,
            fmt::format("{}: give exactly one of \"flat\", \"plane\", \"heightmap\" and \"island\"", r->context())};
    }
    for (const char* key : {"flat", "plane", "heightmap", "island"}) {
        if (!r->has(key)) continue;
        auto shape = ObjectReader::open(r->at(key), r->source(), r->child_path(key));
        if (!shape) return shape.error();
        const std::string k = key;
        if (k == "heightmap") return read_heightmap(*shape, base_dir);
        if (k == "island") return read_island(*shape);
        if (k == "flat") {
            if (auto st = shape->allow_only({"height", "half_size"}); !st) return st.error();
            FlatTerrain flat;
            if (auto st = shape->number("height", flat.height, true); !st) return st.error();
            if (auto st = check_range(*shape, "height", flat.height, -kMaxAbsHeight, kMaxAbsHeight, " m"); !st)
                return st.error();
            if (auto st = read_half_size(*shape, flat.half_size); !st) return st.error();
            return Terrain(flat);
        }
        if (auto st = shape->allow_only({"height", "slope", "half_size"}); !st) return st.error();
        PlaneTerrain plane;
        if (auto st = shape->number("height", plane.height, true); !st) return st.error();
        if (auto st = check_range(*shape, "height", plane.height, -kMaxAbsHeight, kMaxAbsHeight, " m"); !st)
            return st.error();
        if (auto st = read_pair(*shape, "slope", plane.slope, true, 10.0); !st) return st.error();
        if (auto st = read_half_size(*shape, plane.half_size); !st) return st.error();
        return Terrain(plane);
    }
    return Error{ErrorCode::schema_error, fmt::format("{}: no terrain shape", r->context())};
}

}  // namespace tidewater::detail
