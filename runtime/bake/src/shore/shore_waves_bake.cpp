// The shore model's bake: the per-wave fields of ShoreWaves (tidewater/detail/shore_waves.hpp)
// from the shoreline's distance field, by fast marching per wave.
#include "tidewater/detail/shore_waves_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "shore/fast_marching.hpp"
#include "shore/march_record.hpp"
#include "shore/shore_diffraction.hpp"
#include "shore/shore_march_edit.hpp"
#include "shore/shore_marches.hpp"
#include "shore/shore_rows.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {

namespace {

using detail::kDeepKh;
using detail::OpenSeaTest;
using detail::RunTilesView;

/// `target`'s grid over the terrain: depth from the terrain at its texel centres;
/// distance and gradient sampled from `from` (a shoreline field at another resolution),
/// the distance signed by the texel's own depth so that it agrees with `depth`.
Result<ShoreField> resampled_grid(const Terrain& terrain, double water_level, const ShoreGrid& target,
                                  const ShoreField& from, unsigned threads) {
    ShoreField g;
    const int n = target.resolution;
    g.resolution = n;
    g.texel = target.texel;
    g.corner = target.corner;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    auto sized = [count](SharedFloats& grid) {
        std::vector<float>& v = grid.write();
        v.resize(count);
        return v.data();
    };
    float *depths = sized(g.depth), *distances = sized(g.signed_distance);
    std::vector<std::uint16_t>& gradient = g.gradient.write();
    gradient.resize(count);
    std::atomic<bool> finite{true};
    detail::parallel_for_each(static_cast<std::size_t>(n), threads, [&](std::size_t row) {
        const int j = static_cast<int>(row);
        for (int i = 0; i < n; ++i) {
            const std::size_t k = g.index(i, j);
            const glm::dvec2 p = g.texel_center(i, j);
            const double depth = water_level - terrain.height_at(p);
            if (!std::isfinite(depth)) finite = false;
            depths[k] = static_cast<float>(depth);
            distances[k] = resampled_distance(from, p, depth);
            gradient[k] = SharedDirections::encode(detail::resampled_normal(from, p));
        }
    });
    if (!finite)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: the terrain height is not finite somewhere on the model grid"};
    return g;
}

/// The model's own grid from a shoreline baked at another resolution over the terrain's extent.
Result<ShoreField> resample_shoreline(const Terrain& terrain, double water_level, int n, const ShoreField& shoreline,
                                      unsigned threads) {
    const double half = terrain.extent_half_size();
    const ShoreGrid target{n, 2.0 * half / n, terrain.extent_center() - glm::dvec2(half)};
    if (std::abs(shoreline.texel * shoreline.resolution - 2.0 * half) > 1e-6 * half ||
        glm::length(shoreline.corner - target.corner) > 1e-6 * half)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: the shoreline field covers another extent than the terrain"};
    return resampled_grid(terrain, water_level, target, shoreline, threads);
}

Error cancelled() {
    return Error{ErrorCode::cancelled, "shore waves: cancelled"};
}

/// Owns a grid made here; null when not.
std::shared_ptr<const ShoreField> owned(Result<ShoreField> made) {
    return made ? std::make_shared<const ShoreField>(std::move(made).value()) : nullptr;
}

/// The model's grid: the shoreline baked elsewhere (not copied; resampled to the model's
/// resolution where it differs), or baked here over `options.region` with progress 0..`share`.
Result<std::shared_ptr<const ShoreField>> model_grid(const Terrain& terrain, double water_level,
                                                     const ShoreWaveOptions& options, const ShoreField* shoreline,
                                                     double share) {
    if (shoreline && options.region)
        return Error{ErrorCode::invalid_argument,
                     "shore waves: a region is baked with its own shoreline, not one baked elsewhere"};
    if (shoreline && shoreline->resolution == options.resolution)
        return std::shared_ptr<const ShoreField>(std::shared_ptr<void>(), shoreline);
    if (shoreline) {
        auto made = resample_shoreline(terrain, water_level, options.resolution, *shoreline, options.threads);
        if (!made) return made.error();
        return owned(std::move(made));
    }
    BakeOptions bake;
    bake.resolution = options.resolution;
    bake.region = options.region;
    bake.threads = options.threads;
    bake.cancel = options.cancel;
    bake.progress = [&](double f) {
        if (options.progress) options.progress(share * f);
    };
    auto made = bake_shore(terrain, water_level, bake);
    if (!made) return made.error();
    return owned(std::move(made));
}

/// One wave's phase over the grid by fast marching from deep water (or from the edges it
/// enters through, on a domain with none), offset by `base` (returned), and its local
/// wavenumber k(h) per texel (0 on land) in `slowness`. Unreached texels stay infinite.
struct MarchedPhase {
    std::vector<float> slowness;  // the marched wavenumber per texel
    std::vector<double> phase;
    bool any_deep = false;
    double base = 0.0;
};
MarchedPhase march_phase(const Wave& wave, const ShoreField& field) {
    const int n = field.resolution;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    const double k0 = wave.k;
    const glm::dvec2 dir{wave.dir_x, wave.dir_z};
    MarchedPhase m;
    m.slowness.assign(count, 0.0f);
    m.phase.assign(count, detail::kUnreached);
    for (std::size_t k = 0; k < count; ++k) {
        const double h = static_cast<double>(field.depth[k]);
        m.slowness[k] = detail::marched_wavenumber(wave.omega, h);  // 0 on land, which blocks the waves
        m.any_deep = m.any_deep || detail::marched_deep(m.slowness[k], h);
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::size_t k = field.index(i, j);
            if (m.slowness[k] <= 0.0f) continue;
            const bool deep = detail::marched_deep(m.slowness[k], static_cast<double>(field.depth[k]));
            if (detail::phase_source(m.any_deep, deep, i, j, n, dir.x, dir.y))
                m.phase[k] = k0 * glm::dot(dir, field.texel_center(i, j));
        }
    }
    // Offset so the marched values start near zero (keeps doubles exact on big domains).
    m.base = k0 * glm::dot(dir, field.corner);
    for (double& v : m.phase)
        if (std::isfinite(v)) v -= m.base;
    detail::fast_march(m.slowness, m.phase, n, field.texel);
    return m;
}

/// A grid's tiles as the bake fills them, and the grid tile behind each stored slot.
struct TilePlan {
    ShoreGrid grid;
    ShoreTiles tiles;               ///< pages set, texels sized, slots 0 and 1 filled
    std::vector<std::size_t> tile;  ///< per stored slot (from kShoreFirstStoredSlot): its tile
};

/// Which tiles of `field`'s grid to store, known before any wave is marched: a tile is
/// open sea when the layer's longest wave is in deep water (k h >= pi) at every texel of
/// its slot, so that each of its waves keeps its open-sea phase there and shoaling changes
/// its amplitude and wavevector by under 0.4 %, and the open sea's waves neither break nor
/// fold anywhere in it; dry land when every texel is dry and a tile or more from the
/// shoreline. The rest is stored. `open` is the layer's waves' k0 D (none: the shared layer).
TilePlan plan_tiles(const OpenSeaTest& test, std::span<const glm::dvec2> open, const ShoreField& field,
                    double breaking_index, bool every_tile, unsigned threads) {
    TilePlan plan;
    plan.grid = {field.resolution, field.texel, field.corner};
    ShoreTiles& t = plan.tiles;
    t = ShoreTiles::open_grid(field.resolution, open.empty() ? kShoreSharedRows : 4 * open.size());
    const std::size_t m = static_cast<std::size_t>(t.tiles_per_side);
    std::vector<char> kinds(m * m, 's');
    detail::parallel_for_each(m, threads, [&](std::size_t tj) {
        for (std::size_t ti = 0; ti < m; ++ti) {
            const std::size_t tile = tj * m + ti;
            bool is_open = !every_tile && !test.open_folds, dry = !every_tile;
            for (std::size_t k = 0; k < ShoreTiles::kSlotTexels && (is_open || dry); ++k) {
                const std::size_t g = t.grid_index(tile, k);
                const double h = static_cast<double>(field.depth[g]);
                dry = dry && far_dry_land(h, static_cast<double>(field.signed_distance[g]), field.texel);
                // Breaking starts at 0.85 of the cap (cap_breaking); shoaling in deep water stays under 1.
                is_open = is_open && detail::open_sea_texel(test, h, breaking_index);
            }
            kinds[tile] = is_open ? 'o' : dry ? 'd' : 's';
        }
    });
    for (std::size_t tile = 0; tile < kinds.size(); ++tile) {
        if (kinds[tile] == 'd') t.pages[tile] = gpu::kShoreDrySlot;
        if (kinds[tile] != 's') continue;
        t.pages[tile] = static_cast<std::uint32_t>(gpu::kShoreFirstStoredSlot + plan.tile.size());
        plan.tile.push_back(tile);
    }
    return plan;
}

/// The plan's slots, open sea and dry land filled (`open`: the layer's waves' k0 D, none
/// for the shared layer), the stored ones zero until the bake writes them.
void make_slots(TilePlan& plan, std::span<const glm::dvec2> open) {
    plan.tiles.assign_slots(gpu::kShoreFirstStoredSlot + plan.tile.size());
    fill_constant_slots(plan.tiles, open);
}

/// Calls visit(slot texel's floats, grid index, stored slot texel) for every texel of every
/// stored slot, slots spread over workers.
template <typename Visit>
void each_stored_texel(TilePlan& plan, unsigned threads, const Visit& visit) {
    ShoreTiles& t = plan.tiles;
    detail::parallel_for_each(plan.tile.size(), threads, [&](std::size_t s) {
        float* slot = t.slot_for_writing(gpu::kShoreFirstStoredSlot + s);
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k)
            visit(slot + k * t.stride, t.grid_index(plan.tile[s], k), s * ShoreTiles::kSlotTexels + k);
    });
}

/// What the march of a run's waves leaves beside their tiles for the cap and the foam
/// (march_record.hpp): per stored texel and wave, the march's share of the wave's amplitude
/// and its amplitude factor, which the cap blends with the rays' (the tiles hold the rays'
/// until then); per texel of the run's grid, the marched energy and its breaking part in
/// quanta of 2^-24 of the sea's energy: integers, so that the sums do not depend on the
/// order the waves finish in.
struct RunDiffraction {
    RunDiffraction(std::size_t stored_slots, std::size_t waves, int resolution, double quantum, bool kept_for_edits)
        : marched(stored_slots, waves, kept_for_edits), energy(resolution, quantum), kept(waves), spacing(waves, 0.0) {}
    /// Kept with its reach when it outlives the bake (ShoreWaveOptions::keep_marches): an
    /// edit reads where each march reached and broke. The bake's cap alone reads the share
    /// and the amplitude where the march has a share, so without it no more is kept (on a
    /// 16 km world a tenth of the blocks, and a quarter of each).
    detail::MarchedAmplitudes marched;
    detail::MarchedEnergy energy;
    std::mutex lock;  ///< held while a wave's energy is added
    /// With ShoreWaveOptions::keep_marches: each wave's kept march and its spacing.
    std::vector<std::shared_ptr<const detail::KeptMarch>> kept;
    std::vector<double> spacing;
};

/// Wave w of a run's rows of every stored texel from its marched phase: the phase residual,
/// the local wavevector (k0 D + grad residual, of length exactly k(h)) and the amplitude
/// factor from shoaling (energy flux) and refraction (rays against the shore normal), or
/// the march's (`diffracted`) where it holds: its share there, the rays' direction taken
/// in, is written back to `diffracted` and recorded in `record`.
void wave_rows(const Wave& wave, const ShoreField& field, const MarchedPhase& m, detail::DiffractedWave* diffracted,
               std::size_t w, TilePlan& plan, RunDiffraction* record) {
    const int n = field.resolution;
    const std::size_t nw = plan.tiles.stride / 4;
    auto phase = [&](int a, int b) { return m.phase[field.index(a, b)]; };
    if (diffracted) diffracted->held = diffracted->share;
    each_stored_texel(plan, 1, [&](float* t, std::size_t k, std::size_t at) {
        const int i = static_cast<int>(k % static_cast<std::size_t>(n)),
                  j = static_cast<int>(k / static_cast<std::size_t>(n));
        const glm::dvec2 normal(field.gradient[k]);
        const detail::WaveTexel v =
            detail::wave_texel(wave, phase, i, j, n, field.texel, field.texel_center(i, j), m.base,
                               static_cast<double>(field.depth[k]), static_cast<double>(m.slowness[k]), normal,
                               m.any_deep && detail::marched_deep(m.slowness[k], static_cast<double>(field.depth[k])));
        // The march's share at the texel, its apron copies alike (`share` is left as the
        // march made it: where it reached).
        if (diffracted && diffracted->share[k] != 0) {
            // Where the rays do not reach, the march's amplitude is kept (its energy makes
            // foam) but not blended in.
            const bool rays = v.kx != 0.0f || v.kz != 0.0f;
            const std::uint8_t share = rays ? detail::held_share(wave, v.kx, v.kz, diffracted->spacing) : 0;
            diffracted->held[k] = rays ? share : 255;
            if (share != 0 || record->marched.keeps_reach())
                record->marched.set(at, w, share, diffracted->amplitude[k], true, diffracted->broken[k] != 0);
        }
        t[w] = v.residual;
        t[nw + w] = v.amplitude;
        t[2 * nw + w] = v.kx;
        t[3 * nw + w] = v.kz;
    });
}

/// One run of waves being baked: its waves, its grid, and its tiles.
struct RunBake {
    std::size_t first = 0, count = 0;
    /// Its grid: the model's (not owned), or its own; once its waves are marched, a coarse
    /// grid is kept whole only for edits (stored_depth holds what the cap reads).
    std::shared_ptr<const ShoreField> field;
    TilePlan plan;
    std::unique_ptr<RunDiffraction> diffraction;  ///< with ShoreWaveOptions::diffraction
    /// A coarse run's depth at its stored texels (stored slot * kSlotTexels + texel), once
    /// its grid is let go (`field` null).
    std::vector<float> stored_depth;

    /// The depth (m) at grid texel k, stored texel `at`, after the march.
    double depth_at(std::size_t k, std::size_t at) const {
        return static_cast<double>(field ? field->depth[k] : stored_depth[at]);
    }
};

/// A coarse run's grid once its waves are marched, before the shared fields' slots are
/// made: only the depth, which breaking reads, at its stored texels (on a large world a
/// fine coarse run stores a few of its grid's tiles), or over the grid when `for_edits`
/// (an edit's re-bake reads it). The model's grid is kept whole.
void keep_depth_only(RunBake& run, const std::shared_ptr<const ShoreField>& model, bool for_edits) {
    if (run.field == model) return;
    if (!for_edits) {
        const std::vector<std::size_t>& tiles = run.plan.tile;
        run.stored_depth.resize(tiles.size() * ShoreTiles::kSlotTexels);
        for (std::size_t s = 0; s < tiles.size(); ++s)
            for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k)
                run.stored_depth[s * ShoreTiles::kSlotTexels + k] =
                    run.field->depth[run.plan.tiles.grid_index(tiles[s], k)];
        run.field = nullptr;
        return;
    }
    auto depth_only = std::make_shared<ShoreField>();
    depth_only->corner = run.field->corner;
    depth_only->texel = run.field->texel;
    depth_only->resolution = run.field->resolution;
    depth_only->depth = run.field->depth;  // shared, not copied
    run.field = std::move(depth_only);
}

/// Adds a diffracted wave's energy (the march's share, at the stored texels as wave_rows
/// left it) and its breaking part to its run's record.
void record_energy(const Wave& wave, const detail::DiffractedWave& d, RunDiffraction& record) {
    const std::lock_guard<std::mutex> guard(record.lock);
    const double quantum = record.energy.quantum();
    for (std::size_t k = 0; k < d.share.size(); ++k) {
        if (d.held[k] == 0) continue;
        // The amplitude as the record holds it (half precision): a re-bake after an edit
        // sums the same.
        const float amplitude = detail::MarchedAmplitudes::held(d.amplitude[k]);
        record.energy.add(k,
                          detail::energy_quanta(wave.amplitude * static_cast<double>(amplitude), d.held_of(k), quantum),
                          d.broken[k] != 0);
    }
}

/// The runs as the cap reads them.
std::vector<RunTilesView> run_views(const std::vector<RunBake>& runs) {
    std::vector<RunTilesView> views;
    for (const RunBake& r : runs) views.push_back({r.first, r.count, &r.plan.grid, &r.plan.tiles});
    return views;
}

/// The shared layer's rows of every stored texel: depth and shore distance, breaking (all
/// waves together: the foam rises toward the cap) and steepness (Q is scaled where the
/// waves together, capped, would fold). Reads the runs before their caps. With `ratios`,
/// the cap's ratio at each stored texel is kept there.
void shared_rows(std::span<const Wave> waves, double breaking_index, const ShoreField& field,
                 const std::vector<RunBake>& runs, TilePlan& plan, unsigned threads, detail::CapRatios* ratios) {
    const int n = field.resolution;
    const std::vector<RunTilesView> views = run_views(runs);
    std::vector<detail::EnergyView> energies;
    for (const RunBake& r : runs)
        if (r.diffraction) energies.push_back({&r.plan.grid, &r.diffraction->energy});
    each_stored_texel(plan, threads, [&](float* t, std::size_t k, std::size_t at) {
        const int i = static_cast<int>(k % static_cast<std::size_t>(n)),
                  j = static_cast<int>(k / static_cast<std::size_t>(n));
        const double h = static_cast<double>(field.depth[k]);
        const double ratio = h > 0.0 ? detail::cap_ratio(waves, views, plan.grid, i, j, h, breaking_index) : 0.0;
        if (ratios) ratios->fill(at, static_cast<float>(ratio));
        detail::shared_texel_rows(waves, views, plan.grid, i, j, field.depth[k], field.signed_distance[k], ratio, t,
                                  detail::marched_energy_at(energies, plan.grid, i, j, field.texel_center(i, j)));
    });
}

/// Caps every run's amplitudes where the local height exceeds breaking_index * h / 2 of
/// amplitude: all waves scaled down together (each run on its own grid; no wave on land).
void cap_runs(std::span<const Wave> waves, double breaking_index, std::vector<RunBake>& runs, unsigned threads) {
    // Every run's ratios are found before any run is capped (each reads all the runs). Only
    // a slot where the cap bites (a ratio over 1) keeps its ratios: these are made while
    // every run's and the shared layer's slots are held, and the surf zone is a small part
    // of a large world's stored tiles.
    using SlotRatios = std::unique_ptr<float[]>;
    std::vector<std::vector<SlotRatios>> over(runs.size());
    const std::vector<RunTilesView> views = run_views(runs);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        RunBake& run = runs[r];
        const int n = run.plan.grid.resolution;
        over[r].resize(run.plan.tile.size());
        each_stored_texel(run.plan, threads, [&](float*, std::size_t k, std::size_t at) {
            const double h = run.depth_at(k, at);
            if (h <= 0.0) return;
            const int i = static_cast<int>(k % static_cast<std::size_t>(n)),
                      j = static_cast<int>(k / static_cast<std::size_t>(n));
            const double ratio = detail::cap_ratio(waves, views, run.plan.grid, i, j, h, breaking_index);
            if (!(ratio > 1.0)) return;
            SlotRatios& slot = over[r][at / ShoreTiles::kSlotTexels];  // each slot has one worker
            if (!slot) {
                slot = std::make_unique<float[]>(ShoreTiles::kSlotTexels);
                std::fill_n(slot.get(), ShoreTiles::kSlotTexels, 1.0f);
            }
            slot[at % ShoreTiles::kSlotTexels] = static_cast<float>(ratio);
        });
    }
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const std::size_t nw = runs[r].count;
        each_stored_texel(runs[r].plan, threads, [&](float* t, std::size_t k, std::size_t at) {
            const double h = runs[r].depth_at(k, at);
            const float* slot = over[r][at / ShoreTiles::kSlotTexels].get();
            const double ratio = slot ? static_cast<double>(slot[at % ShoreTiles::kSlotTexels]) : 1.0;
            const RunDiffraction* d = runs[r].diffraction.get();
            for (std::size_t w = 0; w < nw; ++w) {
                const float rays = detail::capped_amplitude(t[nw + w], h, ratio);
                t[nw + w] =
                    d ? detail::march_blend(d->marched.share(at, w), d->marched.amplitude(at, w), rays, h) : rays;
            }
        });
    }
}

/// Carries a coarse run's phase residual and wavevector two texels onto land from the
/// water next to it (the residual along the neighbour's own wavevector), the amplitude
/// left at 0: between its last wet texel and the shore a coarse run's waves then keep
/// their phase and direction, and the model's grid (the waterline ramp on its depth)
/// ends them at the shoreline. On the model's own grid the last texel is a fraction of
/// a wavelength and the fields stop there.
void extend_onto_land(std::span<const Wave> waves, RunBake& run, unsigned threads) {
    const ShoreGrid& g = run.plan.grid;
    const int n = g.resolution;
    const std::size_t nw = run.count;
    // A ring's values, found from the tiles as they were and written after: per stored
    // slot, (float index in the slot, value).
    struct Update {
        std::size_t at;
        float value;
    };
    const ShoreTiles& tiles = run.plan.tiles;
    std::vector<std::vector<Update>> updates(run.plan.tile.size());
    for (int ring = 0; ring < 2; ++ring) {
        detail::parallel_for_each(run.plan.tile.size(), threads, [&](std::size_t s) {
            const float* slot = tiles.slot(gpu::kShoreFirstStoredSlot + s);
            std::vector<Update>& out = updates[s];
            out.clear();
            for (std::size_t texel = 0; texel < ShoreTiles::kSlotTexels; ++texel) {
                const float* t = slot + texel * tiles.stride;
                const std::size_t k = tiles.grid_index(run.plan.tile[s], texel);
                const int i = static_cast<int>(k % static_cast<std::size_t>(n)),
                          j = static_cast<int>(k / static_cast<std::size_t>(n));
                for (std::size_t w = 0; w < nw; ++w) {
                    if (detail::carries_wave(t, nw, w)) continue;  // a wave is here
                    const auto v = detail::carried_onto_land(waves[run.first + w], tiles, nw, w, i, j, n, g.texel,
                                                             [](int, int) { return true; });
                    if (!v) continue;
                    const std::size_t at = texel * tiles.stride;
                    out.push_back({at + w, v->residual});
                    out.push_back({at + 2 * nw + w, v->kx});
                    out.push_back({at + 3 * nw + w, v->kz});
                }
            }
        });
        detail::parallel_for_each(run.plan.tile.size(), threads, [&](std::size_t s) {
            if (updates[s].empty()) return;
            float* slot = run.plan.tiles.slot_for_writing(gpu::kShoreFirstStoredSlot + s);
            for (const Update& u : updates[s]) slot[u.at] = u.value;
        });
    }
}

/// The runs of consecutive waves and each one's texel, a power of two times the model's:
/// the largest whose shortest wave keeps `texels_per_wavelength` texels a deep-water
/// wavelength (0: every wave on the model's grid), while the run's grid keeps at least a
/// tile a side. Neighbouring runs merge (on the finer texel) until there are at most
/// kShoreMaxLayers.
struct Run {
    std::size_t first = 0, count = 0;
    int scale = 1;
};
std::vector<Run> plan_runs(std::span<const Wave> waves, double texel, int resolution, double texels_per_wavelength) {
    std::vector<Run> runs;
    for (std::size_t w = 0; w < waves.size(); ++w) {
        int scale = 1;
        if (texels_per_wavelength > 0.0)
            while ((resolution + 2 * scale - 1) / (2 * scale) >= ShoreTiles::kTile &&
                   2.0 * scale * texel * texels_per_wavelength <= kTwoPi / waves[w].k)
                scale *= 2;
        if (!runs.empty() && runs.back().scale == scale)
            ++runs.back().count;
        else
            runs.push_back({w, 1, scale});
    }
    while (runs.size() > gpu::kShoreMaxLayers) {
        // Merge the neighbours whose texels differ least (the first such pair).
        std::size_t best = 0;
        double best_gap = 1e300;
        for (std::size_t r = 0; r + 1 < runs.size(); ++r) {
            const double gap = std::abs(std::log2(static_cast<double>(runs[r].scale) / runs[r + 1].scale));
            if (gap < best_gap) {
                best_gap = gap;
                best = r;
            }
        }
        runs[best].count += runs[best + 1].count;
        runs[best].scale = std::min(runs[best].scale, runs[best + 1].scale);
        runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(best) + 1);
    }
    return runs;
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
    if (!(options.texels_per_wavelength >= 0.0) || !std::isfinite(options.texels_per_wavelength))
        return Error{ErrorCode::invalid_argument, "shore waves: texels_per_wavelength must be finite and >= 0"};
    try {
        // The grid: 0..30% of the progress when the shoreline is baked here, then the waves.
        const double grid_share = shoreline ? 0.0 : 0.3;
        auto grid = model_grid(terrain, water_level, options, shoreline, grid_share);
        if (!grid) return grid.error();
        const std::shared_ptr<const ShoreField> field = std::move(grid).value();
        if (options.cancel.stop_requested()) return cancelled();

        const auto waves = set.waves();
        const std::size_t nw = waves.size();
        std::vector<glm::dvec2> open;
        for (const Wave& w : waves) open.push_back(w.k * glm::dvec2(w.dir_x, w.dir_z));
        const detail::SeaState sea = detail::sea_state(waves);
        const bool keeps_marches = options.keep_marches && options.diffraction;
        // Each run on its own grid: the model's, or every scale-th texel's size from the same corner.
        std::vector<RunBake> runs;
        for (const Run& r : plan_runs(waves, field->texel, field->resolution, options.texels_per_wavelength)) {
            RunBake run{r.first, r.count, nullptr, {}, nullptr, {}};
            if (r.scale == 1) {
                run.field = field;
            } else {
                const ShoreGrid g{(field->resolution + r.scale - 1) / r.scale, field->texel * r.scale, field->corner};
                auto coarse = resampled_grid(terrain, water_level, g, *field, options.threads);
                if (!coarse) return coarse.error();
                run.field = std::make_shared<const ShoreField>(std::move(coarse).value());
            }
            run.plan = plan_tiles(detail::open_sea_test(waves, r.first, r.count),
                                  std::span<const glm::dvec2>(open).subspan(r.first, r.count), *run.field,
                                  options.breaking_index, options.store_every_tile, options.threads);
            if (options.diffraction) {
                run.diffraction =
                    std::make_unique<RunDiffraction>(run.plan.tile.size(), r.count, run.field->resolution,
                                                     std::ldexp(std::max(sea.energy, 1e-30), -24), keeps_marches);
            }
            runs.push_back(std::move(run));
        }
        std::vector<std::size_t> run_of(nw);
        for (std::size_t r = 0; r < runs.size(); ++r)
            for (std::size_t w = runs[r].first; w < runs[r].first + runs[r].count; ++w) run_of[w] = r;
        // A random sea breaks as a whole: marched once as one wave, on the grid of the run
        // whose waves' periods are nearest its mean period (its wavelength needs no finer),
        // its height is where every component breaks.
        std::optional<detail::SeaHeight> sea_height;
        std::optional<detail::SeaMarch> sea_march;  // with keep_marches
        if (options.diffraction && sea.components > 1) {
            std::size_t nearest = 0;
            for (std::size_t w = 1; w < nw; ++w)
                if (std::abs(waves[w].period() - sea.mean_period) < std::abs(waves[nearest].period() - sea.mean_period))
                    nearest = w;
            std::unique_ptr<detail::KeptMarch> sea_kept;
            if (options.keep_marches) sea_kept = std::make_unique<detail::KeptMarch>();
            sea_height = detail::march_sea(waves, sea, runs[run_of[nearest]].field, sea_kept.get());
            if (options.keep_marches)
                if (const auto whole = detail::whole_sea_wave(waves, sea))
                    sea_march = detail::SeaMarch{*whole, run_of[nearest], *sea_height, std::move(sea_kept)};
        }
        std::atomic<std::size_t> waves_done{0};
        std::mutex progress_lock;  // the callback is the caller's: one call at a time
        // The shortest waves first: their runs lie on the finest grids, whose marches take
        // the most memory, and are marched before the long waves' runs, which store the
        // most tiles, have their slots made (a run's slots are made as its first wave starts):
        // the waves start in that order whichever worker takes them.
        std::vector<std::once_flag> slots_made(runs.size());
        std::vector<std::atomic<std::size_t>> waves_left(runs.size());
        for (std::size_t r = 0; r < runs.size(); ++r) waves_left[r] = runs[r].count;
        detail::parallel_in_order(nw, options.threads, [&](std::size_t i) {
            if (options.cancel.stop_requested()) return;  // the fields are thrown away below
            const std::size_t w = nw - 1 - i;
            RunBake& run = runs[run_of[w]];
            std::call_once(slots_made[run_of[w]], [&] {
                make_slots(run.plan, std::span<const glm::dvec2>(open).subspan(run.first, run.count));
            });
            if (!run.plan.tile.empty()) {
                const MarchedPhase m = march_phase(waves[w], *run.field);
                std::optional<detail::DiffractedWave> diffracted;
                detail::KeptMarch kept;
                if (run.diffraction) {
                    const ShoreField& f = *run.field;
                    diffracted = detail::diffract_wave(
                        waves[w], sea, f,
                        [&](std::size_t k) {
                            return !std::isfinite(m.phase[k]) ||
                                   (m.any_deep && detail::marched_deep(m.slowness[k], static_cast<double>(f.depth[k])));
                        },
                        sea_height ? &*sea_height : nullptr, options.keep_marches ? &kept : nullptr);
                    if (options.keep_marches) {
                        run.diffraction->kept[w - run.first] =
                            std::make_shared<const detail::KeptMarch>(std::move(kept));
                        run.diffraction->spacing[w - run.first] = diffracted->spacing;
                    }
                }
                wave_rows(waves[w], *run.field, m, diffracted ? &*diffracted : nullptr, w - run.first, run.plan,
                          run.diffraction.get());
                if (diffracted) record_energy(waves[w], *diffracted, *run.diffraction);
            }
            if (--waves_left[run_of[w]] == 0) keep_depth_only(run, field, keeps_marches);
            const std::size_t done = ++waves_done;
            if (options.progress) {
                const std::lock_guard<std::mutex> lock(progress_lock);
                options.progress(grid_share + (1.0 - grid_share) * static_cast<double>(done) / static_cast<double>(nw));
            }
        });
        if (options.cancel.stop_requested()) return cancelled();
        sea_height.reset();  // holds a run's whole grid
#ifdef __GLIBC__
        // The marches' rows, buckets and grids are freed; glibc keeps such pages resident
        // until asked. Given back before the shared layer's slots are made, beside the
        // runs' tiles: from there to the end of the bake its memory is at its peak.
        malloc_trim(0);
#endif
        TilePlan shared = plan_tiles(detail::open_sea_test(waves, 0, nw), {}, *field, options.breaking_index,
                                     options.store_every_tile, options.threads);
        make_slots(shared, {});
        detail::CapRatios ratios(keeps_marches ? shared.tile.size() : 0);
        shared_rows(waves, options.breaking_index, *field, runs, shared, options.threads,
                    keeps_marches ? &ratios : nullptr);
        cap_runs(waves, options.breaking_index, runs, options.threads);
        for (RunBake& r : runs)
            if (r.plan.grid.texel != field->texel) extend_onto_land(waves, r, options.threads);
        if (keeps_marches) {
            auto marches = std::make_shared<detail::ShoreMarches>();
            marches->sea = sea;
            marches->ratios = std::move(ratios);
            marches->sea_march = std::move(sea_march);
            for (RunBake& r : runs)
                marches->runs.push_back({r.field, std::move(r.diffraction->marched), std::move(r.diffraction->energy),
                                         std::move(r.diffraction->kept), std::move(r.diffraction->spacing)});
            *options.keep_marches = std::move(marches);
        }
        std::vector<ShoreWaveLayer> layers;
        for (RunBake& r : runs) layers.push_back({r.plan.grid, r.first, r.count, std::move(r.plan.tiles)});
        return ShoreWaves::from_tiles(shared.grid, std::move(shared.tiles), std::move(layers), waves);
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("shore waves: the bake failed: {}", e.what())};
    }
}

}  // namespace tidewater
