// The shore model's bake: the per-wave fields of ShoreWaves (tidewater/detail/shore_waves.hpp)
// from the shoreline's distance field, by fast marching per wave.
#include "tidewater/detail/shore_waves_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <mutex>
#include <span>

#include "shore/fast_marching.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {

namespace {

/// The deep-water boundary: k h >= pi, where tanh(k h) > 0.996.
constexpr double kDeepKh = kPi;
constexpr double kMaxFold = 0.95;

/// The model's own grid from a shoreline baked at another resolution: depth from the
/// terrain at this grid's texel centres; distance and gradient sampled from `shoreline`,
/// the distance signed by the texel's own depth so that it agrees with `depth`.
Result<ShoreField> resample_shoreline(const Terrain& terrain, double water_level, int n, const ShoreField& shoreline,
                                      unsigned threads) {
    ShoreField g;
    g.resolution = n;
    const double half = terrain.extent_half_size();
    g.texel = 2.0 * half / n;
    g.corner = terrain.extent_center() - glm::dvec2(half);
    if (std::abs(shoreline.texel * shoreline.resolution - 2.0 * half) > 1e-6 * half ||
        glm::length(shoreline.corner - g.corner) > 1e-6 * half)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: the shoreline field covers another extent than the terrain"};
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    g.depth.resize(count);
    g.signed_distance.resize(count);
    g.gradient_x.resize(count);
    g.gradient_z.resize(count);
    std::atomic<bool> finite{true};
    detail::parallel_for_each(static_cast<std::size_t>(n), threads, [&](std::size_t row) {
        const int j = static_cast<int>(row);
        for (int i = 0; i < n; ++i) {
            const std::size_t k = g.index(i, j);
            const glm::dvec2 p = g.texel_center(i, j);
            const double depth = water_level - terrain.height_at(p);
            if (!std::isfinite(depth)) finite = false;
            g.depth[k] = static_cast<float>(depth);
            g.signed_distance[k] =
                static_cast<float>(std::copysign(std::abs(shoreline.distance_at(p)), depth > 0.0 ? 1.0 : -1.0));
            glm::dvec2 grad{shoreline.sample(shoreline.gradient_x, p), shoreline.sample(shoreline.gradient_z, p)};
            const double len = glm::length(grad);
            grad = len > 1e-6 ? grad / len : glm::dvec2(0.0);
            g.gradient_x[k] = static_cast<float>(grad.x);
            g.gradient_z[k] = static_cast<float>(grad.y);
        }
    });
    if (!finite)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: the terrain height is not finite somewhere on the model grid"};
    return g;
}

Error cancelled() {
    return Error{ErrorCode::cancelled, "shore waves: cancelled"};
}

/// The model's grid: the shoreline baked elsewhere (resampled to the model's resolution
/// where it differs), or baked here over `options.region` with progress 0..`share`.
Result<ShoreField> model_grid(const Terrain& terrain, double water_level, const ShoreWaveOptions& options,
                              const ShoreField* shoreline, double share) {
    if (shoreline && options.region)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: a region is baked with its own shoreline, not one baked elsewhere"};
    if (shoreline && shoreline->resolution == options.resolution) return *shoreline;
    if (shoreline) return resample_shoreline(terrain, water_level, options.resolution, *shoreline, options.threads);
    BakeOptions bake;
    bake.resolution = options.resolution;
    bake.region = options.region;
    bake.threads = options.threads;
    bake.cancel = options.cancel;
    bake.progress = [&](double f) {
        if (options.progress) options.progress(share * f);
    };
    return bake_shore(terrain, water_level, bake);
}

/// One wave's phase over the grid by fast marching from deep water (or from the edges it
/// enters through, on a domain with none), offset by `base` (returned), and its local
/// wavenumber k(h) per texel (0 on land) in `slowness`. Unreached texels stay infinite.
struct MarchedPhase {
    std::vector<double> slowness, phase;
    std::vector<unsigned char> deep;
    bool any_deep = false;
    double base = 0.0;
};
MarchedPhase march_phase(const Wave& wave, const ShoreField& field) {
    const int n = field.resolution;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    const double k0 = wave.k;
    const glm::dvec2 dir{wave.dir_x, wave.dir_z};
    MarchedPhase m;
    m.slowness.assign(count, 0.0);
    m.phase.assign(count, detail::kUnreached);
    m.deep.assign(count, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const double h = static_cast<double>(field.depth[k]);
        if (h <= 0.0) continue;  // land blocks the waves
        m.slowness[k] = wavenumber_at_depth(wave.omega, h);
        m.deep[k] = m.slowness[k] * h >= kDeepKh;
        m.any_deep = m.any_deep || m.deep[k];
    }
    // Sources: deep water, where the open-ocean phase holds. A domain with no deep
    // water takes the wave from the edges it enters through instead (shallow edges
    // would otherwise pin the unrefracted phase along them).
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::size_t k = field.index(i, j);
            if (m.slowness[k] <= 0.0) continue;
            const bool entry_edge = (i == 0 && dir.x > 0.05) || (i == n - 1 && dir.x < -0.05) ||
                                    (j == 0 && dir.y > 0.05) || (j == n - 1 && dir.y < -0.05);
            if (m.any_deep ? m.deep[k] != 0 : entry_edge) m.phase[k] = k0 * glm::dot(dir, field.texel_center(i, j));
        }
    }
    // Offset so the marched values start near zero (keeps doubles exact on big domains).
    m.base = k0 * glm::dot(dir, field.corner);
    for (double& v : m.phase)
        if (std::isfinite(v)) v -= m.base;
    detail::fast_march(m.slowness, m.phase, n, field.texel);
    return m;
}

/// The tiles the bake stores, and the grid tile behind each stored slot.
struct TilePlan {
    ShoreTiles tiles;               ///< pages set, texels sized; slots 0 and 1 filled
    std::vector<std::size_t> tile;  ///< per stored slot (from kShoreFirstStoredSlot): its tile
};

/// Which tiles to store, known before any wave is marched: a tile is open sea when the
/// longest wave is in deep water (k h >= pi) at every texel of its slot, so that every wave
/// keeps its open-sea phase there and shoaling changes its amplitude and wavevector by
/// under 0.4 %, and the open sea's waves neither break nor fold anywhere in it; dry land
/// when every texel is dry and a tile or more from the shoreline. The rest is stored.
TilePlan plan_tiles(std::span<const Wave> waves, const ShoreField& field, double breaking_index, bool every_tile,
                    unsigned threads) {
    TilePlan plan;
    ShoreTiles& t = plan.tiles;
    const int n = field.resolution;
    t.resolution = n;
    t.tiles_per_side = (n + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    t.stride = ShoreWaves::query_texel_stride(waves.size());
    const std::size_t m = static_cast<std::size_t>(t.tiles_per_side);
    double longest = 0.0, energy = 0.0, fold = 0.0;
    for (const Wave& w : waves) {
        longest = longest == 0.0 ? w.omega : std::min(longest, w.omega);
        energy += w.amplitude * w.amplitude;
        fold += w.steepness * w.k * w.amplitude;
    }
    // Deep water shortens a wave by at most 0.4 % (k h >= pi): the fold with that margin.
    const bool open_folds = fold * 1.01 > kMaxFold;
    std::vector<char> kinds(m * m, 's');
    detail::parallel_for_each(m, threads, [&](std::size_t tj) {
        for (std::size_t ti = 0; ti < m; ++ti) {
            const std::size_t tile = tj * m + ti;
            bool open = !every_tile && !open_folds && !waves.empty(), dry = !every_tile;
            for (std::size_t k = 0; k < ShoreTiles::kSlotTexels && (open || dry); ++k) {
                const std::size_t g = t.grid_index(tile, k);
                const double h = static_cast<double>(field.depth[g]);
                dry = dry && far_dry_land(h, static_cast<double>(field.signed_distance[g]), field.texel);
                // Breaking starts at 0.85 of the cap (cap_breaking); shoaling in deep water stays under 1.
                open = open && h > 0.0 && wavenumber_at_depth(longest, h) * h >= kDeepKh &&
                       std::sqrt(energy) < 0.8 * 0.5 * breaking_index * h;
            }
            kinds[tile] = open ? 'o' : dry ? 'd' : 's';
        }
    });
    t.pages.assign(m * m, gpu::kShoreOpenSlot);
    for (std::size_t tile = 0; tile < kinds.size(); ++tile) {
        if (kinds[tile] == 'd') t.pages[tile] = gpu::kShoreDrySlot;
        if (kinds[tile] != 's') continue;
        t.pages[tile] = static_cast<std::uint32_t>(gpu::kShoreFirstStoredSlot + plan.tile.size());
        plan.tile.push_back(tile);
    }
    t.texels.assign((gpu::kShoreFirstStoredSlot + plan.tile.size()) * ShoreTiles::kSlotTexels * t.stride, 0.0f);
    return plan;
}

/// Calls visit(slot texel's floats, grid index) for every texel of every stored slot, slots spread over workers.
template <typename Visit>
void each_stored_texel(TilePlan& plan, unsigned threads, const Visit& visit) {
    ShoreTiles& t = plan.tiles;
    detail::parallel_for_each(plan.tile.size(), threads, [&](std::size_t s) {
        float* slot = t.texels.data() + (gpu::kShoreFirstStoredSlot + s) * ShoreTiles::kSlotTexels * t.stride;
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k)
            visit(slot + k * t.stride, t.grid_index(plan.tile[s], k));
    });
}

/// Wave w's rows of every stored texel from its marched phase: the phase residual, the
/// local wavevector (k0 D + grad residual, of length exactly k(h)) and the amplitude factor
/// from shoaling (energy flux) and refraction (rays against the shore normal).
void wave_rows(const Wave& wave, const ShoreField& field, const MarchedPhase& m, std::size_t w, TilePlan& plan) {
    const int n = field.resolution;
    const std::size_t nw = plan.tiles.stride / 4 - 1;
    const double k0 = wave.k;
    const glm::dvec2 dir{wave.dir_x, wave.dir_z};
    const std::vector<double>& phase = m.phase;
    each_stored_texel(plan, 1, [&](float* t, std::size_t k) {
        const int i = static_cast<int>(k % static_cast<std::size_t>(n)),
                  j = static_cast<int>(k / static_cast<std::size_t>(n));
        t[w] = t[nw + w] = t[2 * nw + w] = t[3 * nw + w] = 0.0f;
        if (!std::isfinite(phase[k])) return;  // unreached: no wave
        // A source keeps the open-ocean phase: residual exactly 0.
        const bool source = m.any_deep && m.deep[k] != 0;
        if (!source) t[w] = static_cast<float>(phase[k] + m.base - k0 * glm::dot(dir, field.texel_center(i, j)));
        const double h = field.depth[k];
        if (h <= 0.0) return;
        // Local wavevector = k0 D + grad(residual), central differences over reached water.
        auto diff = [&](int a0, int b0, int a1, int b1) {
            const bool ok0 = a0 >= 0 && b0 >= 0 && a0 < n && b0 < n && std::isfinite(phase[field.index(a0, b0)]);
            const bool ok1 = a1 >= 0 && b1 >= 0 && a1 < n && b1 < n && std::isfinite(phase[field.index(a1, b1)]);
            const double v0 = ok0 ? phase[field.index(a0, b0)] : phase[k];
            const double v1 = ok1 ? phase[field.index(a1, b1)] : phase[k];
            const double span = (ok0 ? 1.0 : 0.0) + (ok1 ? 1.0 : 0.0);
            return span > 0.0 ? (v1 - v0) / (span * field.texel) : 0.0;
        };
        // In deep water the wave travels as offshore: no turn, so no refraction either.
        glm::dvec2 kvec = source ? dir : glm::dvec2{diff(i - 1, j, i + 1, j), diff(i, j - 1, i, j + 1)};
        const double kl = m.slowness[k];  // k(h), solved once in march_phase
        const double len = glm::length(kvec);
        kvec = len > 0.0 ? kvec * (kl / len) : dir * kl;  // magnitude exactly k(h)
        t[2 * nw + w] = static_cast<float>(kvec.x);
        t[3 * nw + w] = static_cast<float>(kvec.y);
        // Shoaling from energy flux: sqrt(cg_deep / cg(h)), cg_deep = omega / (2 k0).
        const double ks = std::sqrt(0.5 * wave.omega / k0 / group_velocity(kl, h));
        const glm::dvec2 normal{static_cast<double>(field.gradient_x[k]), static_cast<double>(field.gradient_z[k])};
        double kr = 1.0;
        if (!source && glm::length(normal) > 0.5) {
            const double cos0 = std::abs(glm::dot(dir, normal));
            const double cos1 = std::abs(glm::dot(kvec / kl, normal));
            if (cos0 > 0.05 && cos1 > 0.05) kr = std::sqrt(std::clamp(cos0 / cos1, 0.25, 4.0));
        }
        t[nw + w] = static_cast<float>(ks * kr);
    });
}

/// The shared rows of every stored texel, then breaking (all waves together) and
/// steepness: the amplitudes are capped at breaking_index * h / 2 of local height, the
/// foam rises toward the cap, and Q is scaled where the waves together would fold.
void shared_rows(std::span<const Wave> waves, double breaking_index, const ShoreField& field, TilePlan& plan,
                 unsigned threads) {
    const std::size_t nw = waves.size();
    const double cap_ratio = 0.5 * breaking_index;  // amplitude cap = index * h / 2
    each_stored_texel(plan, threads, [&](float* t, std::size_t k) {
        const double h = static_cast<double>(field.depth[k]);
        t[4 * nw] = field.depth[k];
        t[4 * nw + 1] = 0.0f;
        t[4 * nw + 2] = 1.0f;
        t[4 * nw + 3] = field.signed_distance[k];
        // The local wave height 2 sqrt(sum A^2): exactly 2A for one wave, the rms-based
        // height (about 0.71 Hs) for a spectrum, whose occasional peaks a cap on sum(A) would overstate.
        double energy = 0.0;
        for (std::size_t w = 0; w < nw; ++w) {
            const double a = waves[w].amplitude * static_cast<double>(t[nw + w]);
            energy += a * a;
        }
        const double total = std::sqrt(energy);
        if (h <= 0.0) {
            for (std::size_t w = 0; w < nw; ++w) t[nw + w] = 0.0f;
            return;
        }
        const double cap = cap_ratio * h;
        const double ratio = total > 0.0 ? total / cap : 0.0;
        t[4 * nw + 1] = static_cast<float>(std::clamp((ratio - 0.85) / 0.45, 0.0, 1.0));
        if (ratio > 1.0)
            for (std::size_t w = 0; w < nw; ++w) t[nw + w] = static_cast<float>(static_cast<double>(t[nw + w]) / ratio);
        double fold = 0.0;
        for (std::size_t w = 0; w < nw; ++w) {
            const double kl = std::hypot(static_cast<double>(t[2 * nw + w]), static_cast<double>(t[3 * nw + w]));
            fold += waves[w].steepness * kl * waves[w].amplitude * static_cast<double>(t[nw + w]);
        }
        if (fold > kMaxFold) t[4 * nw + 2] = static_cast<float>(kMaxFold / fold);
    });
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> bake_shore_waves(const WaveSet& set, const Terrain& terrain,
                                                           double water_level, const ShoreWaveOptions& options,
                                                           const ShoreField* shoreline) {
    if (options.resolution < 16 || options.resolution > 8192)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore waves: resolution {} is out of range (16 to 8192)", options.resolution)};
    if (!(options.breaking_index > 0.0 && options.breaking_index <= 1.2))
        return Error{ErrorCode::invalid_argument, "shore waves: breaking_index must be in (0, 1.2]"};
    try {
        // The grid: 0..30% of the progress when the shoreline is baked here, then the waves.
        const double grid_share = shoreline ? 0.0 : 0.3;
        auto field = model_grid(terrain, water_level, options, shoreline, grid_share);
        if (!field) return field.error();
        if (options.cancel.stop_requested()) return cancelled();

        const auto waves = set.waves();
        const std::size_t nw = waves.size();
        TilePlan plan = plan_tiles(waves, *field, options.breaking_index, options.store_every_tile, options.threads);
        std::atomic<std::size_t> waves_done{0};
        std::mutex progress_lock;  // the callback is the caller's: one call at a time
        detail::parallel_for_each(nw, options.threads, [&](std::size_t w) {
            if (options.cancel.stop_requested()) return;  // the fields are thrown away below
            if (!plan.tile.empty()) wave_rows(waves[w], *field, march_phase(waves[w], *field), w, plan);
            const std::size_t done = ++waves_done;
            if (options.progress) {
                const std::lock_guard<std::mutex> lock(progress_lock);
                options.progress(grid_share + (1.0 - grid_share) * static_cast<double>(done) / static_cast<double>(nw));
            }
        });
        if (options.cancel.stop_requested()) return cancelled();
        shared_rows(waves, options.breaking_index, *field, plan, options.threads);
        return ShoreWaves::from_tiles({field->resolution, field->texel, field->corner}, std::move(plan.tiles), waves);
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("shore waves: the bake failed: {}", e.what())};
    }
}

}  // namespace tidewater
