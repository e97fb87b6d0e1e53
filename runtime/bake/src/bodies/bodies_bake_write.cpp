// Writing saved lakes and rivers (the format is in docs/scene-format.md;
// bodies_bake_folder.cpp loads them).
#include "tidewater/detail/bodies_bake_write.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <tuple>

#include "host_device.h"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/bake_files_write.hpp"
#include "tidewater/detail/shore_bake_write.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;
using detail::FieldGrid;
using detail::LakeBake;
using detail::RiverBake;
using nlohmann::json;

std::string lake_folder(std::size_t l) {
    return fmt::format("lake_{:02}", l);
}

json grid_json(const FieldGrid& g) {
    return {{"corner_m", {g.corner.x, g.corner.y}}, {"texel_m", g.texel}, {"nx", g.nx}, {"nz", g.nz}};
}

json points_json(const std::vector<glm::dvec2>& points) {
    json out = json::array();
    for (const glm::dvec2& p : points) out.push_back({p.x, p.y});
    return out;
}

std::vector<float> as_floats(const std::vector<std::uint8_t>& v) {
    return {v.begin(), v.end()};
}

std::vector<float> shape_heights(const Terrain& terrain, const FieldGrid& g) {
    std::vector<float> h(g.size());
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) h[g.index(i, j)] = static_cast<float>(terrain.shape_height_at(g.center(i, j)));
    return h;
}

Status write_fields(const fs::path& dir, const std::string& prefix, const FieldGrid& g,
                    std::initializer_list<std::tuple<const char*, const std::vector<float>*, const char*>> fields,
                    json& out) {
    for (const auto& [name, values, unit] : fields) {
        auto entry = detail::write_field_png(dir, prefix + name, *values, g.nx, g.nz, unit);
        if (!entry) return entry.error();
        out[name] = *entry;
    }
    return {};
}

}  // namespace

Status write_bodies_bake_into(const fs::path& dir, const Scene& baked) {
    if (!baked.bake || !baked.bake->bodies)
        return Error{ErrorCode::invalid_argument, fmt::format("{} has no baked lakes or rivers", scene_label(baked))};
    const detail::WaterBodiesBake& bodies = *baked.bake->bodies;
    const Terrain uncut = baked.terrain.with_cuts({});
    const FieldGrid shape_grid = detail::saved_lake_grid(uncut, baked.shore.resolution);
    json sidecar = {{"version", kBodiesBakeFormatVersion},
                    {"scene", baked.name},
                    {"encoding", detail::kFieldEncoding},
                    {"water_level_m", baked.water_level()},
                    {"has_ocean", baked.has_ocean},
                    {"lake_resolution", baked.shore.resolution},
                    {"texels_across", detail::BodiesBakeOptions{}.texels_across}};
    json terrain = {{"grid", grid_json(shape_grid)},
                    {"notes", "the terrain's shape (no river cuts) on the grid lakes are found on"}};
    const std::vector<float> shape = shape_heights(uncut, shape_grid);
    if (auto st = write_fields(dir, "terrain_", shape_grid, {{"shape", &shape, "m"}}, terrain["fields"]); !st)
        return st;
    sidecar["terrain"] = terrain;
    sidecar["lakes"] = json::array();
    for (std::size_t l = 0; l < bodies.lakes.size(); ++l) {
        const LakeBake& lake = bodies.lakes[l];
        json entry = {{"name", lake.name},
                      {"level_m", lake.level},
                      {"at_m", {baked.lakes[l].at.x, baked.lakes[l].at.y}},
                      {"grid", grid_json(lake.grid)},
                      {"texels", lake.texels},
                      {"shore", nullptr}};
        const std::vector<float> inside = as_floats(lake.inside);
        if (auto st = write_fields(dir, fmt::format("lake_{:02}_", l), lake.grid, {{"inside", &inside, "1"}},
                                   entry["fields"]);
            !st)
            return st;
        const auto& model = l < baked.bake->lake_shores.size() ? baked.bake->lake_shores[l] : nullptr;
        if (model) {
            const fs::path sub = dir / lake_folder(l);
            std::error_code ec;
            fs::create_directory(sub, ec);
            if (ec)
                return Error{ErrorCode::io_error,
                             fmt::format("{}: cannot create folder: {}", sub.string(), ec.message())};
            ShoreBakeContents contents;
            contents.model = model.get();
            contents.waves = &baked.lakes[l].body.waves();
            contents.water_level = lake.level;
            contents.breaking_index = baked.shore.breaking_index;
            contents.texels_per_wavelength = baked.shore.texels_per_wavelength;
            contents.diffraction = baked.shore.diffraction;
            contents.scene_name = baked.name;
            if (auto st = write_shore_bake_into(sub, contents); !st) return st;
            entry["shore"] = lake_folder(l);
        }
        sidecar["lakes"].push_back(entry);
    }
    sidecar["rivers"] = json::array();
    for (std::size_t r = 0; r < bodies.rivers.size(); ++r) {
        const RiverBake& river = bodies.rivers[r];
        const SceneRiver& spec = baked.rivers[r];
        json entry = {{"name", river.name},
                      {"path_m", points_json(spec.path)},
                      {"width_m", spec.width},
                      {"discharge_m3_s", spec.discharge},
                      {"manning", spec.manning},
                      {"carve", spec.carve},
                      {"end", detail::river_end_name(river.end)},
                      {"receiver", river.receiver},
                      {"islands", river.islands},
                      {"baked_discharge_m3_s", river.discharge},
                      {"own_discharge_m3_s", river.own_discharge},
                      {"mouth_level_m", river.mouth_level},
                      {"mean_speed_m_s", river.mean_speed},
                      {"centreline_m", points_json(river.centreline)},
                      {"along_m", river.along},
                      {"section_width_m", river.width},
                      {"surface_m", river.surface},
                      {"bed_m", river.bed},
                      {"slope", river.slope},
                      {"grid", grid_json(river.grid)}};
        // The weights of the query texels are the only part of them not held elsewhere.
        const std::size_t n = river.grid.size();
        std::vector<float> wave_weight(n), still_weight(n);
        for (std::size_t t = 0; t < n; ++t) {
            wave_weight[t] = river.query_texels[t * gpu::kRiverQueryStride + gpu::kRiverQueryWaveWeight];
            still_weight[t] = river.query_texels[t * gpu::kRiverQueryStride + gpu::kRiverQueryStillWeight];
        }
        const std::vector<float> texel = as_floats(river.texel);
        const std::string prefix = fmt::format("river_{:02}_", r);
        if (auto st = write_fields(dir, prefix, river.grid,
                                   {{"texel", &texel, "1"},
                                    {"surface_height", &river.surface_height, "m"},
                                    {"depth", &river.depth, "m"},
                                    {"psi", &river.psi, "m^3/s"},
                                    {"discharge_x", &river.discharge_x, "m^2/s"},
                                    {"discharge_z", &river.discharge_z, "m^2/s"},
                                    {"flow_x", &river.flow_x, "m/s"},
                                    {"flow_z", &river.flow_z, "m/s"},
                                    {"channel_s", &river.channel_s, "m"},
                                    {"channel_n", &river.channel_n, "m"},
                                    {"tangent_x", &river.tangent_x, "1"},
                                    {"tangent_z", &river.tangent_z, "1"},
                                    {"wave_weight", &wave_weight, "1"},
                                    {"still_weight", &still_weight, "1"}},
                                   entry["fields"]);
            !st)
            return st;
        if (river.cut)
            if (auto st =
                    write_fields(dir, prefix, river.grid, {{"cut_depth", &river.cut->depth, "m"}}, entry["fields"]);
                !st)
                return st;
        sidecar["rivers"].push_back(entry);
    }
    return detail::write_text_file(dir / kBodiesSidecar, sidecar.dump(2));
}

}  // namespace tidewater
