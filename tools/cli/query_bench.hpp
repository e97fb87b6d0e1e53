// Query throughput and accuracy measurement behind `tidewater bench`:
// the SIMD Newton queries against the seed project's fixed-point loop, on
// spectrum-generated wave sets, one thread and all threads, each with its
// maximum height error against a tight double-precision solve.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater::cli {

struct BenchConfig {
    std::vector<int> wave_counts{8, 32, 64};
    std::size_t points = 200000;  ///< Query points per timed run.
    int repeats = 3;              ///< Best of this many runs is reported.
    double steepness = 0.7;       ///< Target sum(Q*k*A) of the generated sets.
    std::uint64_t seed = 42;
    unsigned threads = 0;                 ///< "All threads" count; 0 = hardware concurrency.
    std::size_t accuracy_samples = 2000;  ///< Points checked against the exact solve.
};

struct MethodResult {
    std::string method;
    unsigned threads = 1;
    double queries_per_second = 0.0;
    double max_height_error = 0.0;  ///< m, against the exact solve.
};

struct WaveCountResult {
    int waves = 0;
    double fold_measure = 0.0;
    double mean_iterations = 0.0;  ///< Newton evaluations per query.
    std::vector<MethodResult> methods;
};

struct BenchReport {
    std::string kernel;
    unsigned hardware_threads = 1;
    unsigned threads = 1;
    BenchConfig config;
    std::vector<WaveCountResult> results;
};

Result<BenchReport> run_query_bench(const BenchConfig& config, const std::function<void(const std::string&)>& progress);
nlohmann::json to_json(const BenchReport& report);
/// A Markdown table of the report (as in docs/PERFORMANCE.md).
std::string to_markdown(const BenchReport& report);

}  // namespace tidewater::cli
