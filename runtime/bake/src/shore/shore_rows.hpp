// The shore model's values at one texel, as the bake computes them: a wave's rows from
// its marched phase, the breaking cap, the shared rows, a coarse run's rows carried onto
// land, and which tiles are left out. The full bake (shore_waves_bake.cpp) and the local
// re-bake after an edit under the water (shore_water_edit.cpp) both call these. Private.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <optional>
#include <span>

#include "fast_marching.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_tiles.hpp"
#include "tidewater/dispersion.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::detail {

/// The waves together never fold: sum(Q k A) is kept at or under this.
inline constexpr double kMaxFold = 0.95;

/// A run of waves [first, first + count) in its tiles on its grid, as the cap reads it.
struct RunTilesView {
    std::size_t first = 0, count = 0;
    const ShoreGrid* grid = nullptr;
    const ShoreTiles* tiles = nullptr;
};

/// The runs' amplitude factors and wavevectors at world xz `p`, texel (i, j) of `grid`:
/// read from the texel where a run lies on that grid, sampled bilinearly elsewhere.
/// Calls each(wave, amplitude factor, wavevector x, z).
template <typename Each>
void each_run_wave(std::span<const RunTilesView> runs, const ShoreGrid& grid, int i, int j, glm::dvec2 p,
                   const Each& each) {
    for (const RunTilesView& r : runs) {
        const std::size_t nw = r.count;
        if (*r.grid == grid) {
            const float* t = r.tiles->texel(i, j);
            for (std::size_t w = 0; w < nw; ++w)
                each(r.first + w, static_cast<double>(t[nw + w]), static_cast<double>(t[2 * nw + w]),
                     static_cast<double>(t[3 * nw + w]));
            continue;
        }
        const ShoreTaps taps = shore_taps(*r.grid, *r.tiles, p);
        for (std::size_t w = 0; w < nw; ++w)
            each(r.first + w, taps.lerp(nw + w), taps.lerp(2 * nw + w), taps.lerp(3 * nw + w));
    }
}

/// The cap at depth h (m): the largest sqrt(sum A^2) (m) the waves keep there, half of
/// breaking_index * h. cap_ratio, cap_energy and the open sea's margin read it.
inline double cap_amplitude(double h, double breaking_index) {
    return 0.5 * breaking_index * h;
}

/// The local height over the breaking cap at texel (i, j) of `grid` (depth h > 0): the
/// local wave height 2 sqrt(sum A^2) over breaking_index * h (exactly 2A for one wave, the
/// rms-based height, about 0.71 Hs, for a spectrum, whose occasional peaks a cap on sum(A)
/// would overstate). Reads the runs before their caps.
inline double cap_ratio(std::span<const Wave> waves, std::span<const RunTilesView> runs, const ShoreGrid& grid, int i,
                        int j, double h, double breaking_index) {
    double energy = 0.0;
    each_run_wave(runs, grid, i, j, grid.corner + grid.texel * glm::dvec2(i + 0.5, j + 0.5),
                  [&](std::size_t w, double factor, double, double) {
                      const double a = waves[w].amplitude * factor;
                      energy += a * a;
                  });
    return std::sqrt(energy) / cap_amplitude(h, breaking_index);
}

/// What the diffracted waves (shore_diffraction.hpp) tell the foam at a texel: the
/// energy (sum of A^2, m^2) whose fields the march gives and the part of it that is
/// breaking there.
struct DiffractedEnergy {
    double marched = 0.0, breaking = 0.0;
};

/// The foam (the shared breaking row) where the runs before their caps are at `ratio` of
/// the cap with energy `energy` (sum of A^2, m^2), and the march gives `diffracted`:
/// rising toward the cap where the rays give the waves, the breaking share of the energy
/// where the march gives them.
inline float shared_foam(double ratio, double energy, DiffractedEnergy diffracted) {
    const double ray_foam = std::clamp((ratio - 0.85) / 0.45, 0.0, 1.0);
    double foam = ray_foam;
    if (energy > 0.0 && diffracted.marched > 0.0) {
        const double marched = std::min(diffracted.marched / energy, 1.0);
        foam = std::min(diffracted.breaking / energy, marched) + (1.0 - marched) * ray_foam;
    }
    return static_cast<float>(std::clamp(foam, 0.0, 1.0));
}

/// The energy (sum of A^2 of the runs before their caps, m^2) at depth h whose cap_ratio
/// is `ratio`.
inline double cap_energy(double ratio, double h, double breaking_index) {
    const double e = ratio * cap_amplitude(h, breaking_index);
    return e * e;
}

/// Shared texel (i, j)'s rows (depth h, signed shore distance): depth and distance,
/// breaking (all waves together: the foam rises toward the cap where the rays give the
/// waves, and is the breaking share of the energy where the march gives them) and the
/// steepness scale (Q is scaled where the waves together, capped, would fold), into
/// t[0..3]. Reads the runs before their caps; `ratio` is their cap_ratio there (read
/// where h > 0).
inline void shared_texel_rows(std::span<const Wave> waves, std::span<const RunTilesView> runs, const ShoreGrid& grid,
                              int i, int j, float depth, float distance, double ratio, float* t,
                              DiffractedEnergy diffracted = {}) {
    const double h = static_cast<double>(depth);
    t[0] = depth;
    t[1] = 0.0f;
    t[2] = 1.0f;
    t[3] = distance;
    if (h <= 0.0) return;
    const double scale = ratio > 1.0 ? 1.0 / ratio : 1.0;
    double fold = 0.0, energy = 0.0;
    each_run_wave(runs, grid, i, j, grid.corner + grid.texel * glm::dvec2(i + 0.5, j + 0.5),
                  [&](std::size_t w, double factor, double kx, double kz) {
                      const double a = waves[w].amplitude * factor;
                      fold += waves[w].steepness * std::sqrt(kx * kx + kz * kz) * a * scale;
                      energy += a * a;
                  });
    t[1] = shared_foam(ratio, energy, diffracted);
    if (fold > kMaxFold) t[2] = static_cast<float>(kMaxFold / fold);
}

/// A run texel's amplitude after the cap: none on land, scaled down by `ratio` (the
/// cap_ratio there) over the cap.
inline float capped_amplitude(float amplitude, double depth, double ratio) {
    if (depth <= 0.0) return 0.0f;
    return ratio > 1.0 ? static_cast<float>(static_cast<double>(amplitude) / ratio) : amplitude;
}

/// Whether a run's texel `t` (its `nw` waves' rows) holds a wavevector for wave w: land
/// and water the wave did not reach hold none.
inline bool carries_wave(const float* t, std::size_t nw, std::size_t w) {
    return t[2 * nw + w] != 0.0f || t[3 * nw + w] != 0.0f;
}

/// One wave's rows at a texel, before the cap.
struct WaveTexel {
    float residual = 0.0f, amplitude = 0.0f, kx = 0.0f, kz = 0.0f;
};

/// Wave `wave`'s rows at texel (i, j) of an n x n grid (`texel` m, texel centre `centre`)
/// from its marched phase, phase(a, b) (offset by `base`, kUnreached where not reached):
/// the phase residual, the local wavevector (k0 D + grad residual, of length exactly
/// kl = k(h)) and the amplitude factor from shoaling (energy flux) and refraction (rays
/// against the shore normal `normal`). `source`: the texel keeps the open-ocean phase.
template <typename Phase>
WaveTexel wave_texel(const Wave& wave, const Phase& phase, int i, int j, int n, double texel, glm::dvec2 centre,
                     double base, double h, double kl, glm::dvec2 normal, bool source) {
    WaveTexel t;
    const double here = phase(i, j);
    if (!std::isfinite(here)) return t;  // unreached: no wave
    const double k0 = wave.k;
    const glm::dvec2 dir{wave.dir_x, wave.dir_z};
    // A source keeps the open-ocean phase: residual exactly 0.
    if (!source) t.residual = static_cast<float>(here + base - k0 * glm::dot(dir, centre));
    if (h <= 0.0) return t;
    // Local wavevector = k0 D + grad(residual), central differences over reached water.
    auto diff = [&](int a0, int b0, int a1, int b1) {
        const double p0 = a0 >= 0 && b0 >= 0 && a0 < n && b0 < n ? phase(a0, b0) : kUnreached;
        const double p1 = a1 >= 0 && b1 >= 0 && a1 < n && b1 < n ? phase(a1, b1) : kUnreached;
        const bool ok0 = std::isfinite(p0), ok1 = std::isfinite(p1);
        const double v0 = ok0 ? p0 : here;
        const double v1 = ok1 ? p1 : here;
        const double span = (ok0 ? 1.0 : 0.0) + (ok1 ? 1.0 : 0.0);
        return span > 0.0 ? (v1 - v0) / (span * texel) : 0.0;
    };
    // In deep water the wave travels as offshore: no turn, so no refraction either.
    glm::dvec2 kvec = source ? dir : glm::dvec2{diff(i - 1, j, i + 1, j), diff(i, j - 1, i, j + 1)};
    const double len = glm::length(kvec);
    kvec = len > 0.0 ? kvec * (kl / len) : dir * kl;  // magnitude exactly k(h)
    t.kx = static_cast<float>(kvec.x);
    t.kz = static_cast<float>(kvec.y);
    // Shoaling from energy flux: sqrt(cg_deep / cg(h)), cg_deep = omega / (2 k0).
    const double ks = std::sqrt(0.5 * wave.omega / k0 / group_velocity(kl, h));
    double kr = 1.0;
    if (!source && glm::length(normal) > 0.5) {
        const double cos0 = std::abs(glm::dot(dir, normal));
        const double cos1 = std::abs(glm::dot(kvec / kl, normal));
        if (cos0 > 0.05 && cos1 > 0.05) kr = std::sqrt(std::clamp(cos0 / cos1, 0.25, 4.0));
    }
    t.amplitude = static_cast<float>(ks * kr);
    return t;
}

/// A coarse run's wave w (of its `nw`) carried one texel onto land at texel (i, j) of an
/// n x n grid (`texel` m), from the neighbours in `tiles` that carry it and that `from`
/// accepts: the residual along each neighbour's own wavevector, averaged, and their mean
/// wavevector. nullopt when no neighbour gives one.
struct LandTexel {
    float residual = 0.0f, kx = 0.0f, kz = 0.0f;
};
template <typename From>
std::optional<LandTexel> carried_onto_land(const Wave& wave, const ShoreTiles& tiles, std::size_t nw, std::size_t w,
                                           int i, int j, int n, double texel, const From& from) {
    const glm::dvec2 k0{wave.k * wave.dir_x, wave.k * wave.dir_z};
    double residual = 0.0;
    glm::dvec2 kvec{0.0};
    int count = 0;
    for (const glm::ivec2 d : {glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)}) {
        const int a = i + d.x, b = j + d.y;
        if (a < 0 || b < 0 || a >= n || b >= n) continue;
        const float* v = tiles.texel(a, b);
        const glm::dvec2 kn{static_cast<double>(v[2 * nw + w]), static_cast<double>(v[3 * nw + w])};
        if (kn == glm::dvec2(0.0) || !from(a, b)) continue;
        // The residual grows by (k - k0 D) . step from the neighbour to here.
        residual += static_cast<double>(v[w]) - glm::dot(kn - k0, glm::dvec2(d)) * texel;
        kvec += kn;
        ++count;
    }
    if (count == 0) return std::nullopt;
    return LandTexel{static_cast<float>(residual / count), static_cast<float>(kvec.x / count),
                     static_cast<float>(kvec.y / count)};
}

/// A distance gradient sampled between texels, as a grid of the bake holds it: normalized,
/// 0 where it vanishes.
inline glm::vec2 unit_normal(glm::dvec2 grad) {
    const double len = glm::length(grad);
    return glm::vec2(len > 1e-6 ? grad / len : glm::dvec2(0.0));
}

/// The shoreline's distance gradient sampled at world xz `p` and normalized (0 where it
/// vanishes): what a grid other than the shoreline's holds there, once held_normal.
inline glm::vec2 resampled_normal(const ShoreField& shoreline, glm::dvec2 p) {
    return unit_normal(shoreline.gradient_at(p));
}

/// A normal as a grid holds it: its 16-bit angle's (SharedDirections).
inline glm::vec2 held_normal(glm::vec2 normal) {
    return SharedDirections::decode(SharedDirections::encode(normal));
}

/// What decides which tiles of a layer are left out as open sea: its longest wave
/// (lowest frequency), and the energy and fold of every wave (breaking and folding are
/// the waves' together).
struct OpenSeaTest {
    double longest_omega = 0.0;
    double energy = 0.0;      ///< sum of A^2, m^2
    bool open_folds = false;  ///< the open sea's waves fold: no tile is open sea
};
/// `layer` is waves [first, first + count) of `all`. Where the layer's waves are deep the
/// others may not be: their amplitudes count twice (the most refraction raises one), so
/// that the layer is stored wherever the waves together may break.
inline OpenSeaTest open_sea_test(std::span<const Wave> all, std::size_t first, std::size_t count) {
    OpenSeaTest t;
    double fold = 0.0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Wave& w = all[i];
        const bool own = i >= first && i < first + count;
        t.energy += (own ? 1.0 : 4.0) * w.amplitude * w.amplitude;
        fold += w.steepness * w.k * w.amplitude;
        if (own) t.longest_omega = t.longest_omega == 0.0 ? w.omega : std::min(t.longest_omega, w.omega);
    }
    // Deep water shortens a wave by at most 0.4 % (k h >= pi): the fold with that margin.
    t.open_folds = fold * 1.01 > kMaxFold || all.empty();
    return t;
}

/// Whether a texel of depth h lets its tile be open sea: the layer's longest wave is in
/// deep water (k h >= pi), so that each of its waves keeps its open-sea phase there and
/// shoaling changes its amplitude and wavevector by under 0.4 %, and the waves together
/// stay under where breaking starts (0.85 of the cap).
inline bool open_sea_texel(const OpenSeaTest& test, double h, double breaking_index) {
    return marched_deep_water(test.longest_omega, h) && std::sqrt(test.energy) < 0.8 * cap_amplitude(h, breaking_index);
}

}  // namespace tidewater::detail
