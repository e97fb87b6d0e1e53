// Writing saved shore bakes (the format is in docs/scene-format.md; shore_bake_folder.cpp
// loads them).
#include "tidewater/detail/shore_bake_write.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/atomic_folder.hpp"
#include "tidewater/detail/bake_files_write.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;

Result<nlohmann::json> write_field(const fs::path& dir, const std::string& name, const std::vector<float>& values,
                                   int n, const char* unit) {
    return detail::write_field_png(dir, name, values, n, n, unit);
}

/// Fills `temp` with the bake.
Status write_bake(const fs::path& temp, const ShoreBakeContents& c) {
    const ShoreWaveFields& f = c.model->fields();
    const int n = f.resolution;
    nlohmann::json model = {{"resolution", n},
                            {"texel_m", f.texel},
                            {"corner_m", {f.corner.x, f.corner.y}},
                            {"size_m", f.texel * n},
                            {"breaking_index", c.breaking_index}};
    const std::pair<const char*, std::pair<const std::vector<float>*, const char*>> shared[] = {
        {"depth", {&f.depth, "m"}},
        {"shore_distance", {&f.shore_distance, "m"}},
        {"breaking", {&f.breaking, "1"}},
        {"steepness_scale", {&f.steepness_scale, "1"}}};
    for (const auto& [name, field] : shared) {
        auto entry = write_field(temp, name, *field.first, n, field.second);
        if (!entry) return entry.error();
        model["fields"][name] = *entry;
    }
    const auto waves = c.waves->waves();
    model["waves"] = nlohmann::json::array();
    for (std::size_t i = 0; i < waves.size(); ++i) {
        const Wave& w = waves[i];
        nlohmann::json entry = {
            {"deep_water_wavelength_m", kTwoPi / w.k}, {"omega_rad_s", w.omega},     {"period_s", w.period()},
            {"direction", {w.dir_x, w.dir_z}},         {"amplitude_m", w.amplitude}, {"steepness", w.steepness}};
        const std::pair<const char*, std::pair<const std::vector<float>*, const char*>> per_wave[] = {
            {"phase_residual", {&f.phase_residual[i], "rad"}},
            {"amplitude_factor", {&f.amplitude_factor[i], "1"}},
            {"wavevector_x", {&f.wavevector_x[i], "rad/m"}},
            {"wavevector_z", {&f.wavevector_z[i], "rad/m"}}};
        for (const auto& [name, field] : per_wave) {
            auto e = write_field(temp, fmt::format("wave_{:02}_{}", i, name), *field.first, n, field.second);
            if (!e) return e.error();
            entry["fields"][name] = *e;
        }
        model["waves"].push_back(entry);
    }
    nlohmann::json sidecar = {{"version", kShoreBakeFormatVersion},
                              {"scene", c.scene_name},
                              {"water_level_m", c.water_level},
                              {"encoding", detail::kFieldEncoding},
                              {"model", model}};
    if (const ShoreField* d = c.distance_field) {
        nlohmann::json dist = {{"resolution", d->resolution},
                               {"texel_m", d->texel},
                               {"corner_m", {d->corner.x, d->corner.y}},
                               {"size_m", d->texel * d->resolution},
                               {"shoreline",
                                {{"file", "shorelines.json"},
                                 {"segments", d->segment_count},
                                 {"land_polygons", d->polygons},
                                 {"enclosed_waters", d->holes},
                                 {"simplify_tolerance_m", d->simplify_tolerance}}},
                               {"notes", "exact distance to the simplified shoreline (CGAL): positive over water"}};
        const std::pair<const char*, std::pair<const std::vector<float>*, const char*>> fields[] = {
            {"signed_distance", {&d->signed_distance, "m"}},
            {"gradient_x", {&d->gradient_x, "1"}},
            {"gradient_z", {&d->gradient_z, "1"}},
            {"depth", {&d->depth, "m"}}};
        for (const auto& [name, field] : fields) {
            auto e = write_field(temp, fmt::format("distance_{}", name), *field.first, d->resolution, field.second);
            if (!e) return e.error();
            dist["fields"][name] = *e;
        }
        nlohmann::json lines = nlohmann::json::array();
        for (const ShoreLine& l : d->shorelines) {
            nlohmann::json pts = nlohmann::json::array();
            for (const auto& p : l.points) pts.push_back({p.x, p.y});
            lines.push_back({{"closed", l.closed}, {"points", pts}});
        }
        if (auto st = detail::write_text_file(temp / "shorelines.json", lines.dump()); !st) return st;
        sidecar["distance_field"] = dist;
    }
    return detail::write_text_file(temp / kShoreSidecar, sidecar.dump(2));
}

}  // namespace

Status write_shore_bake_into(const fs::path& dir, const ShoreBakeContents& contents) {
    if (!contents.model || !contents.waves)
        return Error{ErrorCode::invalid_argument, "save_shore_bake: the model and its waves are required"};
    if (contents.model->wave_count() != contents.waves->size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("save_shore_bake: the model has {} waves, the wave set {}",
                                 contents.model->wave_count(), contents.waves->size())};
    return write_bake(dir, contents);
}

Status save_shore_bake(const fs::path& dir, const ShoreBakeContents& contents) {
    return detail::write_folder_atomically(dir,
                                           [&](const fs::path& temp) { return write_shore_bake_into(temp, contents); });
}

}  // namespace tidewater
