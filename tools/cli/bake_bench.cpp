#include "bake_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/query.hpp"
#include "tidewater/ripples.hpp"
#include "tidewater/spectrum.hpp"

namespace tidewater::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// An archipelago: fractal noise crossing the water level gives hundreds of islands and
/// well over 10^4 shoreline segments at 1024^2 over 3 km.
Terrain archipelago() {
    auto img = std::make_shared<Gray16Image>();
    const int n = 2048;
    img->width = img->height = n;
    img->pixels.resize(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::dvec2 q = glm::dvec2((i - n / 2) * 1.5, (j - n / 2) * 1.5) / 400.0;
            double h = 0.0, a = 30.0;
            for (int o = 0; o < 6; ++o) {
                h += a * gradient_noise(q, 11u + static_cast<std::uint32_t>(o)).value;
                q *= 2.3;
                a *= 0.62;
            }
            img->pixels[static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::clamp((h + 60.0) / 120.0 * 65535.0, 0.0, 65535.0));
        }
    HeightmapTerrain t;
    t.file = "<archipelago>";
    t.size = {3072.0, 3072.0};
    t.min_height = -60.0;
    t.max_height = 60.0;
    t.image = img;
    return Terrain(t);
}

}  // namespace

Result<nlohmann::json> run_bake_bench(const BakeBenchConfig& config,
                                      const std::function<void(const std::string&)>& progress) {
    const unsigned all = config.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : config.threads;
    auto say = [&](const std::string& s) {
        if (progress) progress(s);
    };
    nlohmann::json report;
    report["benchmark"] = "shore_bake";
    report["threads_all"] = all;
    report["coastline"] = "archipelago: 6-octave noise heightmap, 3072 m square";
    const Terrain terrain = archipelago();

    // Signed distance fields.
    std::vector<int> sizes{1024};
    if (config.include_4096) sizes.push_back(4096);
    std::unique_ptr<ShoreField> kept;
    for (int res : sizes) {
        for (unsigned threads : {1u, all}) {
            if (threads == all && all == 1 && !report["distance_fields"].empty()) continue;
            say(fmt::format("signed distance {}^2, {} thread(s)", res, threads));
            BakeOptions o;
            o.resolution = res;
            o.threads = threads;
            const auto t0 = Clock::now();
            auto field = bake_shore(terrain, 0.0, o);
            const double s = seconds_since(t0);
            if (!field) return field.error();
            report["distance_fields"].push_back({{"resolution", res},
                                                 {"threads", threads},
                                                 {"seconds", s},
                                                 {"segments", field->segment_count},
                                                 {"land_polygons", field->polygons},
                                                 {"enclosed_waters", field->holes},
                                                 {"stages_seconds",
                                                  {{"heights", field->timings.heights},
                                                   {"contour", field->timings.contour},
                                                   {"simplify", field->timings.simplify},
                                                   {"tree", field->timings.tree},
                                                   {"distance", field->timings.distance}}},
                                                 {"queries_per_second", res * double(res) / s}});
            if (res == 1024 && threads == 1) kept = std::make_unique<ShoreField>(std::move(field).value());
        }
    }

    // CGAL against brute force on a subset of the 1024^2 texels: exactness and speed.
    say("brute-force distance on 4096 texels");
    double worst = 0.0;
    const auto t0 = Clock::now();
    int samples = 0;
    for (int j = 3; j < kept->resolution; j += 16)
        for (int i = 7; i < kept->resolution; i += 16) {
            const double brute = reference::brute_force_shore_distance(*kept, kept->texel_center(i, j));
            worst = std::max(worst,
                             std::abs(brute - std::abs(static_cast<double>(kept->signed_distance[kept->index(i, j)]))));
            ++samples;
        }
    const double brute_seconds = seconds_since(t0);
    report["brute_force"] = {{"samples", samples},
                             {"seconds_per_query", brute_seconds / samples},
                             {"max_difference_m", worst},
                             {"note", "CGAL values are stored as float: differences are float rounding of metres"}};

    // Per-wave phase fields for a 24-wave spectrum.
    SpectrumSpec spec;
    spec.wave_count = 24;
    spec.wind_speed = 12.0;
    auto specs = generate_waves(spec, "bench");
    if (!specs) return specs.error();
    auto set = WaveSet::create(*specs, FoldPolicy::clamp, "bench");
    if (!set) return set.error();
    for (int res : {256, 512}) {
        for (unsigned threads : {1u, all}) {
            say(fmt::format("phase fields {}^2 x 24 waves, {} thread(s)", res, threads));
            ShoreWaveOptions o;
            o.resolution = res;
            o.threads = threads;
            const auto t1 = Clock::now();
            auto shore = bake_shore_waves(*set, terrain, 0.0, o);
            if (!shore) return shore.error();
            report["phase_fields"].push_back(
                {{"resolution", res}, {"waves", 24}, {"threads", threads}, {"seconds", seconds_since(t1)}});
        }
    }

    // Query throughput with the shore on and off (24 waves, 100k points over the archipelago).
    say("queries with the shore on and off");
    ShoreWaveOptions so;
    so.resolution = 256;
    auto shore = bake_shore_waves(*set, terrain, 0.0, so);
    if (!shore) return shore.error();
    WaterProfile profile;
    profile.waves = *specs;
    profile.fold_policy = FoldPolicy::clamp;
    auto open = WaterBody::create(profile, 0.0, "bench");
    if (!open) return open.error();
    auto shored_result = open->with_shore(*shore);
    if (!shored_result) return shored_result.error();
    const WaterBody& shored = *shored_result;
    std::vector<glm::dvec2> pts(100000);
    for (std::size_t k = 0; k < pts.size(); ++k)
        pts[k] = {std::fmod(static_cast<double>(k) * 37.71, 3000.0) - 1500.0,
                  std::fmod(static_cast<double>(k) * 91.13, 3000.0) - 1500.0};
    std::vector<SurfacePoint> out(pts.size());
    const WaterBody& open_body = *open;
    for (auto [name, body] : {std::pair<const char*, const WaterBody*>{"open_water_simd", &open_body},
                              std::pair<const char*, const WaterBody*>{"shore", &shored}}) {
        for (unsigned threads : {1u, all}) {
            QueryOptions qo;
            qo.threads = threads;
            const auto t2 = Clock::now();
            if (auto st = query_surface(*body, 10.0, pts, out, qo); !st) return st.error();
            report["queries"].push_back({{"mode", name},
                                         {"threads", threads},
                                         {"queries_per_second", static_cast<double>(pts.size()) / seconds_since(t2)}});
        }
    }
    return report;
}

std::string bake_bench_markdown(const nlohmann::json& r) {
    std::string s = fmt::format("Coastline: {}. All threads = {}.\n\n", r["coastline"].get<std::string>(),
                                r["threads_all"].get<unsigned>());
    s += "| signed distance field | threads | seconds | heights | contour | simplify | tree | distances | segments | "
         "land polygons | "
         "enclosed waters |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& d : r["distance_fields"]) {
        const auto& st = d["stages_seconds"];
        s += fmt::format("| {}^2 | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {} | {} | {} |\n",
                         d["resolution"].get<int>(), d["threads"].get<unsigned>(), d["seconds"].get<double>(),
                         st["heights"].get<double>(), st["contour"].get<double>(), st["simplify"].get<double>(),
                         st["tree"].get<double>(), st["distance"].get<double>(), d["segments"].get<std::size_t>(),
                         d["land_polygons"].get<std::size_t>(), d["enclosed_waters"].get<std::size_t>());
    }
    const auto& b = r["brute_force"];
    s += fmt::format(
        "\nBrute force over every segment: {:.1f} us per texel ({} texels), max |CGAL - brute force| = {:.2g} m.\n\n",
        b["seconds_per_query"].get<double>() * 1e6, b["samples"].get<int>(), b["max_difference_m"].get<double>());
    s += "| phase fields (24 waves) | threads | seconds |\n|---|---:|---:|\n";
    for (const auto& p : r["phase_fields"])
        s += fmt::format("| {}^2 | {} | {:.2f} |\n", p["resolution"].get<int>(), p["threads"].get<unsigned>(),
                         p["seconds"].get<double>());
    s += "\n| queries (24 waves) | threads | queries/s |\n|---|---:|---:|\n";
    for (const auto& q : r["queries"])
        s += fmt::format("| {} | {} | {:.3g} |\n", q["mode"].get<std::string>(), q["threads"].get<unsigned>(),
                         q["queries_per_second"].get<double>());
    return s;
}

}  // namespace tidewater::cli
