// Wall-clock timing shared by the benchmarks.
#pragma once

#include <algorithm>
#include <chrono>

namespace tidewater::cli {

/// Best wall time of `repeats` runs of `work`, in seconds.
template <typename Work>
double best_time(int repeats, const Work& work) {
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        work();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

}  // namespace tidewater::cli
