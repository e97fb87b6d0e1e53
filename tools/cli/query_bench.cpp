#include "query_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#include "bench_timing.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/gerstner.hpp"
#include "tidewater/query.hpp"
#include "tidewater/spectrum.hpp"
#include "tidewater/water_body.hpp"

namespace tidewater::cli {

namespace {

constexpr double kBenchTime = 1000.25;  // s; away from t = 0 so phases are generic

std::vector<glm::dvec2> random_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<glm::dvec2> pts(n);
    for (auto& p : pts) {
        const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
        const double v = static_cast<double>(rng() >> 11) * 0x1.0p-53;
        p = {2000.0 * u - 1000.0, 2000.0 * v - 1000.0};
    }
    return pts;
}

/// Runs the reference loop over `threads` contiguous chunks.
void reference_parallel(const WaveSet& set, std::span<const glm::dvec2> pts, std::span<double> out, unsigned threads) {
    if (threads <= 1) {
        reference::fixed_point_heights(set, kBenchTime, pts, out);
        return;
    }
    std::vector<std::thread> pool;
    const std::size_t chunk = (pts.size() + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t) {
        const std::size_t b = std::min(pts.size(), t * chunk), e = std::min(pts.size(), b + chunk);
        pool.emplace_back([&, b, e] {
            reference::fixed_point_heights(set, kBenchTime, pts.subspan(b, e - b), out.subspan(b, e - b));
        });
    }
    for (auto& th : pool) th.join();
}

}  // namespace

Result<BenchReport> run_query_bench(const BenchConfig& config,
                                    const std::function<void(const std::string&)>& progress) {
    if (config.points < 1 || config.points > 100'000'000)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("--points: {} is out of range (1 to 1e8)", config.points)};
    if (config.repeats < 1 || config.repeats > 1000)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("--repeats: {} is out of range (1 to 1000)", config.repeats)};
    BenchReport report;
    report.config = config;
    report.kernel = query_kernel_name();
    report.hardware_threads = std::max(1u, std::thread::hardware_concurrency());
    report.threads = config.threads == 0 ? report.hardware_threads : config.threads;

    const std::vector<glm::dvec2> pts = random_points(config.points, config.seed);
    const std::size_t samples = std::min(config.accuracy_samples, pts.size());

    for (int waves : config.wave_counts) {
        SpectrumSpec spec;
        spec.wave_count = waves;
        spec.steepness = config.steepness;
        spec.seed = config.seed;
        spec.wind_speed = 12.0;
        spec.spreading = 4.0;
        auto specs = generate_waves(spec, "bench spectrum");
        if (!specs) return specs.error();
        WaterProfile profile;
        profile.waves = std::move(specs).value();
        auto body = WaterBody::create(profile, 0.0, "bench");
        if (!body) return body.error();
        const WaveSet& set = body->waves();

        WaveCountResult row;
        row.waves = waves;
        row.fold_measure = set.fold_measure();
        if (progress) progress(fmt::format("{} waves: exact reference on {} points", waves, samples));
        std::vector<double> exact(samples);
        for (std::size_t i = 0; i < samples; ++i) exact[i] = reference::query_point(*body, kBenchTime, pts[i]).height;
        auto max_error = [&](const std::vector<double>& h) {
            double e = 0.0;
            for (std::size_t i = 0; i < samples; ++i) e = std::max(e, std::abs(h[i] - exact[i]));
            return e;
        };

        std::vector<double> heights(pts.size());
        std::vector<SurfacePoint> full(pts.size());
        std::vector<unsigned> thread_counts{1u};
        if (report.threads > 1) thread_counts.push_back(report.threads);
        for (unsigned threads : thread_counts) {
            if (progress) progress(fmt::format("{} waves, {} thread(s): timing", waves, threads));
            QueryOptions opt;
            opt.threads = threads;
            Status status;
            const double t_heights =
                best_time(config.repeats, [&] { status = query_heights(*body, kBenchTime, pts, heights, opt); });
            if (!status) return status.error();
            row.methods.push_back(
                {"newton_simd_heights", threads, static_cast<double>(pts.size()) / t_heights, max_error(heights)});

            const double t_full =
                best_time(config.repeats, [&] { status = query_surface(*body, kBenchTime, pts, full, opt); });
            if (!status) return status.error();
            std::vector<double> full_heights(pts.size());
            double iterations = 0.0;
            for (std::size_t i = 0; i < pts.size(); ++i) {
                full_heights[i] = full[i].height;
                iterations += full[i].iterations;
            }
            row.mean_iterations = iterations / static_cast<double>(pts.size());
            row.methods.push_back(
                {"newton_simd_full", threads, static_cast<double>(pts.size()) / t_full, max_error(full_heights)});

            const double t_ref = best_time(config.repeats, [&] { reference_parallel(set, pts, heights, threads); });
            row.methods.push_back(
                {"fixed_point_reference", threads, static_cast<double>(pts.size()) / t_ref, max_error(heights)});
        }
        report.results.push_back(std::move(row));
    }
    return report;
}

namespace {

const MethodResult* find(const WaveCountResult& r, const std::string& method, unsigned threads) {
    for (const auto& m : r.methods)
        if (m.method == method && m.threads == threads) return &m;
    return nullptr;
}

}  // namespace

nlohmann::json to_json(const BenchReport& report) {
    nlohmann::json j;
    j["benchmark"] = "eulerian_height_queries";
    j["kernel"] = report.kernel;
    j["hardware_threads"] = report.hardware_threads;
    j["threads_all"] = report.threads;
    j["points"] = report.config.points;
    j["repeats"] = report.config.repeats;
    j["steepness_target"] = report.config.steepness;
    j["seed"] = report.config.seed;
    j["accuracy_samples"] = std::min(report.config.accuracy_samples, report.config.points);
    j["units"] = {{"queries_per_second", "1/s"}, {"max_height_error", "m"}};
    for (const auto& r : report.results) {
        nlohmann::json row;
        row["waves"] = r.waves;
        row["fold_measure"] = r.fold_measure;
        row["mean_newton_evaluations"] = r.mean_iterations;
        for (const auto& m : r.methods) {
            row["methods"].push_back({{"method", m.method},
                                      {"threads", m.threads},
                                      {"queries_per_second", m.queries_per_second},
                                      {"max_height_error", m.max_height_error}});
        }
        const auto* ours = find(r, "newton_simd_heights", 1);
        const auto* ref = find(r, "fixed_point_reference", 1);
        if (ours && ref) row["speedup_per_core"] = ours->queries_per_second / ref->queries_per_second;
        j["results"].push_back(row);
    }
    return j;
}

std::string to_markdown(const BenchReport& report) {
    std::string s = fmt::format(
        "Kernel `{}`, {} points per run, best of {}, sum(Q k A) target {}, all threads = {}\n\n", report.kernel,
        report.config.points, report.config.repeats, report.config.steepness, report.threads);
    s += "| waves | sum(QkA) | method | threads | queries/s | max height error (m) | Newton evals |\n";
    s += "|---:|---:|---|---:|---:|---:|---:|\n";
    for (const auto& r : report.results) {
        for (const auto& m : r.methods) {
            s += fmt::format("| {} | {:.3f} | {} | {} | {:.3g} | {:.2e} | {} |\n", r.waves, r.fold_measure, m.method,
                             m.threads, m.queries_per_second, m.max_height_error,
                             m.method == "fixed_point_reference" ? std::string("4 (fixed)")
                                                                 : fmt::format("{:.2f}", r.mean_iterations));
        }
    }
    s += "\n| waves | speed-up per core (heights) | speed-up, all threads |\n|---:|---:|---:|\n";
    for (const auto& r : report.results) {
        const auto* o1 = find(r, "newton_simd_heights", 1);
        const auto* r1 = find(r, "fixed_point_reference", 1);
        const auto* on = find(r, "newton_simd_heights", report.threads);
        const auto* rn = find(r, "fixed_point_reference", report.threads);
        if (o1 && r1 && on && rn)
            s += fmt::format("| {} | {:.1f}x | {:.1f}x |\n", r.waves, o1->queries_per_second / r1->queries_per_second,
                             on->queries_per_second / rn->queries_per_second);
    }
    return s;
}

}  // namespace tidewater::cli
