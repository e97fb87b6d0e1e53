// Loading saved lakes and rivers (the writer is Tidewater::bake's, bodies_bake_write.cpp).
#include "tidewater/detail/bodies_bake_folder.hpp"

#include <fmt/format.h>

#include <cmath>

#include "host_device.h"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/bake_files.hpp"
#include "tidewater/detail/json_reader.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;
using detail::FieldGrid;
using detail::LakeBake;
using detail::ObjectReader;
using detail::RiverBake;
using nlohmann::json;

bool same(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

Error stale(const ObjectReader& r, std::string_view key, const std::string& what) {
    return r.error(key, what + ": the bake was made for other lakes or rivers; re-run tidewater bake");
}

Result<std::vector<double>> read_numbers(const ObjectReader& r, std::string_view key) {
    if (!r.has(key) || !r.at(key).is_array()) return r.error(key, "expected an array of numbers");
    std::vector<double> out;
    for (const auto& v : r.at(key)) {
        if (!v.is_number()) return r.error(key, "expected an array of numbers");
        out.push_back(v.get<double>());
    }
    return out;
}

Result<std::vector<glm::dvec2>> read_points(const ObjectReader& r, std::string_view key) {
    if (!r.has(key) || !r.at(key).is_array()) return r.error(key, "expected an array of [x, z]");
    std::vector<glm::dvec2> out;
    for (const auto& v : r.at(key)) {
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
            return r.error(key, "expected an array of [x, z]");
        out.push_back({v[0].get<double>(), v[1].get<double>()});
    }
    return out;
}

Result<FieldGrid> read_grid(const ObjectReader& r) {
    if (!r.has("grid")) return r.error("grid", "is missing");
    auto g = ObjectReader::open(r.at("grid"), r.source(), r.child_path("grid"));
    if (!g) return g.error();
    FieldGrid out;
    std::int64_t nx = 0, nz = 0;
    if (auto st = g->integer("nx", nx, 1, 8192, true); !st) return st.error();
    if (auto st = g->integer("nz", nz, 1, 8192, true); !st) return st.error();
    if (auto st = g->number("texel_m", out.texel, true); !st) return st.error();
    if (!(out.texel > 0.0) || !std::isfinite(out.texel)) return g->error("texel_m", "must be a finite number > 0");
    auto corner = read_numbers(*g, "corner_m");
    if (!corner || corner->size() != 2) return g->error("corner_m", "expected [x, z] in metres");
    out.corner = {(*corner)[0], (*corner)[1]};
    out.nx = static_cast<int>(nx);
    out.nz = static_cast<int>(nz);
    return out;
}

/// A field of small integers (texel kinds, masks) decoded exactly.
Result<std::vector<std::uint8_t>> read_codes(const fs::path& dir, const ObjectReader& fields, std::string_view name,
                                             const FieldGrid& g) {
    auto values = detail::read_field_png(dir, fields, name, g.nx, g.nz);
    if (!values) return values.error();
    std::vector<std::uint8_t> out(values->size());
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k] = static_cast<std::uint8_t>(std::clamp(std::lround((*values)[k]), 0L, 255L));
    return out;
}

Result<LakeBake> read_lake(const fs::path& dir, const ObjectReader& r, const SceneLake& lake) {
    LakeBake out;
    std::string name;
    if (auto st = r.string("name", name, true); !st) return st.error();
    double level = 0.0;
    if (auto st = r.number("level_m", level, true); !st) return st.error();
    auto at = read_numbers(r, "at_m");
    if (!at) return at.error();
    if (name != lake.name) return stale(r, "name", fmt::format("\"{}\", the scene's lake is \"{}\"", name, lake.name));
    if (!same(level, lake.body.level()))
        return stale(r, "level_m", fmt::format("{} m, the scene's lake is at {} m", level, lake.body.level()));
    if (at->size() != 2 || !same((*at)[0], lake.at.x) || !same((*at)[1], lake.at.y))
        return stale(r, "at_m", "another point");
    auto grid = read_grid(r);
    if (!grid) return grid.error();
    out.name = name;
    out.level = level;
    out.grid = *grid;
    if (!r.has("fields")) return r.error("fields", "is missing");
    auto fields = ObjectReader::open(r.at("fields"), r.source(), r.child_path("fields"));
    if (!fields) return fields.error();
    auto inside = read_codes(dir, *fields, "inside", out.grid);
    if (!inside) return inside.error();
    out.inside = std::move(inside).value();
    for (const std::uint8_t v : out.inside) out.texels += v != 0 ? 1 : 0;
    return out;
}

/// What a river was baked from must be what the scene says now.
Status check_river_inputs(const ObjectReader& r, const SceneRiver& river) {
    std::string name;
    if (auto st = r.string("name", name, true); !st) return st;
    if (name != river.name)
        return stale(r, "name", fmt::format("\"{}\", the scene's river is \"{}\"", name, river.name));
    auto path = read_points(r, "path_m");
    if (!path) return path.error();
    bool same_path = path->size() == river.path.size();
    for (std::size_t k = 0; same_path && k < path->size(); ++k)
        same_path = same((*path)[k].x, river.path[k].x) && same((*path)[k].y, river.path[k].y);
    if (!same_path) return stale(r, "path_m", "another path");
    auto width = read_numbers(r, "width_m");
    if (!width) return width.error();
    bool same_width = width->size() == river.width.size();
    for (std::size_t k = 0; same_width && k < width->size(); ++k) same_width = same((*width)[k], river.width[k]);
    if (!same_width) return stale(r, "width_m", "other widths");
    double discharge = 0.0, manning = 0.0;
    if (auto st = r.number("discharge_m3_s", discharge, true); !st) return st;
    if (!same(discharge, river.discharge))
        return stale(r, "discharge_m3_s", fmt::format("{} m^3/s, the scene's is {}", discharge, river.discharge));
    if (auto st = r.number("manning", manning, true); !st) return st;
    if (!same(manning, river.manning))
        return stale(r, "manning", fmt::format("{}, the scene's is {}", manning, river.manning));
    if (!r.has("carve") || !r.at("carve").is_boolean()) return r.error("carve", "expected true or false");
    if (r.at("carve").get<bool>() != river.carve) return stale(r, "carve", "another carving");
    return {};
}

Result<RiverBake> read_river(const fs::path& dir, const ObjectReader& r, const SceneRiver& river, std::size_t lakes,
                             std::size_t rivers) {
    if (auto st = check_river_inputs(r, river); !st) return st.error();
    RiverBake out;
    out.name = river.name;
    out.manning = river.manning;
    std::string end;
    if (auto st = r.string("end", end, true); !st) return st.error();
    std::int64_t receiver = -1, islands = 0;
    if (auto st = r.integer("receiver", receiver, -1, 1 << 20, true); !st) return st.error();
    bool known = false;
    for (const auto kind :
         {detail::RiverEnd::ocean, detail::RiverEnd::lake, detail::RiverEnd::river, detail::RiverEnd::domain_edge})
        if (end == detail::river_end_name(kind)) out.end = kind, known = true;
    if (!known) return r.error("end", fmt::format("\"{}\" is not one of ocean, lake, river, domain_edge", end));
    const bool needs_receiver = out.end == detail::RiverEnd::lake || out.end == detail::RiverEnd::river;
    const std::size_t bound = out.end == detail::RiverEnd::lake ? lakes : rivers;
    if (needs_receiver != (receiver >= 0) || (needs_receiver && static_cast<std::size_t>(receiver) >= bound))
        return r.error("receiver", fmt::format("{} does not name a {} of the scene", receiver, end));
    out.receiver = static_cast<int>(receiver);
    if (auto st = r.integer("islands", islands, 0, 1 << 30, true); !st) return st.error();
    out.islands = static_cast<std::size_t>(islands);
    for (const auto& [key, target] :
         {std::pair{"baked_discharge_m3_s", &out.discharge}, std::pair{"own_discharge_m3_s", &out.own_discharge},
          std::pair{"mouth_level_m", &out.mouth_level}, std::pair{"mean_speed_m_s", &out.mean_speed}}) {
        if (auto st = r.number(key, *target, true); !st) return st.error();
        if (!std::isfinite(*target)) return r.error(key, "must be finite");
    }
    auto centreline = read_points(r, "centreline_m");
    if (!centreline) return centreline.error();
    out.centreline = std::move(centreline).value();
    for (const auto& [key, target] :
         {std::pair{"along_m", &out.along}, std::pair{"section_width_m", &out.width},
          std::pair{"surface_m", &out.surface}, std::pair{"bed_m", &out.bed}, std::pair{"slope", &out.slope}}) {
        auto values = read_numbers(r, key);
        if (!values) return values.error();
        if (values->size() != out.centreline.size())
            return r.error(key,
                           fmt::format("{} values for {} centreline points", values->size(), out.centreline.size()));
        *target = std::move(values).value();
    }
    if (out.centreline.size() < 2) return r.error("centreline_m", "needs at least two points");
    auto grid = read_grid(r);
    if (!grid) return grid.error();
    out.grid = *grid;
    if (!r.has("fields")) return r.error("fields", "is missing");
    auto fields = ObjectReader::open(r.at("fields"), r.source(), r.child_path("fields"));
    if (!fields) return fields.error();
    auto texel = read_codes(dir, *fields, "texel", out.grid);
    if (!texel) return texel.error();
    out.texel = std::move(texel).value();
    for (const std::uint8_t t : out.texel)
        if (t > static_cast<std::uint8_t>(detail::RiverTexel::mouth))
            return fields->error("texel", fmt::format("holds the unknown kind {}", t));
    std::vector<float> wave_weight, still_weight;
    const std::pair<const char*, std::vector<float>*> floats[] = {{"surface_height", &out.surface_height},
                                                                  {"depth", &out.depth},
                                                                  {"psi", &out.psi},
                                                                  {"discharge_x", &out.discharge_x},
                                                                  {"discharge_z", &out.discharge_z},
                                                                  {"flow_x", &out.flow_x},
                                                                  {"flow_z", &out.flow_z},
                                                                  {"channel_s", &out.channel_s},
                                                                  {"channel_n", &out.channel_n},
                                                                  {"tangent_x", &out.tangent_x},
                                                                  {"tangent_z", &out.tangent_z},
                                                                  {"wave_weight", &wave_weight},
                                                                  {"still_weight", &still_weight}};
    for (const auto& [name, target] : floats) {
        auto values = detail::read_field_png(dir, *fields, name, out.grid.nx, out.grid.nz);
        if (!values) return values.error();
        *target = std::move(values).value();
    }
    if (fields->has("cut_depth")) {
        auto cut = detail::read_field_png(dir, *fields, "cut_depth", out.grid.nx, out.grid.nz);
        if (!cut) return cut.error();
        auto made = std::make_shared<TerrainCut>();
        made->corner = out.grid.corner;
        made->texel = out.grid.texel;
        made->nx = out.grid.nx;
        made->nz = out.grid.nz;
        made->depth = std::move(cut).value();
        out.cut = std::move(made);
    }
    detail::pack_query_texels(out, wave_weight, still_weight);
    return out;
}

/// The terrain under a river is the one baked over: shape = surface - depth + cut at
/// every texel of its water, within the fields' encodings.
Status check_river_terrain(const ObjectReader& fields, const RiverBake& river, const Terrain& terrain) {
    const double tolerance =
        0.51 * (detail::field_png_step(fields, "surface_height") + detail::field_png_step(fields, "depth") +
                (fields.has("cut_depth") ? detail::field_png_step(fields, "cut_depth") : 0.0)) +
        1e-3;
    const FieldGrid& g = river.grid;
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            if (river.texel[t] == 0) continue;
            const glm::dvec2 p = g.center(i, j);
            const double cut = river.cut ? static_cast<double>(river.cut->depth[t]) : 0.0;
            const double stored =
                static_cast<double>(river.surface_height[t]) - static_cast<double>(river.depth[t]) + cut;
            const double shape = terrain.shape_height_at(p);
            if (!(std::abs(shape - stored) <= tolerance))
                return fields.error(
                    "depth",
                    fmt::format("the terrain differs from the one baked under the river ({:.3f} m at x = {:.1f}, "
                                "z = {:.1f}, the bake says {:.3f} m): re-run tidewater bake",
                                shape, p.x, p.y, stored));
        }
    return {};
}

}  // namespace

FieldGrid detail::saved_lake_grid(const Terrain& terrain, int resolution) {
    FieldGrid g;
    const double half = terrain.extent_half_size();
    g.nx = g.nz = resolution;
    g.texel = 2.0 * half / resolution;
    g.corner = terrain.extent_center() - glm::dvec2(half);
    return g;
}

Result<LoadedBodies> load_bodies_bake(const fs::path& dir, const Scene& scene, const detail::BodiesBakeOptions& options,
                                      bool lake_shores) {
    const fs::path sidecar_path = dir / kBodiesSidecar;
    if (!fs::exists(sidecar_path))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: missing: the bake in {} holds no lakes or rivers, the scene has them; "
                                 "re-run tidewater bake",
                                 sidecar_path.string(), dir.string())};
    auto doc = detail::read_sidecar(sidecar_path, kBodiesBakeFormatVersion);
    if (!doc) return doc.error();
    auto root = ObjectReader::open(*doc, sidecar_path.string(), "");
    if (!root) return root.error();
    std::int64_t lake_resolution = 0;
    double level = 0.0, texels_across = 0.0;
    if (auto st = root->number("water_level_m", level, true); !st) return st.error();
    if (!same(level, scene.water_level()))
        return root->error(
            "water_level_m",
            fmt::format("the bake was made at water level {} m, the scene's is {} m: re-run tidewater bake", level,
                        scene.water_level()));
    if (!root->has("has_ocean") || !root->at("has_ocean").is_boolean())
        return root->error("has_ocean", "expected true or false");
    if (root->at("has_ocean").get<bool>() != scene.has_ocean) return stale(*root, "has_ocean", "another ocean");
    // The grid lakes were found on is the bake's (a saved bake fixes the shore resolution).
    if (auto st = root->integer("lake_resolution", lake_resolution, 8, 8192, true); !st) return st.error();
    if (auto st = root->number("texels_across", texels_across, true); !st) return st.error();
    if (!same(texels_across, options.texels_across))
        return root->error("texels_across", fmt::format("{}, this bake asks for {}: re-run tidewater bake",
                                                        texels_across, options.texels_across));

    // The terrain's shape on the lakes' grid.
    const Terrain uncut = scene.terrain.with_cuts({});
    if (!root->has("terrain")) return root->error("terrain", "is missing");
    auto terrain = ObjectReader::open(root->at("terrain"), root->source(), "/terrain");
    if (!terrain) return terrain.error();
    auto shape_grid = read_grid(*terrain);
    if (!shape_grid) return shape_grid.error();
    const FieldGrid expected = detail::saved_lake_grid(uncut, static_cast<int>(lake_resolution));
    if (shape_grid->nx != expected.nx || shape_grid->nz != expected.nz || !same(shape_grid->texel, expected.texel) ||
        !same(shape_grid->corner.x, expected.corner.x) || !same(shape_grid->corner.y, expected.corner.y))
        return terrain->error("grid",
                              "covers another extent: the bake was made for another terrain; re-run tidewater bake");
    if (!terrain->has("fields")) return terrain->error("fields", "is missing");
    auto terrain_fields = ObjectReader::open(terrain->at("fields"), terrain->source(), "/terrain/fields");
    if (!terrain_fields) return terrain_fields.error();
    auto shape = detail::read_field_png(dir, *terrain_fields, "shape", expected.nx, expected.nz);
    if (!shape) return shape.error();
    const double tolerance = 0.51 * detail::field_png_step(*terrain_fields, "shape") + 1e-3;
    for (int j = 0; j < expected.nz; ++j)
        for (int i = 0; i < expected.nx; ++i) {
            const double h = uncut.shape_height_at(expected.center(i, j)),
                         stored = static_cast<double>((*shape)[expected.index(i, j)]);
            if (!(std::abs(h - stored) <= tolerance))
                return terrain_fields->error(
                    "shape", fmt::format("the terrain differs from the one baked ({:.3f} m at x = {:.1f}, z = {:.1f}, "
                                         "the bake says {:.3f} m): re-run tidewater bake",
                                         h, expected.center(i, j).x, expected.center(i, j).y, stored));
        }

    LoadedBodies out;
    if (!root->has("lakes") || !root->at("lakes").is_array()) return root->error("lakes", "expected an array");
    if (!root->has("rivers") || !root->at("rivers").is_array()) return root->error("rivers", "expected an array");
    const auto& lakes = root->at("lakes");
    const auto& rivers = root->at("rivers");
    if (lakes.size() != scene.lakes.size())
        return stale(*root, "lakes", fmt::format("{} lakes, the scene has {}", lakes.size(), scene.lakes.size()));
    if (rivers.size() != scene.rivers.size())
        return stale(*root, "rivers", fmt::format("{} rivers, the scene has {}", rivers.size(), scene.rivers.size()));
    std::vector<std::string> lake_shore_folders(lakes.size());
    for (std::size_t l = 0; l < lakes.size(); ++l) {
        auto r = ObjectReader::open(lakes[l], root->source(), fmt::format("/lakes/{}", l));
        if (!r) return r.error();
        auto lake = read_lake(dir, *r, scene.lakes[l]);
        if (!lake) return lake.error();
        out.bodies.lakes.push_back(std::move(lake).value());
        if (r->has("shore") && !r->at("shore").is_null()) {
            if (auto st = r->string("shore", lake_shore_folders[l]); !st) return st.error();
            if (lake_shore_folders[l].empty() || lake_shore_folders[l].find('/') != std::string::npos)
                return r->error("shore", "must be a folder name inside the bake folder");
        }
    }
    std::vector<std::shared_ptr<const TerrainCut>> cuts;
    for (std::size_t k = 0; k < rivers.size(); ++k) {
        auto r = ObjectReader::open(rivers[k], root->source(), fmt::format("/rivers/{}", k));
        if (!r) return r.error();
        auto river = read_river(dir, *r, scene.rivers[k], lakes.size(), rivers.size());
        if (!river) return river.error();
        auto fields = ObjectReader::open(r->at("fields"), r->source(), r->child_path("fields"));
        if (!fields) return fields.error();
        if (auto st = check_river_terrain(*fields, *river, uncut); !st) return st.error();
        if (river->cut) cuts.push_back(river->cut);
        out.bodies.rivers.push_back(std::move(river).value());
    }
    out.bodies.terrain = uncut.with_cuts(cuts);
    out.lake_shores.assign(lakes.size(), nullptr);
    if (lake_shores)
        for (std::size_t l = 0; l < lakes.size(); ++l) {
            if (lake_shore_folders[l].empty())
                return root->error(fmt::format("lakes/{}/shore", l),
                                   "is missing: the bake holds no shore model for this lake; re-run tidewater bake");
            const SquareRegion region = detail::lake_basin_region(out.bodies.lakes[l]);
            SceneShore settings = scene.shore;
            auto model = load_shore_bake(dir / lake_shore_folders[l], scene.lakes[l].body.waves(),
                                         out.bodies.lakes[l].level, out.bodies.terrain, &region, &settings);
            if (!model) {
                Error e = model.error();
                e.message = fmt::format("lake \"{}\": {}", scene.lakes[l].name, e.message);
                return e;
            }
            out.lake_shores[l] = std::move(model).value();
            if (!out.shore_settings) out.shore_settings = settings;
        }
    return out;
}

}  // namespace tidewater
