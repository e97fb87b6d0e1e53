// The fit benchmark: phase-resolved fit time and R^2 against the number of waves for
// a 30-minute buoy record and a wave-tank record, on one thread and on all.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater::cli {

Result<nlohmann::json> run_fit_bench(const std::filesystem::path& refdata, unsigned threads,
                                     const std::function<void(const std::string&)>& progress);
std::string fit_bench_markdown(const nlohmann::json& report);

}  // namespace tidewater::cli
