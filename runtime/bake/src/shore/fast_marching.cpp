#include "fast_marching.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace tidewater::detail {

namespace {

/// The upwind update of texel (i, j) from the values `known_at(a, b)` gives (kUnreached
/// for a neighbour not known): one axis of the stencil takes the smaller known neighbour,
/// and, when the next one beyond it is known and no larger, the second-order value
/// (4 t1 - t2) / 3 (weight 9/4); then sum_d w_d (T - t_d)^2 = (s h)^2 over the axes that
/// contribute, falling back to first order (and then to one axis) where the quadratic has
/// no upwind root.
template <typename KnownAt>
double upwind_update(int i, int j, double slowness, double h, const KnownAt& known_at) {
    struct Axis {
        double t = kUnreached;
        double weight = 1.0;
    };
    auto axis = [&](int di, int dj) {
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
    const double f2 = slowness * h * slowness * h;
    Axis ax[2] = {axis(1, 0), axis(0, 1)};
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
    const double t1 =
        std::min(std::min(known_at(i - 1, j), known_at(i + 1, j)), std::min(known_at(i, j - 1), known_at(i, j + 1)));
    return t1 + std::sqrt(f2);
}

/// How a texel of a march stands before it: free (its value a source when finite), or
/// frozen at its value, known from the start (a source), or taken up in the order of its
/// value as though the march had reached it (so that a texel beside it does not use it
/// before its turn, which the upwind update's fallbacks would notice).
enum Frozen : unsigned char { kFree, kFrozenSource, kFrozenInTurn };

/// The march over an nx x ny grid. Texels with a finite value are known from the start,
/// but for those `frozen` (when given) in turn; frozen texels keep their value.
void march(const std::vector<float>& slowness, std::vector<double>& value, const std::vector<unsigned char>* frozen,
           int nx, int ny, double h) {
    enum : unsigned char { kFar, kTrial, kKnown };
    const std::size_t count = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
    auto index = [nx](int a, int b) {
        return static_cast<std::size_t>(b) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(a);
    };
    std::vector<unsigned char> state(count, kFar);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
    auto frozen_at = [&](std::size_t k) { return frozen ? (*frozen)[k] : static_cast<unsigned char>(kFree); };
    for (std::size_t k = 0; k < count; ++k) {
        if (!std::isfinite(value[k])) continue;
        if (frozen_at(k) == kFrozenInTurn) {
            state[k] = kTrial;
            heap.push({value[k], k});
        } else {
            state[k] = kKnown;
        }
    }
    auto known_at = [&](int a, int b) -> double {
        if (a < 0 || b < 0 || a >= nx || b >= ny) return kUnreached;
        const std::size_t k = index(a, b);
        return state[k] == kKnown ? value[k] : kUnreached;
    };
    auto relax_neighbours = [&](int i, int j) {
        const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
            const int a = i + di[d], b = j + dj[d];
            if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
            const std::size_t k = index(a, b);
            if (state[k] == kKnown || slowness[k] <= 0.0f || frozen_at(k) != kFree) continue;
            const double t = upwind_update(a, b, static_cast<double>(slowness[k]), h, known_at);
            if (t < value[k]) {
                value[k] = t;
                state[k] = kTrial;
                heap.push({t, k});
            }
        }
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            if (state[index(i, j)] == kKnown) relax_neighbours(i, j);
    while (!heap.empty()) {
        const auto [t, k] = heap.top();
        heap.pop();
        if (state[k] == kKnown || t > value[k]) continue;
        state[k] = kKnown;
        relax_neighbours(static_cast<int>(k % static_cast<std::size_t>(nx)),
                         static_cast<int>(k / static_cast<std::size_t>(nx)));
    }
}

}  // namespace

void fast_march(const std::vector<float>& slowness, std::vector<double>& value, int n, double h) {
    march(slowness, value, nullptr, n, n, h);
}

MarchWindow remarch(const MarchChange& c, int margin) {
    const int n = c.n;
    auto clamped = [n](TexelWindow w) {
        return TexelWindow{std::max(w.i0, 0), std::max(w.j0, 0), std::min(w.i1, n), std::min(w.j1, n)};
    };
    TexelWindow w =
        clamped({c.changed.i0 - margin, c.changed.j0 - margin, c.changed.i1 + margin, c.changed.j1 + margin});
    int step = std::max(margin, 1);
    MarchWindow out;
    // The change's slowness and sources and the solution before, over the last window
    // marched and its rings: a window only grows, so each texel's are asked once.
    TexelWindow cached{0, 0, 0, 0};
    std::vector<float> cached_slowness;
    std::vector<double> cached_source, cached_before;
    for (;;) {
        ++out.solves;
        // The window and two rings round it (the second-order stencil's reach), the rings
        // frozen at the solution before.
        const TexelWindow r = clamped({w.i0 - 2, w.j0 - 2, w.i1 + 2, w.j1 + 2});
        const int rx = r.i1 - r.i0, ry = r.j1 - r.j0;
        const std::size_t count = static_cast<std::size_t>(rx) * static_cast<std::size_t>(ry);
        auto local = [&](int i, int j) {
            return static_cast<std::size_t>(j - r.j0) * static_cast<std::size_t>(rx) +
                   static_cast<std::size_t>(i - r.i0);
        };
        std::vector<float> slowness(count);
        std::vector<double> source(count), before(count), value(count);
        for (int j = r.j0; j < r.j1; ++j)
            for (int i = r.i0; i < r.i1; ++i) {
                const std::size_t k = local(i, j);
                if (cached.contains(i, j)) {
                    const std::size_t o =
                        static_cast<std::size_t>(j - cached.j0) * static_cast<std::size_t>(cached.i1 - cached.i0) +
                        static_cast<std::size_t>(i - cached.i0);
                    slowness[k] = cached_slowness[o];
                    source[k] = cached_source[o];
                    before[k] = cached_before[o];
                } else {
                    slowness[k] = c.slowness(i, j);
                    source[k] = c.source(i, j);
                    before[k] = c.before(i, j);
                }
            }
        std::vector<unsigned char> frozen(count, kFree);
        for (int j = r.j0; j < r.j1; ++j)
            for (int i = r.i0; i < r.i1; ++i) {
                const std::size_t k = local(i, j);
                if (w.contains(i, j)) {
                    value[k] = source[k];
                } else {
                    value[k] = before[k];
                    frozen[k] = std::isfinite(source[k]) ? kFrozenSource : kFrozenInTurn;
                }
            }
        march(slowness, value, &frozen, rx, ry, c.h);

        // The change reaches past a side of the window where the two texels along it
        // (the stencil's reach) now differ from the solution before: the texels beyond
        // them would be updated from new values.
        bool grow[4] = {false, false, false, false};  // -i, +i, -j, +j
        for (int j = w.j0; j < w.j1; ++j)
            for (int i = w.i0; i < w.i1; ++i) {
                const bool near[4] = {w.i0 > 0 && i < w.i0 + 2, w.i1 < n && i >= w.i1 - 2, w.j0 > 0 && j < w.j0 + 2,
                                      w.j1 < n && j >= w.j1 - 2};
                if (!(near[0] || near[1] || near[2] || near[3])) continue;
                const double now = value[local(i, j)], then = before[local(i, j)];
                if ((std::isinf(now) && std::isinf(then)) || std::abs(now - then) <= c.tolerance) continue;
                for (int side = 0; side < 4; ++side) grow[side] = grow[side] || near[side];
            }
        const TexelWindow next = clamped({w.i0 - (grow[0] ? step : 0), w.j0 - (grow[2] ? step : 0),
                                          w.i1 + (grow[1] ? step : 0), w.j1 + (grow[3] ? step : 0)});
        const bool settled = next.i0 == w.i0 && next.j0 == w.j0 && next.i1 == w.i1 && next.j1 == w.j1;
        if (settled) {
            out.window = w;
            out.value.resize(static_cast<std::size_t>(w.i1 - w.i0) * static_cast<std::size_t>(w.j1 - w.j0));
            for (int j = w.j0; j < w.j1; ++j)
                for (int i = w.i0; i < w.i1; ++i)
                    out.value[static_cast<std::size_t>(j - w.j0) * static_cast<std::size_t>(w.i1 - w.i0) +
                              static_cast<std::size_t>(i - w.i0)] = value[local(i, j)];
            return out;
        }
        cached = r;
        cached_slowness = std::move(slowness);
        cached_source = std::move(source);
        cached_before = std::move(before);
        w = next;
        step *= 2;
    }
}

}  // namespace tidewater::detail
