#include "shore_query_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "bench_timing.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kBenchTime = 1000.25;  // s
constexpr std::size_t kBatch = 400;     // 100 floating objects, 4 points each
constexpr double kBoatSpeed = 1.0;      // m/s, the harbour boats' drift

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Points on the shore grid where the signed shore distance lies in [lo, hi] m, jittered
/// within their texel, in a fixed random order.
std::vector<glm::dvec2> shore_band(const ShoreWaves& shore, double lo, double hi, std::size_t count,
                                   std::uint64_t seed) {
    std::vector<glm::dvec2> centres;
    const int n = shore.resolution();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double d = shore.texel_values(i, j).shore_distance();
            if (d >= lo && d <= hi) centres.push_back(shore.corner() + shore.texel() * glm::dvec2(i + 0.5, j + 0.5));
        }
    std::vector<glm::dvec2> pts;
    if (centres.empty()) return pts;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.5, 0.5);
    for (std::size_t k = 0; k < count; ++k) {
        const glm::dvec2 c = centres[rng() % centres.size()];
        pts.push_back(c + shore.texel() * glm::dvec2(jitter(rng), jitter(rng)));
    }
    return pts;
}

std::vector<glm::dvec2> open_sea(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1000.0, 1000.0);
    std::vector<glm::dvec2> pts(count);
    for (auto& p : pts) p = {u(rng), u(rng)};
    return pts;
}

struct Accuracy {
    double height = 0.0;  // m
    double normal_deg = 0.0;
    double dry_motion = 0.0;  // largest |displacement| + |velocity| at dry points
    std::size_t dry = 0;
    std::size_t unconverged = 0;  // points either path left unconverged (not compared)
};

Accuracy accuracy(const WaterBody& body, const std::vector<glm::dvec2>& pts, std::size_t samples) {
    Accuracy a;
    const std::size_t n = std::min(samples, pts.size());
    std::vector<SurfacePoint> simd(n);
    (void)query_surface(body, kBenchTime, std::span(pts.data(), n), simd);
    for (std::size_t i = 0; i < n; ++i) {
        const SurfacePoint ref = reference::query_point(body, kBenchTime, pts[i]);
        // A stalled solve (the known waterline limit, docs/physics.md) ends wherever its
        // last iteration did: counted, not compared.
        if (!simd[i].converged || !ref.converged) {
            ++a.unconverged;
            continue;
        }
        a.height = std::max(a.height, std::abs(simd[i].height - ref.height));
        const double c = std::clamp(glm::dot(simd[i].normal, ref.normal), -1.0, 1.0);
        a.normal_deg = std::max(a.normal_deg, std::acos(c) * 180.0 / kPi);
        if (ref.depth < 0.0 && simd[i].depth < 0.0) {
            ++a.dry;
            a.dry_motion = std::max(a.dry_motion, glm::length(simd[i].displacement) + glm::length(simd[i].velocity));
        }
    }
    return a;
}

}  // namespace

Result<nlohmann::json> run_shore_query_bench(const ShoreBenchConfig& config,
                                             const std::function<void(const std::string&)>& progress) {
    if (progress) progress("shore: loading and baking the default island");
    auto parsed = default_scene();
    if (!parsed) return parsed.error();
    auto scene = bake_scene(*parsed);
    if (!scene) return scene.error();
    const std::shared_ptr<const Scene> baked = std::move(scene).value();
    const WaterBody& shore_body = baked->ocean;
    if (!shore_body.shore() || shore_body.shore()->trivial())
        return Error{ErrorCode::invalid_argument, "shore bench: the default scene has no shore model"};
    auto open_body = shore_body.with_shore(nullptr);
    if (!open_body) return open_body.error();
    const ShoreWaves& shore = *shore_body.shore();

    // Near the shore: the surf zone and the waterline, a little dry beach included.
    const std::vector<glm::dvec2> near = shore_band(shore, -5.0, 120.0, config.points, 7);
    const std::vector<glm::dvec2> open = open_sea(config.points, 8);
    if (near.empty()) return Error{ErrorCode::invalid_argument, "shore bench: no shore texels in the default scene"};

    nlohmann::json j;
    j["benchmark"] = "shore_queries";
    j["kernel"] = query_kernel_name();
    j["waves"] = shore_body.waves().size();
    j["points"] = config.points;
    j["units"] = {
        {"queries_per_second", "1/s"}, {"batch_ms", "ms"}, {"height_error", "m"}, {"normal_error", "degrees"}};

    std::vector<unsigned> thread_counts{1u};
    const unsigned all = config.threads == 0 ? 0u : config.threads;
    if (all != 1u) thread_counts.push_back(all);
    std::vector<SurfacePoint> full(config.points);
    std::vector<double> heights(config.points);
    for (unsigned threads : thread_counts) {
        QueryOptions opt;
        opt.threads = threads;
        nlohmann::json row;
        row["threads"] = threads == 0 ? std::string("all") : std::to_string(threads);
        struct Case {
            const char* name;
            const WaterBody* body;
            const std::vector<glm::dvec2>* pts;
        };
        for (const Case& c : {Case{"open_water", &*open_body, &open}, Case{"shore", &shore_body, &near}}) {
            if (progress)
                progress(
                    fmt::format("shore: {} with {} thread(s)", c.name, threads == 0 ? "all" : std::to_string(threads)));
            Status st;
            const double th =
                best_time(config.repeats, [&] { st = query_heights(*c.body, kBenchTime, *c.pts, heights, opt); });
            if (!st) return st.error();
            const double tf =
                best_time(config.repeats, [&] { st = query_surface(*c.body, kBenchTime, *c.pts, full, opt); });
            if (!st) return st.error();
            double evals = 0.0;
            for (const auto& p : full) evals += p.iterations;
            row[c.name] = {{"heights_per_second", static_cast<double>(c.pts->size()) / th},
                           {"surface_per_second", static_cast<double>(c.pts->size()) / tf},
                           {"mean_newton_evaluations", evals / static_cast<double>(full.size())}};
        }
        row["shore_over_open_heights"] =
            row["shore"]["heights_per_second"].get<double>() / row["open_water"]["heights_per_second"].get<double>();
        row["shore_over_open_surface"] =
            row["shore"]["surface_per_second"].get<double>() / row["open_water"]["surface_per_second"].get<double>();
        j["throughput"].push_back(row);
    }

    // A game frame: 400 points near the shore in one call, on the caller's thread. The
    // harbour is what seed 000 budgets: the same 100 boats, 4 hull corners each, frame
    // after frame (their shore texels stay in cache). Scattered batches take 400 new
    // points from the whole band every call: the cold-cache worst case.
    if (progress) progress("shore: 400-point batches");
    const std::vector<glm::dvec2> boats = shore_band(shore, 2.0, 120.0, kBatch / 4, 9);
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> heading_dist(0.0, 2.0 * kPi);
    std::vector<double> heading(boats.size());
    for (double& h : heading) h = heading_dist(rng);
    auto harbour_frame = [&](int frame, std::vector<glm::dvec2>& pts) {
        pts.clear();
        const double t = frame / 60.0;
        for (std::size_t b = 0; b < boats.size(); ++b) {
            const glm::dvec2 fwd(std::cos(heading[b]), std::sin(heading[b])), side(-fwd.y, fwd.x);
            const glm::dvec2 centre = boats[b] + kBoatSpeed * t * fwd;
            for (const glm::dvec2 corner :
                 {glm::dvec2(2.0, 1.0), glm::dvec2(2.0, -1.0), glm::dvec2(-2.0, 1.0), glm::dvec2(-2.0, -1.0)})
                pts.push_back(centre + corner.x * fwd + corner.y * side);
        }
    };
    for (const char* scenario : {"harbour", "scattered"}) {
        const bool harbour = std::string(scenario) == "harbour";
        for (const char* kind : {"heights", "surface"}) {
            std::vector<double> times;
            std::vector<SurfacePoint> out(kBatch);
            std::vector<double> h(kBatch);
            std::vector<glm::dvec2> frame_points;
            for (int call = 0; call < config.batch_calls; ++call) {
                std::span<const glm::dvec2> batch;
                if (harbour) {
                    harbour_frame(call, frame_points);
                    batch = frame_points;
                } else {
                    const std::size_t at = (static_cast<std::size_t>(call) * kBatch) % (near.size() - kBatch + 1);
                    batch = std::span<const glm::dvec2>(near.data() + at, kBatch);
                }
                const double time = kBenchTime + call / 60.0;
                const auto t0 = Clock::now();
                const Status st = std::string(kind) == "heights"
                                      ? query_heights(shore_body, time, batch, std::span(h.data(), batch.size()))
                                      : query_surface(shore_body, time, batch, std::span(out.data(), batch.size()));
                times.push_back(seconds_since(t0));
                if (!st) return st.error();
            }
            std::sort(times.begin(), times.end());
            j["batch_400"][scenario][kind] = {{"median_ms", times[times.size() / 2] * 1e3},
                                              {"p95_ms", times[times.size() * 95 / 100] * 1e3}};
        }
    }

    if (progress) progress("shore: accuracy against the scalar double path");
    const Accuracy a = accuracy(shore_body, near, config.accuracy_samples);
    const Accuracy o = accuracy(*open_body, open, config.accuracy_samples);
    j["accuracy"] = {{"shore_max_height_error", a.height},
                     {"shore_max_normal_error", a.normal_deg},
                     {"open_max_height_error", o.height},
                     {"open_max_normal_error", o.normal_deg},
                     {"dry_points", a.dry},
                     {"dry_max_motion", a.dry_motion},
                     {"shore_unconverged", a.unconverged},
                     {"samples", std::min(config.accuracy_samples, near.size())}};
    return j;
}

std::string shore_query_bench_markdown(const nlohmann::json& r) {
    std::string s =
        fmt::format("Default island, {} waves, kernel `{}`, {} points per run\n\n", r["waves"].get<std::size_t>(),
                    r["kernel"].get<std::string>(), r["points"].get<std::size_t>());
    s += "| threads | case | heights/s | surface/s | Newton evals |\n|---|---|---:|---:|---:|\n";
    for (const auto& row : r["throughput"]) {
        for (const char* c : {"open_water", "shore"})
            s += fmt::format("| {} | {} | {:.3g} | {:.3g} | {:.2f} |\n", row["threads"].get<std::string>(), c,
                             row[c]["heights_per_second"].get<double>(), row[c]["surface_per_second"].get<double>(),
                             row[c]["mean_newton_evaluations"].get<double>());
        s += fmt::format("| {} | **shore / open** | **{:.2f}** | **{:.2f}** | |\n", row["threads"].get<std::string>(),
                         row["shore_over_open_heights"].get<double>(), row["shore_over_open_surface"].get<double>());
    }
    const auto& b = r["batch_400"];
    s += "\n400 points near the shore, one call on one thread (median, p95 in brackets):\n\n"
         "| batch | heights (ms) | full surface (ms) |\n|---|---:|---:|\n";
    for (const char* scenario : {"harbour", "scattered"})
        s += fmt::format(
            "| {} | {:.4f} ({:.4f}) | {:.4f} ({:.4f}) |\n", scenario, b[scenario]["heights"]["median_ms"].get<double>(),
            b[scenario]["heights"]["p95_ms"].get<double>(), b[scenario]["surface"]["median_ms"].get<double>(),
            b[scenario]["surface"]["p95_ms"].get<double>());
    const auto& a = r["accuracy"];
    s += fmt::format(
        "\nAgainst the scalar double path ({} points, {} left unconverged by either): shore height {:.2e} m, normal "
        "{:.2e} deg; "
        "open water height {:.2e} m, normal {:.2e} deg; {} dry points, largest displacement + velocity {:.1e}\n",
        a["samples"].get<std::size_t>(), a["shore_unconverged"].get<std::size_t>(),
        a["shore_max_height_error"].get<double>(), a["shore_max_normal_error"].get<double>(),
        a["open_max_height_error"].get<double>(), a["open_max_normal_error"].get<double>(),
        a["dry_points"].get<std::size_t>(), a["dry_max_motion"].get<double>());
    return s;
}

}  // namespace tidewater::cli
