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
    auto known_at = [&](int a, int b) -> double {
        if (a < 0 || b < 0 || a >= n || b >= n) return kUnreached;
        const std::size_t k = static_cast<std::size_t>(b) * static_cast<std::size_t>(n) + static_cast<std::size_t>(a);
        return state[k] == kKnown ? value[k] : kUnreached;
    };
    // One axis of the upwind stencil: the smaller known neighbour, and, when the next one
    // beyond it is known and no larger, the second-order value (4 t1 - t2) / 3 (weight 9/4).
    struct Axis {
        double t = kUnreached;
        double weight = 1.0;
    };
    auto axis = [&](int i, int j, int di, int dj) {
        Axis best;
        for (int s = -1; s <= 1; s += 2) {
            const double t1 = known_at(i + s * di, j + s * dj);
            if (!(t1 < best.t)) continue;
            best = {t1, 1.0};
            const double t2 = known_at(i + 2 * s * di, j + 2 * s * dj);
            if (t2 <= t1) best = {(4.0 * t1 - t2) / 3.0, 2.25};
        }
        return best;
    };
    // Solves sum_d w_d (T - t_d)^2 = (s h)^2 over the axes that contribute, falling back to
    // first order (and then to one axis) where the quadratic has no upwind root.
    auto solve = [&](int i, int j) {
        const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
        const double f2 = slowness[k] * h * slowness[k] * h;
        Axis ax[2] = {axis(i, j, 1, 0), axis(i, j, 0, 1)};
        for (int order = 2; order >= 1; --order) {
            if (order == 1)
                for (Axis& a : ax) {
                    if (a.weight > 1.0) {  // recover the first-order neighbour value
                        const double t1 = std::min(known_at(i - (&a == &ax[0]), j - (&a == &ax[1])),
                                                   known_at(i + (&a == &ax[0]), j + (&a == &ax[1])));
                        a = {t1, 1.0};
                    }
                }
            double qa = 0.0, qb = 0.0, qc = -f2;
            double largest = -kUnreached;
            for (const Axis& a : ax) {
                if (!std::isfinite(a.t)) continue;
                qa += a.weight;
                qb -= 2.0 * a.weight * a.t;
                qc += a.weight * a.t * a.t;
                largest = std::max(largest, a.t);
            }
            if (qa == 0.0) return kUnreached;
            const double disc = qb * qb - 4.0 * qa * qc;
            if (disc >= 0.0) {
                const double t = (-qb + std::sqrt(disc)) / (2.0 * qa);
                if (t >= largest) return t;  // upwind: not below any neighbour used
            }
        }
        // One axis only: the nearer arrival plus a step.
        const double t1 = std::min(std::min(known_at(i - 1, j), known_at(i + 1, j)),
                                   std::min(known_at(i, j - 1), known_at(i, j + 1)));
        return t1 + std::sqrt(f2);
    };
    auto relax_neighbours = [&](int i, int j) {
        const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
            const int a = i + di[d], b = j + dj[d];
            if (a < 0 || b < 0 || a >= n || b >= n) continue;
            const std::size_t k =
                static_cast<std::size_t>(b) * static_cast<std::size_t>(n) + static_cast<std::size_t>(a);
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
            if (state[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] ==
                kKnown)
                relax_neighbours(i, j);
    while (!heap.empty()) {
        const auto [t, k] = heap.top();
        heap.pop();
        if (state[k] == kKnown || t > value[k]) continue;
        state[k] = kKnown;
        relax_neighbours(static_cast<int>(k % static_cast<std::size_t>(n)),
                         static_cast<int>(k / static_cast<std::size_t>(n)));
    }
}

}  // namespace tidewater::detail
