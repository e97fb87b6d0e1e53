// The waves' phase re-marched round a stroke under the water, against a full march: over
// the default island's terrain on a grid of N texels a side, a stroke digs 1.5 m over a
// 10 m radius at about 3, 8 and 16 m of water, and each of three of ocean_rolling's waves
// (the longest, the middle one, the shortest) is marched whole before it and re-marched
// in a window after it (detail::remarch, tolerance 1e-3 rad). Prints one JSON object per
// stroke and wave. The sources are the bake's (detail::phase_source).
//   tidewater_remarch_benchmark [N=1024]
// docs/PERFORMANCE.md ("Worlds at real scale") quotes it.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "shore/fast_marching.hpp"
#include "tidewater/dispersion.hpp"
#include "tidewater/scene.hpp"

namespace {

using namespace tidewater;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::size_t index(int i, int j, int n) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
}

struct Grid {
    int n = 0;
    double texel = 0.0;
    std::vector<double> depth;  ///< at texel centres, m
    double at(int i, int j) const { return depth[index(i, j, n)]; }
};

/// One wave's slowness (its wavenumber at the depth) and sources over a depth field.
struct WaveMarch {
    const Wave& wave;
    double texel;
    bool any_deep = false;
    int n = 0;
    float slowness(double depth) const { return detail::marched_wavenumber(wave.omega, depth); }
    double source(int i, int j, double depth) const {
        const float s = slowness(depth);
        if (s <= 0.0f) return detail::kUnreached;
        const bool deep = detail::marched_deep(s, depth);
        return detail::phase_source(any_deep, deep, i, j, n, wave.dir_x, wave.dir_z)
                   ? wave.k * texel * (wave.dir_x * (i + 0.5) + wave.dir_z * (j + 0.5))
                   : detail::kUnreached;
    }
};

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 1024;
    if (n < 64 || n > 8192) {
        std::fprintf(stderr, "tidewater_remarch_benchmark: N must be 64 to 8192\n");
        return 2;
    }
    auto scene = default_scene();
    if (!scene) {
        std::fprintf(stderr, "tidewater_remarch_benchmark: %s\n", scene.error().message.c_str());
        return 1;
    }
    const Terrain& terrain = scene->terrain;
    const double half = terrain.extent_half_size();
    const glm::dvec2 corner = terrain.extent_center() - glm::dvec2(half);
    Grid grid{n, 2.0 * half / n, std::vector<double>(static_cast<std::size_t>(n) * static_cast<std::size_t>(n))};
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            grid.depth[index(i, j, n)] =
                scene->water_level() - terrain.height_at(corner + grid.texel * glm::dvec2(i + 0.5, j + 0.5));
    const auto waves = scene->ocean.waves().waves();
    for (const double wanted : {3.0, 8.0, 16.0}) {
        // The first water texel (scanning from a third of the way in) near the depth wanted.
        int si = -1, sj = -1;
        for (int j = n / 3; j < n && si < 0; j += 7)
            for (int i = n / 3; i < n && si < 0; i += 7)
                if (grid.at(i, j) > 0.8 * wanted && grid.at(i, j) < 1.2 * wanted) {
                    si = i;
                    sj = j;
                }
        if (si < 0) continue;
        const int r = std::max(1, static_cast<int>(std::ceil(10.0 / grid.texel)));
        auto after = [&](int i, int j) {
            const double d = grid.at(i, j);
            return d > 0.0 && std::hypot(i - si, j - sj) <= r ? d + 1.5 : d;
        };
        for (const std::size_t w : {std::size_t{0}, waves.size() / 2, waves.size() - 1}) {
            WaveMarch m{waves[w], grid.texel, false, n};
            for (const double d : grid.depth) m.any_deep = m.any_deep || detail::marched_deep(m.slowness(d), d);
            std::vector<float> slowness(grid.depth.size());
            std::vector<double> before(grid.depth.size());
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t k = index(i, j, n);
                    slowness[k] = m.slowness(grid.depth[k]);
                    before[k] = m.source(i, j, grid.depth[k]);
                }
            auto t0 = Clock::now();
            detail::fast_march(slowness, before, n, grid.texel);
            const double full_s = seconds_since(t0);
            detail::MarchChange change;
            change.n = n;
            change.h = grid.texel;
            change.slowness = [&](int i, int j) { return m.slowness(after(i, j)); };
            change.source = [&](int i, int j) { return m.source(i, j, after(i, j)); };
            change.before = [&](int i, int j) { return before[index(i, j, n)]; };
            change.changed = {si - r, sj - r, si + r + 1, sj + r + 1};
            change.tolerance = 1e-3;
            t0 = Clock::now();
            const detail::MarchWindow local = detail::remarch(change, 4);
            const double remarch_s = seconds_since(t0);
            std::printf("%s\n", fmt::format(R"({{"grid": {}, "texel_m": {:.3f}, "stroke_depth_m": {:.1f}, )"
                                            R"("wave": {}, "wavelength_m": {:.1f}, "deep_sources": {}, )"
                                            R"("full_march_s": {:.4f}, "window": [{}, {}], "solves": {}, )"
                                            R"("remarch_s": {:.5f}}})",
                                            n, grid.texel, grid.at(si, sj), w, 2.0 * std::numbers::pi / waves[w].k,
                                            m.any_deep, full_s, local.window.i1 - local.window.i0,
                                            local.window.j1 - local.window.j0, local.solves, remarch_s)
                                    .c_str());
        }
    }
    return 0;
}
