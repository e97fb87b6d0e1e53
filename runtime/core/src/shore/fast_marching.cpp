#include "fast_marching.hpp"

#include <cmath>
#include <queue>

namespace tidewater::detail {

void fast_march(const std::vector<double>& slowness, std::vector<double>& value, int n, double h) {
    enum : unsigned char { kFar, kTrial, kKnown };
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    std::vector<unsigned char> state(count, kFar);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
    for (std::size_t k = 0; k < count; ++k) {
        if (std::isfinite(value[k])) {
            state[k] = kKnown;
        }
    }
    auto neighbour_min = [&](int i, int j, int di, int dj) {
        double best = kUnreached;
        for (int s : {-1, 1}) {
            const int a = i + s * di, b = j + s * dj;
            if (a < 0 || b < 0 || a >= n || b >= n) continue;
            const std::size_t k = static_cast<std::size_t>(b) * static_cast<std::size_t>(n) + static_cast<std::size_t>(a);
            if (state[k] == kKnown) best = std::min(best, value[k]);
        }
        return best;
    };
    // First-order upwind update from the known neighbours along x and along y.
    auto solve = [&](int i, int j) {
        const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
        const double f = slowness[k] * h;
        const double a = neighbour_min(i, j, 1, 0), b = neighbour_min(i, j, 0, 1);
        if (!std::isfinite(a) && !std::isfinite(b)) return kUnreached;
        if (!std::isfinite(a) || !std::isfinite(b) || std::abs(a - b) >= f) return std::min(a, b) + f;
        return 0.5 * (a + b + std::sqrt(2.0 * f * f - (a - b) * (a - b)));
    };
    auto relax_neighbours = [&](int i, int j) {
        const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
            const int a = i + di[d], b = j + dj[d];
            if (a < 0 || b < 0 || a >= n || b >= n) continue;
            const std::size_t k = static_cast<std::size_t>(b) * static_cast<std::size_t>(n) + static_cast<std::size_t>(a);
            if (state[k] == kKnown || slowness[k] <= 0.0) continue;
            const double t = solve(a, b);
            if (t < value[k]) {
                value[k] = t;
                state[k] = kTrial;
                heap.push({t, k});
            }
        }
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (state[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] == kKnown) relax_neighbours(i, j);
    while (!heap.empty()) {
        const auto [t, k] = heap.top();
        heap.pop();
        if (state[k] == kKnown || t > value[k]) continue;
        state[k] = kKnown;
        relax_neighbours(static_cast<int>(k % static_cast<std::size_t>(n)), static_cast<int>(k / static_cast<std::size_t>(n)));
    }
}

}  // namespace tidewater::detail
