#include "tidewater/detail/shore_water_edit.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <tuple>
#include <vector>

#include "shore/fast_marching.hpp"
#include "shore/shore_edit_region.hpp"
#include "shore/shore_march_edit.hpp"
#include "shore/shore_rows.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::detail {

namespace {

/// Depths at a grid's texel centres over a terrain, as the bake computes them (level -
/// height, in float).
struct GridDepth {
    const Terrain* terrain = nullptr;
    double level = 0.0;
    ShoreGrid grid;
    glm::dvec2 centre(int i, int j) const { return grid.corner + grid.texel * glm::dvec2(i + 0.5, j + 0.5); }
    float at(int i, int j) const { return static_cast<float>(level - terrain->height_at(centre(i, j))); }
};

/// `r` grown by `by` texels a side, within an n x n grid.
TexelRange grown(const TexelRange& r, int by, int n) {
    return {std::max(0, r.i0 - by), std::max(0, r.j0 - by), std::min(n - 1, r.i1 + by), std::min(n - 1, r.j1 + by)};
}

/// Whether every texel of `r` and a step round it is wet before and after.
bool stays_wet(const TexelRange& r, int n, const GridDepth& before, const GridDepth& after) {
    const TexelRange around = grown(r, 1, n);
    for (int j = around.j0; j <= around.j1; ++j)
        for (int i = around.i0; i <= around.i1; ++i)
            if (!(before.at(i, j) > 0.0f && after.at(i, j) > 0.0f)) return false;
    return true;
}

/// Where the distance field `after` differs from `before` (the same grid): the bounding
/// ranges of the texels whose distance moved, and of the wet ones (after) whose normal
/// moved, which the waves' rows read. Empty where none.
struct DistancesMoved {
    TexelRange distance, normal;
};
DistancesMoved distances_moved(const ShoreField& before, const ShoreField& after, unsigned threads) {
    const int n = before.resolution;
    std::vector<glm::ivec4> per_row(static_cast<std::size_t>(n), glm::ivec4(n, -1, n, -1));
    parallel_for_each(static_cast<std::size_t>(n), threads, [&](std::size_t row) {
        const int j = static_cast<int>(row);
        glm::ivec4& r = per_row[row];
        for (int i = 0; i < n; ++i) {
            const std::size_t k = before.index(i, j);
            if (before.signed_distance[k] != after.signed_distance[k])
                r = {std::min(r.x, i), std::max(r.y, i), r.z, r.w};
            if (before.gradient[k] != after.gradient[k] && after.depth[k] > 0.0f)
                r = {r.x, r.y, std::min(r.z, i), std::max(r.w, i)};
        }
    });
    DistancesMoved moved{{n, n, -1, -1}, {n, n, -1, -1}};
    auto add = [](TexelRange& m, int lo, int hi, int j) {
        if (lo <= hi) m = {std::min(m.i0, lo), std::min(m.j0, j), std::max(m.i1, hi), std::max(m.j1, j)};
    };
    for (int j = 0; j < n; ++j) {
        const glm::ivec4 r = per_row[static_cast<std::size_t>(j)];
        add(moved.distance, r.x, r.y, j);
        add(moved.normal, r.z, r.w, j);
    }
    return moved;
}

/// The shore distance the bake's grid `after.grid` holds at its texel (i, j), index g,
/// `h` deep, over the shoreline `line`: the line's own on its grid, else resampled.
float held_distance(const ShoreField& line, const GridDepth& after, std::size_t g, int i, int j, float h) {
    if (after.grid == ShoreGrid{line.resolution, line.texel, line.corner}) return line.signed_distance[g];
    return resampled_distance(line, after.centre(i, j), static_cast<double>(h));
}

/// Whether every tile whose slot holds a texel of `r` keeps the kind the bake gave it
/// (plan_tiles) over the depths after and the shoreline `line` after: open sea where the
/// bake left it out as open sea, dry land where it left it dry, stored where it stored
/// it. `ask_open` false: where the depths did not change, whether it is open sea stays.
bool same_tile_kinds(const ShoreTiles& tiles, const TexelRange& r, const OpenSeaTest& test, double breaking_index,
                     const GridDepth& after, const ShoreField& line, bool ask_open = true) {
    const int m = tiles.tiles_per_side, n = tiles.resolution, kTile = ShoreTiles::kTile;
    for (int tj = std::max(0, (r.j0 - 1) / kTile); tj <= std::min(m - 1, r.j1 / kTile); ++tj)
        for (int ti = std::max(0, (r.i0 - 1) / kTile); ti <= std::min(m - 1, r.i1 / kTile); ++ti) {
            const std::uint32_t page = tiles.page(ti, tj);
            const std::size_t tile =
                static_cast<std::size_t>(tj) * static_cast<std::size_t>(m) + static_cast<std::size_t>(ti);
            bool open = ask_open ? !test.open_folds : page == gpu::kShoreOpenSlot, dry = true;
            for (std::size_t k = 0; k < ShoreTiles::kSlotTexels && ((ask_open && open) || dry); ++k) {
                const std::size_t g = tiles.grid_index(tile, k);
                const int i = static_cast<int>(g % static_cast<std::size_t>(n)),
                          j = static_cast<int>(g / static_cast<std::size_t>(n));
                const float h = after.at(i, j);
                if (dry)
                    dry = far_dry_land(static_cast<double>(h),
                                       static_cast<double>(held_distance(line, after, g, i, j, h)), after.grid.texel);
                if (ask_open && open) open = open_sea_texel(test, static_cast<double>(h), breaking_index);
            }
            const std::uint32_t kind = open  ? static_cast<std::uint32_t>(gpu::kShoreOpenSlot)
                                       : dry ? static_cast<std::uint32_t>(gpu::kShoreDrySlot)
                                             : static_cast<std::uint32_t>(gpu::kShoreFirstStoredSlot);
            if (kind != std::min(page, static_cast<std::uint32_t>(gpu::kShoreFirstStoredSlot))) return false;
        }
    return true;
}

/// Values over a range of texels, row-major.
template <typename T>
struct Patch {
    TexelRange range;
    std::size_t per_texel = 1;
    std::vector<T> values;
    void assign(const TexelRange& r, std::size_t per, T value) {
        range = r;
        per_texel = per;
        values.assign(static_cast<std::size_t>(r.width()) * static_cast<std::size_t>(r.height()) * per, value);
    }
    std::size_t at(int i, int j) const {
        return (static_cast<std::size_t>(j - range.j0) * static_cast<std::size_t>(range.width()) +
                static_cast<std::size_t>(i - range.i0)) *
               per_texel;
    }
    T* operator()(int i, int j) { return values.data() + at(i, j); }
    const T* operator()(int i, int j) const { return values.data() + at(i, j); }
};

/// One run of waves as the edit re-bakes it.
struct RunEdit {
    const ShoreWaveLayer* layer = nullptr;
    GridDepth before, after;
    TexelRange edit;                 ///< texels whose depth may have changed
    TexelRange normals_moved;        ///< texels under water whose shore normal may have moved (the shoreline moved)
    std::vector<char> any_deep;      ///< per wave: the grid has deep water for it (before and after alike)
    std::vector<MarchWindow> march;  ///< per wave: its phase after, in a window
    TexelRange own;                  ///< its windows and a texel round them: its phase baked again
    TexelRange capped;               ///< where what the cap reads moved: every row baked again
    TexelRange rows;                 ///< both (their bounding range): the depths and rows made over it
    /// On the model's grid, its shared tiles: where their breaking is 0 the cap left the
    /// run's stored amplitudes as they were. Null on other grids.
    const ShoreTiles* uncapped_before = nullptr;
    Patch<float> depth_before, depth_after;  ///< over rows and three texels round them
    Patch<glm::vec2> normal;                 ///< the shore normal the bake's grid holds, same patch
    Patch<float> fields;                     ///< the run's rows before the cap, over rows and two texels round them
    ShoreTiles before_cap, out;

    int n() const { return layer->grid.resolution; }
    glm::dvec2 centre(int i, int j) const { return after.centre(i, j); }
    double base(const Wave& w) const { return w.k * glm::dot(glm::dvec2(w.dir_x, w.dir_z), layer->grid.corner); }
    /// Wave w's phase before the edit, from its stored residual (kUnreached on land and
    /// where the wave did not reach), offset as the march is.
    double phase_before(const Wave& wave, std::size_t w, int i, int j, float depth) const {
        if (!(depth > 0.0f)) return kUnreached;
        const float* t = layer->tiles.texel(i, j);
        if (!carries_wave(t, layer->count, w)) return kUnreached;
        return static_cast<double>(t[w]) + wave.k * glm::dot(glm::dvec2(wave.dir_x, wave.dir_z), centre(i, j)) -
               base(wave);
    }
    /// Whether phase_before is finite there: the wave reached the texel, under water.
    bool reached_before(std::size_t w, int i, int j, float depth) const {
        return depth > 0.0f && carries_wave(layer->tiles.texel(i, j), layer->count, w);
    }
};

/// Per wave of the run, whether its grid has deep water for it outside the edit (the
/// phase's sources, the same before and after): a deep texel is a source, and a source
/// keeps a residual of exactly 0, so the texels with none (and a wave: land and unreached
/// water carry no wavevector) are the only ones whose depth is asked. The run has no open
/// sea (whose tiles are deep for every wave).
std::vector<char> deep_water_outside_edit(const RunEdit& r, std::span<const Wave> waves) {
    const ShoreTiles& tiles = r.layer->tiles;
    const std::size_t n = static_cast<std::size_t>(r.n()), nw = r.layer->count;
    std::vector<char> deep(nw, 0), known(nw, 0);
    std::size_t found = 0;
    // Nothing lies under a heightmap's lowest height (its edge fades to it): a wave for
    // which that depth is not deep has no deep water anywhere.
    const Terrain& terrain = *r.before.terrain;
    if (const auto* map = std::get_if<HeightmapTerrain>(&terrain.shape()); map && terrain.cuts().empty())
        for (std::size_t w = 0; w < nw; ++w)
            if (!marched_deep_water(waves[r.layer->first + w].omega, r.before.level - map->min_height)) {
                known[w] = 1;
                ++found;
            }
    for (std::size_t tile = 0; tile < tiles.pages.size() && found < nw; ++tile) {
        const std::uint32_t page = tiles.pages[tile];
        if (page < gpu::kShoreFirstStoredSlot) continue;
        const float* slot = tiles.slot(page);
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* t = slot + k * tiles.stride;
            for (std::size_t w = 0; w < nw; ++w) {
                if (known[w] || t[w] != 0.0f || !carries_wave(t, nw, w)) continue;
                const std::size_t g = tiles.grid_index(tile, k);
                if (r.edit.contains(static_cast<int>(g % n), static_cast<int>(g / n))) continue;
                if (marched_deep_water(
                        waves[r.layer->first + w].omega,
                        static_cast<double>(r.before.at(static_cast<int>(g % n), static_cast<int>(g / n))))) {
                    deep[w] = known[w] = 1;
                    ++found;
                }
            }
        }
    }
    return deep;
}

/// Whether the edit's texels hold deep water for `wave` over `depths` (the run's before
/// or after the edit).
bool deep_water_in_edit(const RunEdit& r, const Wave& wave, const GridDepth& depths) {
    for (int j = r.edit.j0; j <= r.edit.j1; ++j)
        for (int i = r.edit.i0; i <= r.edit.i1; ++i)
            if (marched_deep_water(wave.omega, static_cast<double>(depths.at(i, j)))) return true;
    return false;
}

/// World xz of the edges of texels [i0, i1) x [j0, j1) of `g`.
WorldRect edges(const ShoreGrid& g, int i0, int j0, int i1, int j1) {
    return {g.corner + g.texel * glm::dvec2(i0, j0), g.corner + g.texel * glm::dvec2(i1, j1)};
}
void unite(WorldRect& a, const WorldRect& b) {
    a.lo = glm::min(a.lo, b.lo);
    a.hi = glm::max(a.hi, b.hi);
}

/// Calls body(i, j) for every texel of `r`, rows spread over workers.
template <typename Body>
void each_texel(const TexelRange& r, unsigned threads, const Body& body) {
    if (r.empty()) return;
    parallel_for_each(static_cast<std::size_t>(r.height()), threads, [&](std::size_t row) {
        const int j = r.j0 + static_cast<int>(row);
        for (int i = r.i0; i <= r.i1; ++i) body(i, j);
    });
}

/// The shore normals the bake's grids hold, read where an edit needs them: the model's
/// grid holds the shoreline's own where the two grids are one, else the shoreline's
/// resampled (resampled_grid); a coarse run's grid resamples the model's grid. Nothing is
/// made over a whole grid.
struct GridNormals {
    const ShoreField& shoreline;
    ShoreGrid model;

    glm::vec2 on_model(int i, int j) const {
        if (model == shoreline_grid()) {
            const std::size_t k = shoreline.index(i, j);
            return shoreline.gradient[k];
        }
        return held_normal(resampled_normal(shoreline, model.corner + model.texel * glm::dvec2(i + 0.5, j + 0.5)));
    }
    /// Texel (i, j) of grid g (the model's or a coarse run's), whose centre is `centre`.
    glm::vec2 at(const ShoreGrid& g, int i, int j, glm::dvec2 centre) const {
        if (g == model) return on_model(i, j);
        // resampled_normal over the model's grid, its four taps made here.
        const GridTaps t = grid_taps(model.corner, model.texel, model.resolution, centre);
        const auto tap = [&](std::size_t k) {
            const std::size_t n = static_cast<std::size_t>(model.resolution);
            return glm::dvec2(on_model(static_cast<int>(k % n), static_cast<int>(k / n)));
        };
        const glm::dvec2 g00 = tap(t.k00), g10 = tap(t.k10), g01 = tap(t.k01), g11 = tap(t.k11);
        return held_normal(unit_normal({t.w00 * g00.x + t.w10 * g10.x + t.w01 * g01.x + t.w11 * g11.x,
                                        t.w00 * g00.y + t.w10 * g10.y + t.w01 * g01.y + t.w11 * g11.y}));
    }
    ShoreGrid shoreline_grid() const { return {shoreline.resolution, shoreline.texel, shoreline.corner}; }
};

/// The run's depths and normals over `rows` and three texels round them (what the rows,
/// their derivatives and the cap's taps read).
void cover(RunEdit& r, const TexelRange& rows, const GridNormals& normals, unsigned threads) {
    r.rows = rows;
    const TexelRange patch = grown(rows, 3, r.n());
    r.depth_before.assign(patch, 1, 0.0f);
    r.depth_after.assign(patch, 1, 0.0f);
    r.normal.assign(patch, 1, glm::vec2(0.0f));
    const ShoreGrid& g = r.layer->grid;
    each_texel(patch, threads, [&](int i, int j) {
        const float after = r.after.at(i, j);
        *r.depth_after(i, j) = after;
        *r.depth_before(i, j) = r.edit.contains(i, j) ? r.before.at(i, j) : after;  // the same heights elsewhere
        *r.normal(i, j) = normals.at(g, i, j, r.centre(i, j));
    });
}

/// The run's rows before the cap at texel (i, j) into t (4 floats a wave), each wave's
/// phase phase(w, a, b), over the depths after.
template <typename Phase>
void texel_rows(std::span<const Wave> waves, const RunEdit& r, int i, int j, const Phase& phase, float* t) {
    const std::size_t nw = r.layer->count;
    const double h = static_cast<double>(*r.depth_after(i, j));
    const glm::dvec2 normal{*r.normal(i, j)};
    for (std::size_t w = 0; w < nw; ++w) {
        const Wave& wave = waves[r.layer->first + w];
        const float kl = marched_wavenumber(wave.omega, h);
        const bool source = r.any_deep[w] && marched_deep(kl, h);
        const WaveTexel v = wave_texel(
            wave, [&](int a, int b) { return phase(w, a, b); }, i, j, r.n(), r.layer->grid.texel, r.centre(i, j),
            r.base(wave), h, static_cast<double>(kl), normal, source);
        t[w] = v.residual;
        t[nw + w] = v.amplitude;
        t[2 * nw + w] = v.kx;
        t[3 * nw + w] = v.kz;
    }
}

/// The run's rows before the cap over `range` (within the covered patch less a texel),
/// each wave's phase the window's where it was re-marched and the stored one's
/// elsewhere, over the depths after; copied from `known` where it holds them.
Patch<float> rows_before_cap(std::span<const Wave> waves, const RunEdit& r, const TexelRange& range, unsigned threads,
                             const Patch<float>* known = nullptr) {
    const std::size_t nw = r.layer->count;
    const TexelRange p = grown(range, 1, r.n());
    std::vector<Patch<double>> phase(nw);
    parallel_for_each(nw, threads, [&](std::size_t w) {
        const Wave& wave = waves[r.layer->first + w];
        const MarchWindow& m = r.march[w];
        phase[w].assign(p, 1, kUnreached);
        for (int j = p.j0; j <= p.j1; ++j)
            for (int i = p.i0; i <= p.i1; ++i)
                *phase[w](i, j) =
                    m.window.contains(i, j) ? m.at(i, j) : r.phase_before(wave, w, i, j, *r.depth_before(i, j));
    });
    Patch<float> fields;
    fields.assign(range, 4 * nw, 0.0f);
    each_texel(range, threads, [&](int i, int j) {
        if (known && known->range.contains(i, j))
            std::copy_n((*known)(i, j), 4 * nw, fields(i, j));
        else if (r.uncapped_before && !r.own.contains(i, j) && !r.edit.contains(i, j) &&
                 !r.normals_moved.contains(i, j) && r.uncapped_before->texel(i, j)[1] == 0.0f)
            // Its phase and depth as before and nothing capped it: the stored rows are
            // the ones before the cap.
            std::copy_n(r.layer->tiles.texel(i, j), 4 * nw, fields(i, j));
        else
            texel_rows(
                waves, r, i, j, [&](std::size_t w, int a, int b) { return *phase[w](a, b); }, fields(i, j));
    });
    return fields;
}

/// The texels of `own` whose amplitude factor or wavevector before the cap (`fields`)
/// differs from the stored one by more than kCapReadTolerance (relative to k0 for the
/// wavevector): where the re-marched phase moves what the cap reads, and where the
/// stored amplitudes were capped. Their bounding range, empty when none.
constexpr double kCapReadTolerance = 1e-4;
TexelRange cap_inputs_moved(std::span<const Wave> waves, const RunEdit& r, const TexelRange& own, unsigned threads) {
    const std::size_t nw = r.layer->count;
    auto differs = [&](const float* a, const float* b) {
        for (std::size_t w = 0; w < nw; ++w) {
            const double k0 = waves[r.layer->first + w].k;
            auto apart = [&](std::size_t row) { return static_cast<double>(std::abs(a[row] - b[row])); };
            if (apart(nw + w) > kCapReadTolerance || apart(2 * nw + w) > kCapReadTolerance * k0 ||
                apart(3 * nw + w) > kCapReadTolerance * k0)
                return true;
        }
        return false;
    };
    // Per row of `own`, the first and last texel that moved.
    std::vector<glm::ivec2> per_row(static_cast<std::size_t>(own.height()), glm::ivec2(own.i1 + 1, own.i0 - 1));
    parallel_for_each(per_row.size(), threads, [&](std::size_t row) {
        const int j = own.j0 + static_cast<int>(row);
        std::vector<float> old(4 * nw);
        for (int i = own.i0; i <= own.i1; ++i) {
            // The stored rows are capped in the surf: there the rows before the edit tell.
            if (!differs(r.fields(i, j), r.layer->tiles.texel(i, j))) continue;
            texel_rows(
                waves, r, i, j,
                [&](std::size_t w, int a, int b) {
                    return r.phase_before(waves[r.layer->first + w], w, a, b, *r.depth_before(a, b));
                },
                old.data());
            if (!differs(r.fields(i, j), old.data())) continue;
            per_row[row] = {std::min(per_row[row].x, i), std::max(per_row[row].y, i)};
        }
    });
    TexelRange moved{own.i1 + 1, own.j1 + 1, own.i0 - 1, own.j0 - 1};
    for (std::size_t row = 0; row < per_row.size(); ++row) {
        if (per_row[row].x > per_row[row].y) continue;
        const int j = own.j0 + static_cast<int>(row);
        moved = {std::min(moved.i0, per_row[row].x), std::min(moved.j0, j), std::max(moved.i1, per_row[row].y),
                 std::max(moved.j1, j)};
    }
    return moved;
}

/// Writes `fields` over `f` into a copy of the run's tiles: what the cap reads.
void write_before_cap(RunEdit& r, const TexelRange& f, unsigned threads) {
    const std::size_t nw = r.layer->count;
    r.before_cap = r.layer->tiles;
    r.before_cap.write_texels(
        f.i0, f.j0, f.i1 + 1, f.j1 + 1, [&](float* t, int i, int j) { std::copy_n(r.fields(i, j), 4 * nw, t); },
        threads);
}

/// A coarse run's waves carried two texels onto land round its rows, as the bake's
/// extend_onto_land does: the first ring from the water, the second from the first.
void carry_onto_land(std::span<const Wave> waves, RunEdit& r, unsigned threads) {
    const std::size_t nw = r.layer->count;
    const int n = r.n();
    const double texel = r.layer->grid.texel;
    auto wet = [&](int a, int b) { return *r.depth_after(a, b) > 0.0f; };
    auto carries = [&](int a, int b, std::size_t w) { return carries_wave(r.out.texel(a, b), nw, w); };
    for (int ring = 1; ring <= 2; ++ring) {
        Patch<float> carried;  // per texel and wave: residual, kx, kz, and 1 where carried
        carried.assign(r.rows, 4 * nw, 0.0f);
        each_texel(r.rows, threads, [&](int i, int j) {
            if (wet(i, j)) return;
            float* c = carried(i, j);
            for (std::size_t w = 0; w < nw; ++w) {
                if (carries(i, j, w)) continue;
                // The first ring takes the water's values; the second the first ring's.
                auto from = [&](int a, int b) {
                    if (ring == 1) return wet(a, b);
                    if (wet(a, b)) return false;
                    for (const glm::ivec2 d :
                         {glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)}) {
                        const int c0 = a + d.x, c1 = b + d.y;
                        if (c0 >= 0 && c1 >= 0 && c0 < n && c1 < n && wet(c0, c1) && carries(c0, c1, w)) return true;
                    }
                    return false;
                };
                const auto v = carried_onto_land(waves[r.layer->first + w], r.out, nw, w, i, j, n, texel, from);
                if (!v) continue;
                c[4 * w] = v->residual;
                c[4 * w + 1] = v->kx;
                c[4 * w + 2] = v->kz;
                c[4 * w + 3] = 1.0f;
            }
        });
        r.out.write_texels(
            r.rows.i0, r.rows.j0, r.rows.i1 + 1, r.rows.j1 + 1,
            [&](float* t, int i, int j) {
                const float* c = carried(i, j);
                for (std::size_t w = 0; w < nw; ++w) {
                    if (c[4 * w + 3] == 0.0f) continue;
                    t[w] = c[4 * w];
                    t[2 * nw + w] = c[4 * w + 1];
                    t[3 * nw + w] = c[4 * w + 2];
                }
            },
            threads);
    }
}

}  // namespace

std::optional<WaterEdit> rebake_water_edit(const HeightmapChange& change, const Terrain& before, const Terrain& after,
                                           double water_level, std::span<const Wave> waves, double breaking_index,
                                           const std::shared_ptr<const ShoreField>& shoreline_ptr,
                                           const std::shared_ptr<const ShoreWaves>& model_ptr, unsigned threads,
                                           const std::shared_ptr<const ShoreMarches>& marches,
                                           const std::shared_ptr<const ShoreField>& shoreline_after) {
    if (!change) return std::nullopt;
    if (!*change) return WaterEdit{shoreline_ptr, model_ptr, marches};  // the same pixels in another image
    const WorldRect& reach = **change;
    const ShoreField& shoreline = *shoreline_ptr;
    const ShoreWaves& model = *model_ptr;
    if (model.wave_count() != waves.size()) return std::nullopt;
    if (marches && marches->runs.size() != model.layers().size()) return std::nullopt;
    const ShoreGrid distance_grid{shoreline.resolution, shoreline.texel, shoreline.corner};
    auto depths = [&](const ShoreGrid& g) {
        return std::pair{GridDepth{&before, water_level, g}, GridDepth{&after, water_level, g}};
    };
    auto edited = [&](const ShoreGrid& g) { return texels_in(g.resolution, g.texel, g.corner, reach); };

    // The water stays where the seabed moved, on every grid: the shoreline keeps its contour.
    // Or the shoreline after the edit is given, on the model's own grid: where its
    // distances and normals moved, the rows are baked again.
    const ShoreGrid& model_grid = model.grid();
    const bool line_moves = shoreline_after != nullptr;
    if (line_moves && !(distance_grid == model_grid && ShoreGrid{shoreline_after->resolution, shoreline_after->texel,
                                                                 shoreline_after->corner} == distance_grid))
        return std::nullopt;
    const TexelRange distance_edit = edited(distance_grid);
    if (!distance_edit.empty() && !line_moves) {
        const auto [b, a] = depths(distance_grid);
        if (!stays_wet(distance_edit, distance_grid.resolution, b, a)) return std::nullopt;
    }
    const DistancesMoved line_moved =
        line_moves ? distances_moved(shoreline, *shoreline_after, threads) : DistancesMoved{};
    const TexelRange model_edit = edited(model_grid);
    const auto [model_before, model_after] = depths(model_grid);
    const ShoreField& line_after = line_moves ? *shoreline_after : shoreline;
    if (!model_edit.empty() &&
        ((!line_moves && !stays_wet(model_edit, model_grid.resolution, model_before, model_after)) ||
         !same_tile_kinds(model.shared(), model_edit, open_sea_test(waves, 0, waves.size()), breaking_index,
                          model_after, line_after)))
        return std::nullopt;
    // Where the distances moved, a tile of dry land stays one and no other becomes one;
    // where the normals moved under water, the waves' rows are baked again.
    auto reach_of = [&](const TexelRange& m) {
        return m.empty() ? WorldRect{} : edges(model_grid, m.i0, m.j0, m.i1 + 1, m.j1 + 1);
    };
    const WorldRect distance_reach = reach_of(line_moved.distance), normal_reach = reach_of(line_moved.normal);
    // A coarse grid's texels whose taps of the model's grid reach `m` (by `reach`).
    auto moved_on = [&](const ShoreGrid& g, const TexelRange& m, const WorldRect& r) {
        return m.empty() ? TexelRange{} : grown(texels_in(g.resolution, g.texel, g.corner, r), 1, g.resolution);
    };
    const OpenSeaTest no_test{};
    if (!line_moved.distance.empty() &&
        !same_tile_kinds(model.shared(), line_moved.distance, no_test, breaking_index, model_after, line_after, false))
        return std::nullopt;
    std::vector<RunEdit> runs;
    for (const ShoreWaveLayer& layer : model.layers()) {
        RunEdit r;
        r.layer = &layer;
        // With the march the stored amplitudes are the march's blended in, not the rays'.
        if (layer.grid == model_grid && !marches) r.uncapped_before = &model.shared();
        std::tie(r.before, r.after) = depths(layer.grid);
        r.edit = edited(layer.grid);
        if (!r.edit.empty() && ((!line_moves && !stays_wet(r.edit, layer.grid.resolution, r.before, r.after)) ||
                                !same_tile_kinds(layer.tiles, r.edit, open_sea_test(waves, layer.first, layer.count),
                                                 breaking_index, r.after, line_after)))
            return std::nullopt;
        r.normals_moved =
            layer.grid == model_grid ? line_moved.normal : moved_on(layer.grid, line_moved.normal, normal_reach);
        const TexelRange distances_moved_here =
            layer.grid == model_grid ? line_moved.distance : moved_on(layer.grid, line_moved.distance, distance_reach);
        if (!distances_moved_here.empty() &&
            !same_tile_kinds(layer.tiles, distances_moved_here, no_test, breaking_index, r.after, line_after, false))
            return std::nullopt;
        // Whether a wave has deep water (its sources where it has) stays as it was: a
        // layer with open sea has it for every wave; otherwise the stored residuals tell
        // outside the edit, the depths under it. Sources may come and go under the edit
        // (the phase is marched again there from the depths after), but a wave that gains
        // its first deep water or loses its last takes its sources from elsewhere.
        r.any_deep.assign(layer.count, 1);
        const bool has_open = std::find(layer.tiles.pages.begin(), layer.tiles.pages.end(), gpu::kShoreOpenSlot) !=
                              layer.tiles.pages.end();
        if (!has_open) {
            r.any_deep = deep_water_outside_edit(r, waves);
            for (std::size_t w = 0; w < layer.count; ++w) {
                if (r.any_deep[w]) continue;
                const Wave& wave = waves[layer.first + w];
                const bool had = deep_water_in_edit(r, wave, r.before), has = deep_water_in_edit(r, wave, r.after);
                if (had != has) return std::nullopt;
                r.any_deep[w] = has ? 1 : 0;
            }
        }
        runs.push_back(std::move(r));
    }
    if (distance_edit.empty() && model_edit.empty() && line_moved.distance.empty() && line_moved.normal.empty() &&
        std::all_of(runs.begin(), runs.end(), [](const RunEdit& r) { return r.edit.empty(); }))
        return WaterEdit{shoreline_ptr, model_ptr, marches};  // the change lies between texel centres

    // The distance field: the one given, or the same distances with the new depths under the edit.
    std::shared_ptr<const ShoreField> field = shoreline_after;
    if (!field) {
        auto kept = std::make_shared<ShoreField>(shoreline);
        if (!distance_edit.empty()) {
            std::vector<float>& depth = kept->depth.write();
            const GridDepth a{&after, water_level, distance_grid};
            each_texel(distance_edit, threads, [&](int i, int j) { depth[kept->index(i, j)] = a.at(i, j); });
        }
        field = std::move(kept);
    }

    // Each wave marched again round the edit, in a window.
    struct Job {
        std::size_t run, wave;
    };
    std::vector<Job> jobs;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        runs[r].march.resize(runs[r].layer->count);
        if (!runs[r].edit.empty())
            for (std::size_t w = 0; w < runs[r].layer->count; ++w) jobs.push_back({r, w});
    }
    parallel_for_each(jobs.size(), threads, [&](std::size_t k) {
        RunEdit& r = runs[jobs[k].run];
        const std::size_t w = jobs[k].wave;
        const Wave& wave = waves[r.layer->first + w];
        const int n = r.n();
        const glm::dvec2 dir{wave.dir_x, wave.dir_z};
        const double base = r.base(wave);
        MarchChange c;
        c.n = n;
        c.h = r.layer->grid.texel;
        c.slowness = [&](int i, int j) {
            const double h = static_cast<double>(r.after.at(i, j));
            return marched_wavenumber(wave.omega, h);
        };
        c.source = [&](int i, int j) {
            const double h = static_cast<double>(r.after.at(i, j));
            if (!(h > 0.0)) return kUnreached;
            return phase_source(r.any_deep[w] != 0, marched_deep_water(wave.omega, h), i, j, n, dir.x, dir.y)
                       ? wave.k * glm::dot(dir, r.centre(i, j)) - base
                       : kUnreached;
        };
        c.before = [&](int i, int j) { return r.phase_before(wave, w, i, j, r.before.at(i, j)); };
        c.changed = {r.edit.i0, r.edit.j0, r.edit.i1 + 1, r.edit.j1 + 1};
        c.tolerance = kOpenSeaPhaseTolerance;
        r.march[w] = remarch(c, 4);
    });

    // What each run bakes again: its windows and a texel round them (the wavevector's
    // differences). What the cap reads moves in part of them: round that part (the cap's
    // taps, a texel of the coarsest grid) and the edit every grid's rows are baked again.
    const GridNormals normals{*field, model_grid};
    WorldRect region = reach;
    if (!line_moved.normal.empty()) unite(region, normal_reach);
    double coarsest = model_grid.texel;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        RunEdit& r = runs[k];
        const ShoreGrid& g = r.layer->grid;
        coarsest = std::max(coarsest, g.texel);
        TexelRange& o = r.own;
        o = {g.resolution, g.resolution, -1, -1};
        for (const MarchWindow& m : r.march) {
            if (m.value.empty()) continue;
            const TexelWindow& win = m.window;
            o = {std::min(o.i0, win.i0 - 1), std::min(o.j0, win.j0 - 1), std::max(o.i1, win.i1),
                 std::max(o.j1, win.j1)};
        }
        if (o.empty()) continue;
        o = grown(o, 0, g.resolution);
        cover(r, o, normals, threads);
        r.fields = rows_before_cap(waves, r, grown(o, 2, g.resolution), threads);
        const TexelRange moved = cap_inputs_moved(waves, r, o, threads);
        if (!moved.empty()) unite(region, edges(g, moved.i0, moved.j0, moved.i1 + 1, moved.j1 + 1));
    }
    // With the march: each wave's taken up again.
    std::optional<MarchEdit> march_edit;
    bool march_only = false;
    auto grown_by_coarsest = [&](WorldRect r) {
        r.lo -= glm::dvec2(coarsest);
        r.hi += glm::dvec2(coarsest);
        return r;
    };
    auto march_only_run = [&](std::size_t l, const TexelRange& baked) {
        const RunEdit& r = runs[l];
        MarchOnlyRun run;
        run.waves = waves.subspan(r.layer->first, r.layer->count);
        run.spacing = marches->runs[l].spacing;
        run.changes = &march_edit->runs[l].changes;
        run.baked = baked;
        run.tiles = &r.layer->tiles;
        run.depth = [&r](int i, int j) { return r.after.at(i, j); };
        return run;
    };
    if (marches) {
        MarchEditInput input;
        input.edited = [&](std::size_t l) { return runs[l].edit; };
        input.depth_after = [&](std::size_t l, int i, int j) { return runs[l].after.at(i, j); };
        input.keep = [&](std::size_t l, std::size_t w, std::size_t k) {
            const RunEdit& r = runs[l];
            const auto n = static_cast<std::size_t>(r.n());
            const int i = static_cast<int>(k % n), j = static_cast<int>(k / n);
            const float h = r.edit.contains(i, j) ? r.after.at(i, j) : marches->runs[l].field->depth[k];
            if (!(h > 0.0f)) return true;
            // Deep water first: it is told from the depth alone, where whether the wave
            // reached the texel reads the texel's stored rows.
            if (r.any_deep[w] != 0 && marched_deep_water(waves[r.layer->first + w].omega, static_cast<double>(h)))
                return true;
            const MarchWindow& m = r.march[w];
            const bool reached =
                !m.value.empty() && m.window.contains(i, j) ? std::isfinite(m.at(i, j)) : r.reached_before(w, i, j, h);
            return !reached;
        };
        input.stored_at = [&](std::size_t l, int i, int j) { return runs[l].layer->tiles.stored_texel(i, j); };
        march_edit = remarch_marches(*marches, waves, reach, input, shoreline_ptr, field, threads);
        // Where only a march moved, its blend and energy and the foam are made again there
        // alone when the model's values allow it; else the rows are baked again there too.
        march_only = marches->ratios.slots() == model.shared().stored_tiles();
        for (std::size_t l = 0; l < runs.size() && march_only; ++l) {
            const ShoreGrid& g = runs[l].layer->grid;
            march_only =
                blends_alone(march_only_run(l, texels_in(g.resolution, g.texel, g.corner, grown_by_coarsest(region))),
                             marches->runs[l].marched);
        }
        if (!march_only)
            for (std::size_t l = 0; l < runs.size(); ++l) {
                const TexelRange& moved = march_edit->runs[l].moved;
                if (!moved.empty())
                    unite(region, edges(runs[l].layer->grid, moved.i0, moved.j0, moved.i1 + 1, moved.j1 + 1));
            }
    }
    region = grown_by_coarsest(region);
    for (RunEdit& r : runs) {
        const ShoreGrid& g = r.layer->grid;
        r.capped = texels_in(g.resolution, g.texel, g.corner, region);
        TexelRange rows = r.own;
        if (rows.empty())
            rows = r.capped;
        else if (!r.capped.empty())
            rows = {std::min(rows.i0, r.capped.i0), std::min(rows.j0, r.capped.j0), std::max(rows.i1, r.capped.i1),
                    std::max(rows.j1, r.capped.j1)};
        if (!rows.empty() &&
            !(rows.i0 == r.own.i0 && rows.j0 == r.own.j0 && rows.i1 == r.own.i1 && rows.j1 == r.own.j1)) {
            cover(r, rows, normals, threads);
            const Patch<float> known = std::move(r.fields);
            r.fields = rows_before_cap(waves, r, grown(rows, 2, g.resolution), threads, &known);
        }
        write_before_cap(r, r.capped.empty() ? r.capped : grown(r.capped, 2, g.resolution), threads);
    }
    std::vector<RunTilesView> before_cap;
    for (const RunEdit& r : runs) before_cap.push_back({r.layer->first, r.layer->count, &r.layer->grid, &r.before_cap});

    // The cap over the model's grid where what it reads moved: for the shared rows and the
    // runs on that grid.
    const TexelRange shared_rows = texels_in(model_grid.resolution, model_grid.texel, model_grid.corner, region);
    Patch<float> model_depth;
    Patch<double> model_ratio;
    model_depth.assign(shared_rows, 1, 0.0f);
    model_ratio.assign(shared_rows, 1, 0.0);
    const auto on_model =
        std::find_if(runs.begin(), runs.end(), [&](const RunEdit& r) { return r.layer->grid == model_grid; });
    const auto& model_depths_after = model_after;  // Clang 14 does not capture a structured binding
    each_texel(shared_rows, threads, [&](int i, int j) {
        const float h = on_model != runs.end() ? *on_model->depth_after(i, j) : model_depths_after.at(i, j);
        *model_depth(i, j) = h;
        if (h > 0.0f)
            *model_ratio(i, j) = cap_ratio(waves, before_cap, model_grid, i, j, static_cast<double>(h), breaking_index);
    });

    // Each run's phase where it was re-marched; where the cap reads moved, its rows capped
    // anew; and carried onto land on the coarse grids.
    std::vector<ShoreTiles> run_tiles;
    std::vector<RunMarches> runs_marched;  // with the march: each run's records after the edit
    runs_marched.reserve(runs.size());
    for (std::size_t l = 0; l < runs.size(); ++l) {
        RunEdit& r = runs[l];
        const ShoreGrid& g = r.layer->grid;
        const std::size_t nw = r.layer->count;
        RunMarches* marched = nullptr;
        if (march_edit) {
            const RunMarches& before_edit = marches->runs[l];
            runs_marched.push_back({march_edit->runs[l].field, before_edit.marched, before_edit.energy,
                                    march_edit->runs[l].kept, before_edit.spacing});
            marched = &runs_marched.back();
        }
        Patch<float> ratio;
        ratio.assign(r.capped, 1, 1.0f);
        each_texel(r.capped, threads, [&](int i, int j) {
            const double h = static_cast<double>(*r.depth_after(i, j));
            if (h <= 0.0) return;
            *ratio(i, j) = static_cast<float>(
                g == model_grid ? *model_ratio(i, j) : cap_ratio(waves, before_cap, g, i, j, h, breaking_index));
        });
        r.out = r.layer->tiles;
        r.out.write_texels(
            r.rows.i0, r.rows.j0, r.rows.i1 + 1, r.rows.j1 + 1,
            [&](float* t, int i, int j, std::uint32_t page, std::size_t s) {
                const float* f = r.fields(i, j);
                const double h = static_cast<double>(*r.depth_after(i, j));
                if (r.capped.contains(i, j)) {
                    const double capped = static_cast<double>(*ratio(i, j));
                    const std::size_t at = (page - gpu::kShoreFirstStoredSlot) * ShoreTiles::kSlotTexels + s;
                    for (std::size_t w = 0; w < nw; ++w) {
                        t[w] = f[w];
                        t[nw + w] = capped_amplitude(f[nw + w], h, capped);
                        t[2 * nw + w] = f[2 * nw + w];
                        t[3 * nw + w] = f[3 * nw + w];
                        // The march's amplitude blended in after the cap, as the bake does.
                        if (marched)
                            t[nw + w] = marched_amplitude(waves[r.layer->first + w], marched->spacing[w],
                                                          march_edit->runs[l].changes, marched->marched, at, w, i, j,
                                                          t[nw + w], t[2 * nw + w], t[3 * nw + w], h);
                    }
                } else if (r.own.contains(i, j)) {
                    // What the cap reads stays within kCapReadTolerance here: the phase alone
                    // moves. On land a coarse run's values are carried again below.
                    for (std::size_t w = 0; w < nw; ++w) {
                        t[w] = f[w];
                        if (h <= 0.0) t[2 * nw + w] = t[3 * nw + w] = 0.0f;
                    }
                }
            },
            threads);
        if (g.texel != model_grid.texel) carry_onto_land(waves, r, threads);
        // The march's energy where the rows were baked again, from the records as they now are.
        if (marched)
            for (int j = r.capped.j0; j <= r.capped.j1; ++j)
                for (int i = r.capped.i0; i <= r.capped.i1; ++i) {
                    const std::optional<std::size_t> at = r.out.stored_texel(i, j);
                    if (!at) continue;
                    const auto [energy, breaking] = marched_energy(waves.subspan(r.layer->first, nw), marched->marched,
                                                                   *at, r.out.texel(i, j), marched->energy.quantum());
                    marched->energy.assign(i, j, energy, breaking);
                }
        if (march_only) blend_again(march_only_run(l, r.capped), r.out, marched->marched, marched->energy, threads);
        run_tiles.push_back(std::move(r.out));
    }
    std::vector<EnergyView> energies;
    for (std::size_t l = 0; l < runs_marched.size(); ++l)
        energies.push_back({&runs[l].layer->grid, &runs_marched[l].energy});
    std::shared_ptr<ShoreMarches> marches_after;
    if (march_edit) {
        marches_after = std::make_shared<ShoreMarches>();
        ShoreMarches& m = *marches_after;
        m.sea = marches->sea;
        m.runs = std::move(runs_marched);
        m.sea_march = std::move(march_edit->sea_march);
        if (m.sea_march) m.sea_march->height.field = m.runs[m.sea_march->run].field;
        m.ratios = marches->ratios;
    }

    // The shared rows: the depth, and the breaking and steepness of the waves together.
    ShoreTiles shared = model.shared();
    Patch<float> shared_values;
    shared_values.assign(shared_rows, kShoreSharedRows, 0.0f);
    each_texel(shared_rows, threads, [&](int i, int j) {
        // The distance as the bake's grid holds it (a texel of a tile's apron may lie in a
        // tile of dry land, whose stored values are not its own).
        const auto n = static_cast<std::size_t>(model_grid.resolution);
        const float distance =
            held_distance(*field, model_depths_after, static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i), i,
                          j, *model_depth(i, j));
        shared_texel_rows(
            waves, before_cap, model_grid, i, j, *model_depth(i, j), distance, *model_ratio(i, j), shared_values(i, j),
            energies.empty() ? DiffractedEnergy{}
                             : marched_energy_at(energies, model_grid, i, j,
                                                 model_grid.corner + model_grid.texel * glm::dvec2(i + 0.5, j + 0.5)));
    });
    CapRatios* ratios =
        marches_after && marches_after->ratios.slots() == shared.stored_tiles() ? &marches_after->ratios : nullptr;
    shared.write_texels(
        shared_rows.i0, shared_rows.j0, shared_rows.i1 + 1, shared_rows.j1 + 1,
        [&](float* t, int i, int j, std::uint32_t page, std::size_t k) {
            std::copy_n(shared_values(i, j), kShoreSharedRows, t);
            if (ratios)
                ratios->set((page - gpu::kShoreFirstStoredSlot) * ShoreTiles::kSlotTexels + k,
                            static_cast<float>(*model_ratio(i, j)));
        },
        threads);
    // Where only the distance moved (on land, or where no wave reads the normal): the
    // shared layer's distance alone.
    if (!line_moved.distance.empty()) {
        const TexelRange& d = line_moved.distance;
        shared.write_texels(
            d.i0, d.j0, d.i1 + 1, d.j1 + 1,
            [&](float* t, int i, int j) { t[3] = field->signed_distance[field->index(i, j)]; }, threads);
    }
    if (march_only) {
        std::vector<std::pair<const ShoreGrid*, const RunMarchChanges*>> changed;
        for (std::size_t l = 0; l < runs.size(); ++l)
            changed.push_back({&runs[l].layer->grid, &march_edit->runs[l].changes});
        foam_again(model_grid, shared, marches_after->ratios, energies, changed, shared_rows, breaking_index, threads);
    }

    return WaterEdit{std::move(field), model.with_tiles(std::move(shared), std::move(run_tiles)),
                     std::move(marches_after)};
}

}  // namespace tidewater::detail
