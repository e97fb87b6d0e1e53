// The lakes-and-rivers bake benchmark behind `tidewater bench --bodies`: a 4 km x 4 km
// heightmap at 1024^2 and 2048^2 with three rivers (one joining another, one round a
// knoll) and a lake, baked on one and two threads with the time of each stage, the
// re-bake after editing one reach, and the default scene.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater::cli {

struct BodiesBenchConfig {
    bool include_2048 = true;
    int repeats = 3;  ///< runs per measurement; the best is kept
};

Result<nlohmann::json> run_bodies_bench(const BodiesBenchConfig& config,
                                        const std::function<void(const std::string&)>& progress);
std::string bodies_bench_markdown(const nlohmann::json& report);

}  // namespace tidewater::cli
