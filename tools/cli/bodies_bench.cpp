#include "bodies_bench.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include "tidewater/body_summary.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::cli {

namespace {

using json = nlohmann::json;

/// A 4 km square falling east to the sea (the coast near x = 1200 m), with hills, a
/// basin for a lake at (-1200, 900) and a knoll 5 m high in the trunk river's bed.
double bench_height(double x, double z) {
    double h = 0.01 * (1200.0 - x) + 8.0 * std::sin(x / 310.0) * std::cos(z / 270.0) + 5.0 * std::sin((x + z) / 190.0) +
               3.0 * std::sin(x / 77.0) * std::sin(z / 91.0);
    const double bx = x + 1200.0, bz = z - 900.0;
    h -= 18.0 * std::exp(-(bx * bx + bz * bz) / (2.0 * 180.0 * 180.0));
    const double kx = x + 855.0, kz = z + 145.0;
    h += 5.0 * std::exp(-(kx * kx + kz * kz) / (2.0 * 10.0 * 10.0));
    return h;
}

constexpr double kSize = 4000.0, kMin = -60.0, kMax = 140.0;

Terrain bench_terrain(int n) {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = n;
    image->pixels.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // Pixel centres span the extent (as HeightmapTerrain samples them).
            const double x = (static_cast<double>(i) / (n - 1) - 0.5) * kSize,
                         z = (static_cast<double>(j) / (n - 1) - 0.5) * kSize;
            const double v = (bench_height(x, z) - kMin) / (kMax - kMin);
            image->pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0));
        }
    HeightmapTerrain map;
    map.file = fmt::format("bench_{}.png", n);
    map.size = {kSize, kSize};
    map.min_height = kMin;
    map.max_height = kMax;
    map.image = std::move(image);
    return Terrain(map);
}

/// The lake's level: 1.5 m under the lowest point of a ring round the basin.
double lake_level(const Terrain& t) {
    double low = 1e300;
    for (int k = 0; k < 360; ++k) {
        const double a = k * 3.141592653589793 / 180.0;
        low = std::min(low, t.height_at({-1200.0 + 380.0 * std::cos(a), 900.0 + 380.0 * std::sin(a)}));
    }
    return low - 1.5;
}

Result<Scene> bench_scene(int n) {
    const Terrain terrain = bench_terrain(n);
    const std::string text = fmt::format(R"({{
      "version": 1, "name": "bench {0}", "water_level": 0.0,
      "terrain": {{ "flat": {{ "height": -10 }} }}, "ocean": "ocean_rolling",
      "lakes": [ {{ "name": "basin", "level": {1}, "at": [-1200, 900], "preset": "lake_rippled" }} ],
      "rivers": [
        {{ "name": "trunk", "path": [[-1900, -300], [-1000, -100], [-200, -350], [600, -150], [1900, -200]],
           "width": [50, 60, 70, 90, 90], "discharge": 80.0 }},
        {{ "name": "branch", "path": [[-1500, -1500], [-900, -1000], [-400, -400], [-250, -330]], "width": 30, "discharge": 25.0 }},
        {{ "name": "east", "path": [[-1600, 1500], [-500, 1300], [600, 1000], [1900, 1100]], "width": 40, "discharge": 40.0 }}
      ] }})",
                                         n, lake_level(terrain));
    auto scene = parse_scene(text, fmt::format("bench_{}.json", n));
    if (!scene) return scene.error();
    scene->terrain = terrain;
    return scene;
}

/// One bake, the wall time of each stage (from the first progress report of a stage to
/// the first of the next) and the total.
struct Timed {
    std::shared_ptr<const Scene> scene;
    std::map<std::string, double> stages;
    double total = 0.0;
};

Result<Timed> timed_bake(const Scene& scene, unsigned threads, int distance_resolution,
                         std::shared_ptr<const Scene> previous = nullptr) {
    Timed out;
    std::string stage;
    auto mark = std::chrono::steady_clock::now();
    const auto start = mark;
    SceneBakeOptions options;
    options.threads = threads;
    options.distance_resolution = distance_resolution;
    options.previous = std::move(previous);
    options.progress = [&](std::string_view s, double) {
        if (s == stage) return;
        const auto now = std::chrono::steady_clock::now();
        if (!stage.empty()) out.stages[stage] += std::chrono::duration<double>(now - mark).count();
        stage = s;
        mark = now;
    };
    auto baked = bake_scene(scene, options);
    if (!baked) return baked.error();
    const auto end = std::chrono::steady_clock::now();
    if (!stage.empty()) out.stages[stage] += std::chrono::duration<double>(end - mark).count();
    out.total = std::chrono::duration<double>(end - start).count();
    out.scene = std::move(baked).value();
    return out;
}

/// The best of `repeats` bakes (by total), with its stage times.
Result<Timed> best_bake(const Scene& scene, unsigned threads, int distance_resolution, int repeats,
                        const std::shared_ptr<const Scene>& previous = nullptr) {
    Result<Timed> best = Error{ErrorCode::internal, "no run"};
    for (int r = 0; r < repeats; ++r) {
        auto run = timed_bake(scene, threads, distance_resolution, previous);
        if (!run) return run.error();
        if (!best || run->total < best->total) best = std::move(run);
    }
    return best;
}

json stages_json(const Timed& t) {
    json stages = json::object();
    for (const auto& [name, seconds] : t.stages) stages[name] = seconds;
    return {{"total_s", t.total}, {"stages_s", stages}};
}

}  // namespace

Result<json> run_bodies_bench(const BodiesBenchConfig& config,
                              const std::function<void(const std::string&)>& progress) {
    json report = {{"benchmark", "lakes and rivers bake"}, {"repeats", config.repeats}};
    std::vector<int> sizes = {1024};
    if (config.include_2048) sizes.push_back(2048);
    for (const int n : sizes) {
        auto scene = bench_scene(n);
        if (!scene) return scene.error();
        json entry = {{"heightmap", n}, {"distance_field", n}, {"shore_model", scene->shore.resolution}};
        std::shared_ptr<const Scene> baked;
        for (const unsigned threads : {1u, 2u}) {
            progress(fmt::format("{}^2 terrain, {} thread(s)", n, threads));
            auto run = best_bake(*scene, threads, n, config.repeats);
            if (!run) return run.error();
            entry[fmt::format("threads_{}", threads)] = stages_json(*run);
            baked = run->scene;
        }
        json rivers = json::array();
        for (const RiverSummary& r : summarize_bodies(*baked).rivers)
            rivers.push_back({{"name", r.name},
                              {"ends_in", r.ends_in},
                              {"receiver", r.receiver},
                              {"length_m", r.length},
                              {"grid", fmt::format("{}x{}", r.grid_nx, r.grid_nz)},
                              {"texel_m", r.texel},
                              {"islands", r.islands},
                              {"mean_speed_m_s", r.mean_speed}});
        entry["rivers"] = rivers;
        // An editor moves one point of the east river by 15 m: only it is baked again.
        Scene edited = *scene;
        edited.rivers[2].path[1].y += 15.0;
        for (const unsigned threads : {1u, 2u}) {
            progress(fmt::format("{}^2 terrain, re-bake after editing one reach, {} thread(s)", n, threads));
            auto run = best_bake(edited, threads, n, config.repeats, baked);
            if (!run) return run.error();
            json r = stages_json(*run);
            r["reused_rivers"] = run->scene->bake->reused.rivers;
            r["reused_lake_shores"] = run->scene->bake->reused.lake_shores;
            r["reused_ocean_shore"] = run->scene->bake->reused.ocean_shore;
            entry[fmt::format("edit_one_reach_threads_{}", threads)] = r;
        }
        report["terrains"].push_back(entry);
    }
    auto parsed = default_scene();
    if (!parsed) return parsed.error();
    for (const unsigned threads : {1u, 2u}) {
        progress(fmt::format("default scene, {} thread(s)", threads));
        auto run = best_bake(*parsed, threads, 0, config.repeats);
        if (!run) return run.error();
        report["default_scene"][fmt::format("threads_{}", threads)] = stages_json(*run);
    }
    return report;
}

std::string bodies_bench_markdown(const json& report) {
    std::string md =
        "| terrain | threads | water bodies | lake shores | shoreline | shore waves | total "
        "|\n|---|---:|---:|---:|---:|---:|---:|\n";
    auto stage = [](const json& run, const char* name) {
        const json& s = run.at("stages_s");
        return s.contains(name) ? fmt::format("{:.3f} s", s.at(name).get<double>()) : std::string("—");
    };
    auto row = [&](const std::string& what, const std::string& threads, const json& run) {
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {:.3f} s |\n", what, threads, stage(run, "water bodies"),
                          stage(run, "lake shores"), stage(run, "shoreline"), stage(run, "shore waves"),
                          run.at("total_s").get<double>());
    };
    for (const json& t : report.at("terrains")) {
        const std::string name = fmt::format("4 km, {0}² heightmap and distance field", t.at("heightmap").get<int>());
        for (const char* threads : {"1", "2"}) row(name, threads, t.at(fmt::format("threads_{}", threads)));
        for (const char* threads : {"1", "2"}) {
            const json& r = t.at(fmt::format("edit_one_reach_threads_{}", threads));
            row(fmt::format("{}: re-bake after moving one point of `east` (reused {} rivers, ocean shore {})", name,
                            r.at("reused_rivers").get<int>(),
                            r.at("reused_ocean_shore").get<bool>() ? "reused" : "re-baked"),
                threads, r);
        }
    }
    for (const char* threads : {"1", "2"})
        row("default scene", threads, report.at("default_scene").at(fmt::format("threads_{}", threads)));
    return md;
}

}  // namespace tidewater::cli
