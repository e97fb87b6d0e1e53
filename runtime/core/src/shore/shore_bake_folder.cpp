// Loading saved shore bakes (the writer is Tidewater::bake's, shore_bake_write.cpp).
#include "tidewater/detail/shore_bake_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/bake_files.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/json_reader.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;
using detail::ObjectReader;

Result<std::vector<float>> read_field(const fs::path& dir, const ObjectReader& fields, std::string_view name, int n) {
    return detail::read_field_png(dir, fields, name, n, n);
}

bool close(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> load_shore_bake(const fs::path& dir, const WaveSet& waves, double water_level,
                                                          const Terrain& terrain, const SquareRegion* region) {
    const fs::path sidecar_path = dir / kShoreSidecar;
    auto doc = detail::read_sidecar(sidecar_path, kShoreBakeFormatVersion);
    if (!doc) return doc.error();
    auto root = ObjectReader::open(*doc, sidecar_path.string(), "");
    if (!root) return root.error();
    double level = 0.0;
    if (auto st = root->number("water_level_m", level, true); !st) return st.error();
    if (!close(level, water_level))
        return root->error(
            "water_level_m",
            fmt::format("the bake was made at water level {} m, the scene's is {} m: re-run tidewater bake", level,
                        water_level));
    if (!root->has("model")) return root->error("model", "is missing");
    auto model = ObjectReader::open(root->at("model"), root->source(), "/model");
    if (!model) return model.error();

    ShoreWaveFields f;
    std::int64_t n = 0;
    if (auto st = model->integer("resolution", n, 2, 8192, true); !st) return st.error();
    f.resolution = static_cast<int>(n);
    if (auto st = model->number("texel_m", f.texel, true); !st) return st.error();
    if (!model->has("corner_m") || !model->at("corner_m").is_array() || model->at("corner_m").size() != 2 ||
        !model->at("corner_m")[0].is_number() || !model->at("corner_m")[1].is_number())
        return model->error("corner_m", "expected [x, z] in metres");
    f.corner = {model->at("corner_m")[0].get<double>(), model->at("corner_m")[1].get<double>()};
    // The grid covers the terrain's extent (or the region), as bake_scene's own bake would.
    const double half = region ? region->half_size : terrain.extent_half_size();
    const glm::dvec2 corner = (region ? region->center : terrain.extent_center()) - glm::dvec2(half);
    if (!close(f.texel * static_cast<double>(n), 2.0 * half) || !close(f.corner.x, corner.x) ||
        !close(f.corner.y, corner.y))
        return model->error(
            "corner_m",
            fmt::format("the bake covers {} m from ({}, {}), the terrain {} m from ({}, {}): "
                        "it was made for another terrain; re-run tidewater bake",
                        f.texel * static_cast<double>(n), f.corner.x, f.corner.y, 2.0 * half, corner.x, corner.y));

    // The waves must be the ones baked for: the fields depend on each one's frequency,
    // direction, amplitude (breaking) and steepness (the fold limit).
    if (!model->has("waves") || !model->at("waves").is_array()) return model->error("waves", "expected an array");
    const auto& list = model->at("waves");
    const auto set = waves.waves();
    if (list.size() != set.size())
        return model->error("waves", fmt::format("the bake has {} waves, the scene's ocean {}: re-run tidewater bake",
                                                 list.size(), set.size()));
    for (std::size_t i = 0; i < set.size(); ++i) {
        auto w = ObjectReader::open(list[i], model->source(), fmt::format("/model/waves/{}", i));
        if (!w) return w.error();
        double omega = 0.0, amplitude = 0.0, steepness = 0.0;
        if (auto st = w->number("omega_rad_s", omega, true); !st) return st.error();
        if (auto st = w->number("amplitude_m", amplitude, true); !st) return st.error();
        if (auto st = w->number("steepness", steepness, true); !st) return st.error();
        const auto& dir_json = w->has("direction") ? w->at("direction") : nlohmann::json();
        if (!dir_json.is_array() || dir_json.size() != 2 || !dir_json[0].is_number() || !dir_json[1].is_number())
            return w->error("direction", "expected [x, z]");
        const Wave& s = set[i];
        if (!close(omega, s.omega) || !close(amplitude, s.amplitude) || !close(steepness, s.steepness) ||
            !close(dir_json[0].get<double>(), s.dir_x) || !close(dir_json[1].get<double>(), s.dir_z))
            return w->error("", "differs from the scene's wave " + std::to_string(i) +
                                    ": the bake was made for other waves; re-run tidewater bake");
        if (!w->has("fields")) return w->error("fields", "is missing");
        auto fields = ObjectReader::open(w->at("fields"), w->source(), w->child_path("fields"));
        if (!fields) return fields.error();
        std::vector<float>* targets[] = {nullptr, nullptr, nullptr, nullptr};
        f.phase_residual.emplace_back(), f.amplitude_factor.emplace_back(), f.wavevector_x.emplace_back(),
            f.wavevector_z.emplace_back();
        targets[0] = &f.phase_residual.back(), targets[1] = &f.amplitude_factor.back();
        targets[2] = &f.wavevector_x.back(), targets[3] = &f.wavevector_z.back();
        const char* names[] = {"phase_residual", "amplitude_factor", "wavevector_x", "wavevector_z"};
        for (int k = 0; k < 4; ++k) {
            auto values = read_field(dir, *fields, names[k], f.resolution);
            if (!values) return values.error();
            *targets[k] = std::move(values).value();
        }
    }
    if (!model->has("fields")) return model->error("fields", "is missing");
    auto fields = ObjectReader::open(model->at("fields"), model->source(), "/model/fields");
    if (!fields) return fields.error();
    std::pair<const char*, std::vector<float>*> shared[] = {{"depth", &f.depth},
                                                            {"shore_distance", &f.shore_distance},
                                                            {"breaking", &f.breaking},
                                                            {"steepness_scale", &f.steepness_scale}};
    for (auto& [name, target] : shared) {
        auto values = read_field(dir, *fields, name, f.resolution);
        if (!values) return values.error();
        *target = std::move(values).value();
    }
    // The terrain must be the one baked over: its depth at every texel, within the encoding.
    const double tolerance = 0.51 * detail::field_png_step(*fields, "depth") + 1e-3;
    for (int j = 0; j < f.resolution; ++j)
        for (int i = 0; i < f.resolution; ++i) {
            const glm::dvec2 p = f.corner + f.texel * glm::dvec2(i + 0.5, j + 0.5);
            const double depth = water_level - terrain.height_at(p);
            const double stored =
                static_cast<double>(f.depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(f.resolution) +
                                            static_cast<std::size_t>(i)]);
            if (!(std::abs(depth - stored) <= tolerance))
                return fields->error(
                    "depth",
                    fmt::format("the terrain differs from the one baked ({:.3f} m deep at x = {:.1f}, z = {:.1f}, "
                                "the bake says {:.3f} m): re-run tidewater bake",
                                depth, p.x, p.y, stored));
        }
    auto made = ShoreWaves::from_fields(std::move(f), set);
    if (!made) {
        Error e = std::move(made).error();
        e.message = fmt::format("{}: {}", dir.string(), e.message);
        return e;
    }
    return made;
}

}  // namespace tidewater
