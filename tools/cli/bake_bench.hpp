// The shore bake benchmark behind `tidewater bench --bake`: the signed distance
// field of a coastline with >= 10^4 segments at 1024^2 (and 4096^2), the per-wave
// phase fields, one thread and all threads, the CGAL distance against brute
// force (exactness and speed), and query throughput with the shore on and off.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater::cli {

struct BakeBenchConfig {
    bool include_4096 = true;
    unsigned threads = 0;  ///< "All threads"; 0 = hardware concurrency.
};

Result<nlohmann::json> run_bake_bench(const BakeBenchConfig& config,
                                      const std::function<void(const std::string&)>& progress);
std::string bake_bench_markdown(const nlohmann::json& report);

}  // namespace tidewater::cli
