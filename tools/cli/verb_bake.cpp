// tidewater bake: the shore fields of a scene as 16-bit PNGs with a JSON sidecar.
// The folder is written under a temporary name and renamed when complete, so a
// failed bake never leaves a partial folder behind.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "scene_option.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/image_io.hpp"
#include "tidewater/shore_bake.hpp"
#include "tidewater/shore_waves.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

namespace fs = std::filesystem;

struct BakeArgs {
    std::string scene;
    std::string out;
    int resolution = 1024;
    double tolerance = 0.0;
    unsigned threads = 0;
    bool quiet = false;
};

/// Encodes a float field as 16-bit: value = offset + scale * pixel / 65535.
nlohmann::json write_field(const fs::path& dir, const std::string& name, const std::vector<float>& values, int n,
                           double lo, double hi, const char* unit, Status& status) {
    if (!(hi > lo)) hi = lo + 1.0;
    Gray16Image img;
    img.width = img.height = n;
    img.pixels.resize(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
        const double t = std::clamp((static_cast<double>(values[k]) - lo) / (hi - lo), 0.0, 1.0);
        img.pixels[k] = static_cast<std::uint16_t>(std::lround(t * 65535.0));
    }
    if (status) status = write_png_gray16(dir / (name + ".png"), img);
    return {{"file", name + ".png"}, {"unit", unit}, {"offset", lo}, {"scale", hi - lo},
            {"decode", "value = offset + scale * pixel / 65535"}};
}

int run_bake(const BakeArgs& a) {
    constexpr const char* verb = "bake";
    if (a.out.empty()) return fail(verb, "give --out DIR");
    auto scene = load_scene_option(a.scene);
    if (!scene) return fail(verb, scene.error().message);
    BakeOptions options;
    options.resolution = a.resolution;
    options.simplify_tolerance = a.tolerance;
    options.threads = a.threads;
    int last_percent = -10;
    options.progress = [&](double f) {
        const int percent = static_cast<int>(f * 100.0);
        if (!a.quiet && percent >= last_percent + 10) {
            std::fprintf(stderr, "bake: %d%%\n", percent);
            last_percent = percent;
        }
    };
    auto field = bake_shore(scene->terrain, scene->water_level, options);
    if (!field) return fail(verb, field.error().message);

    const fs::path target = a.out;
    fs::path temp = target;
    temp += fmt::format(".tmp-{}", ::getpid());
    std::error_code ec;
    fs::remove_all(temp, ec);
    fs::create_directories(temp, ec);
    if (ec) return fail(verb, fmt::format("{}: cannot create folder: {}", temp.string(), ec.message()));
    struct Cleanup {
        fs::path path;
        bool keep = false;
        ~Cleanup() {
            std::error_code ignored;
            if (!keep) fs::remove_all(path, ignored);
        }
    } cleanup{temp};

    const int n = field->resolution;
    const auto [dmin, dmax] = std::minmax_element(field->signed_distance.begin(), field->signed_distance.end());
    const auto [hmin, hmax] = std::minmax_element(field->depth.begin(), field->depth.end());
    Status written;
    nlohmann::json fields;
    fields["signed_distance"] = write_field(temp, "signed_distance", field->signed_distance, n, *dmin, *dmax, "m", written);
    fields["gradient_x"] = write_field(temp, "gradient_x", field->gradient_x, n, -1.0, 1.0, "1", written);
    fields["gradient_z"] = write_field(temp, "gradient_z", field->gradient_z, n, -1.0, 1.0, "1", written);
    fields["depth"] = write_field(temp, "depth", field->depth, n, *hmin, *hmax, "m", written);
    if (!written) return fail(verb, written.error().message);

    nlohmann::json lines = nlohmann::json::array();
    for (const ShoreLine& l : field->shorelines) {
        nlohmann::json pts = nlohmann::json::array();
        for (const auto& p : l.points) pts.push_back({p.x, p.y});
        lines.push_back({{"closed", l.closed}, {"points", pts}});
    }
    // The per-wave fields the shaders sample (the scene's shore model, on its own grid).
    nlohmann::json waves = nlohmann::json::array();
    nlohmann::json shore_grid = nullptr;
    const auto& shore = scene->ocean.shore();
    const auto wave_list = scene->ocean.waves().waves();
    for (std::size_t i = 0; i < wave_list.size(); ++i) {
        const Wave& w = wave_list[i];
        nlohmann::json entry = {{"deep_water_wavelength_m", kTwoPi / w.k}, {"omega_rad_s", w.omega}, {"period_s", w.period()},
                                {"direction", {w.dir_x, w.dir_z}}, {"amplitude_m", w.amplitude}};
        if (shore) {
            const auto& phase = shore->phase_residual(i);
            const auto& amp = shore->amplitude_factor(i);
            const auto [pmin, pmax] = std::minmax_element(phase.begin(), phase.end());
            const auto [amin, amax] = std::minmax_element(amp.begin(), amp.end());
            entry["fields"] = {
                {"phase_residual", write_field(temp, fmt::format("wave_{:02}_phase_residual", i), phase, shore->resolution(),
                                               *pmin, *pmax, "rad", written)},
                {"amplitude_factor", write_field(temp, fmt::format("wave_{:02}_amplitude_factor", i), amp, shore->resolution(),
                                                 *amin, *amax, "1", written)}};
        }
        waves.push_back(entry);
    }
    if (shore) {
        shore_grid = {{"resolution", shore->resolution()}, {"texel_m", shore->texel()},
                      {"corner_m", {shore->corner().x, shore->corner().y}},
                      {"breaking", write_field(temp, "breaking", shore->breaking(), shore->resolution(), 0.0, 1.0, "1", written)},
                      {"steepness_scale", write_field(temp, "steepness_scale", shore->steepness_scale(), shore->resolution(), 0.0, 1.0, "1", written)}};
    }
    if (!written) return fail(verb, written.error().message);
    const nlohmann::json sidecar = {
        {"version", 1},
        {"scene", scene->name},
        {"water_level_m", scene->water_level},
        {"resolution", n},
        {"extent", {{"corner_m", {field->corner.x, field->corner.y}}, {"size_m", field->texel * n}, {"texel_m", field->texel},
                    {"rows_along", "+z"}, {"samples_at", "texel centres"}}},
        {"fields", fields},
        {"shoreline", {{"file", "shorelines.json"}, {"segments", field->segment_count}, {"land_polygons", field->polygons},
                       {"enclosed_waters", field->holes}, {"simplify_tolerance_m", field->simplify_tolerance}}},
        {"waves", waves},
        {"shore_waves", shore_grid},
        {"notes", "signed distance is exact to the simplified shoreline (CGAL AABB tree): positive over water"}};
    for (auto [name, json] : {std::pair{"shore.json", sidecar.dump(2)}, std::pair{"shorelines.json", lines.dump()}}) {
        std::ofstream out(temp / name);
        out << json << "\n";
        if (!out) return fail(verb, fmt::format("{}: write failed", (temp / name).string()));
    }
    // Swap the finished folder into place.
    fs::path old = target;
    old += fmt::format(".old-{}", ::getpid());
    const bool had = fs::exists(target);
    if (had) fs::rename(target, old, ec);
    if (!ec) fs::rename(temp, target, ec);
    if (ec) {
        if (had && !fs::exists(target)) fs::rename(old, target);
        return fail(verb, fmt::format("{}: cannot replace folder: {}", target.string(), ec.message()));
    }
    cleanup.keep = true;
    if (had) fs::remove_all(old, ec);
    std::printf("baked \"%s\" at %dx%d (%.2f m texels): %zu shoreline segments, %zu land polygons, %zu enclosed waters -> %s/\n",
                scene->name.c_str(), n, n, field->texel, field->segment_count, field->polygons, field->holes, target.string().c_str());
    return 0;
}

}  // namespace

Verb add_bake_verb(CLI::App& app) {
    auto args = std::make_shared<BakeArgs>();
    CLI::App* cmd = app.add_subcommand("bake", "Bake the shoreline, signed shore distance, its gradient and depth to a folder");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--out", args->out, "Output folder (written whole or not at all)")->required();
    cmd->add_option("--resolution", args->resolution, "Texels per side (8 to 8192)")->capture_default_str();
    cmd->add_option("--tolerance", args->tolerance, "Shoreline simplification tolerance, m (0 = half a texel)");
    cmd->add_option("--threads", args->threads, "Worker threads (0 = all)");
    cmd->add_flag("--quiet", args->quiet, "No progress lines");
    return {cmd, [args] { return run_bake(*args); }};
}

}  // namespace tidewater::cli
