// The shore query benchmark behind `tidewater bench` (printed beside the open-sea
// table): the default island's ocean (24 waves), queried on open water, near the
// shore (waterline, surf zone, swash) and as a game would (batches of 400 points
// near the shore, each call timed with its overhead: a harbour of 100 boats frame after
// frame, and scattered cold-cache batches), with the SIMD results'
// worst height and normal error against the scalar double path.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater::cli {

struct ShoreBenchConfig {
    std::size_t points = 100000;  ///< Points per timed throughput run.
    int repeats = 3;              ///< Best of this many runs.
    int batch_calls = 2000;       ///< Timed calls of the 400-point batch (the median is reported).
    unsigned threads = 0;         ///< "All threads"; 0 = every hardware thread.
    std::size_t accuracy_samples = 3000;
};

Result<nlohmann::json> run_shore_query_bench(const ShoreBenchConfig& config,
                                             const std::function<void(const std::string&)>& progress);
std::string shore_query_bench_markdown(const nlohmann::json& report);

}  // namespace tidewater::cli
