#include "shore/shore_march_edit.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <limits>

#include "shore/shore_diffraction.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {

void RunMarchChanges::assign(const TexelRange& range, std::size_t waves) {
    range_ = range;
    waves_ = waves;
    const std::size_t count =
        range.empty() ? 0 : static_cast<std::size_t>(range.width()) * static_cast<std::size_t>(range.height()) * waves;
    amplitude_.assign(count, std::numeric_limits<float>::quiet_NaN());
    flags_.assign(count, 0);
}

std::size_t RunMarchChanges::at(int i, int j, std::size_t w) const {
    return (static_cast<std::size_t>(j - range_.j0) * static_cast<std::size_t>(range_.width()) +
            static_cast<std::size_t>(i - range_.i0)) *
               waves_ +
           w;
}

void RunMarchChanges::set(int i, int j, std::size_t w, float amplitude, bool reached, bool broken) {
    const std::size_t k = at(i, j, w);
    amplitude_[k] = amplitude;
    flags_[k] = static_cast<std::uint8_t>((reached ? kReached : 0) | (broken ? kBroken : 0));
}

namespace {

/// The random sea's height is taken to this (over its open-sea height), far finer than a
/// component's amplitude: in the surf zone Battjes and Janssen's share of broken waves,
/// which every component dissipates by, is steep in the sea's height.
constexpr double kSeaHeightTolerance = 1e-5;

/// A run's grid with the edit's depths: the shoreline's field after the edit where the
/// run lies on its grid (it holds the same depths), else a copy whose edited texels are
/// put in (its other values shared).
std::shared_ptr<const ShoreField> field_after(const std::shared_ptr<const ShoreField>& before,
                                              const std::shared_ptr<const ShoreField>& shoreline_before,
                                              const std::shared_ptr<const ShoreField>& shoreline_after,
                                              const PatchedDepths& patched) {
    if (before == shoreline_before) return shoreline_after;
    if (patched.width <= 0 || patched.height <= 0) return before;
    auto field = std::make_shared<ShoreField>(*before);
    std::vector<float>& depth = field->depth.write();
    for (int b = 0; b < patched.height; ++b)
        for (int a = 0; a < patched.width; ++a)
            depth[field->index(patched.i0 + a, patched.j0 + b)] =
                patched.depth[static_cast<std::size_t>(b) * static_cast<std::size_t>(patched.width) +
                              static_cast<std::size_t>(a)];
    return field;
}

/// The edited texels of a run's grid and their depths after the edit.
PatchedDepths patched_depths(const ShoreField& field, const TexelRange& edit, std::size_t run,
                             const MarchEditInput& input) {
    PatchedDepths p;
    p.field = &field;
    if (edit.empty()) return p;
    p.i0 = edit.i0;
    p.j0 = edit.j0;
    p.width = edit.width();
    p.height = edit.height();
    p.depth.resize(static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height));
    for (int j = edit.j0; j <= edit.j1; ++j)
        for (int i = edit.i0; i <= edit.i1; ++i)
            p.depth[static_cast<std::size_t>(j - edit.j0) * static_cast<std::size_t>(p.width) +
                    static_cast<std::size_t>(i - edit.i0)] = input.depth_after(run, i, j);
    return p;
}

/// How the random sea's march is taken up again: to kSeaHeightTolerance, its kept
/// march updated in `updated`, its height before the edit what the first march left.
Remarch sea_remarch(const SeaMarch& sm, KeptMarch* updated) {
    Remarch how;
    how.tolerance = kSeaHeightTolerance;
    how.updated = updated;
    how.marched_before = [&sm](std::size_t k) {
        const float height = sm.height.height[k];
        return MarchedTexel{
            height > 0.0f ? static_cast<float>(static_cast<double>(height) / (2.0 * sm.whole.amplitude)) : 0.0f,
            height > 0.0f, std::nullopt};
    };
    return how;
}

}  // namespace

MarchEdit remarch_marches(const ShoreMarches& marches, std::span<const Wave> waves, const WorldRect& reach,
                          const MarchEditInput& input, const std::shared_ptr<const ShoreField>& shoreline_before,
                          const std::shared_ptr<const ShoreField>& shoreline_after, unsigned threads) {
    MarchEdit out;
    const std::size_t run_count = marches.runs.size();
    std::vector<PatchedDepths> patched(run_count);
    std::vector<TexelRange> edits(run_count);
    out.runs.resize(run_count);
    for (std::size_t r = 0; r < run_count; ++r) {
        edits[r] = input.edited(r);
        patched[r] = patched_depths(*marches.runs[r].field, edits[r], r, input);
    }

    // The random sea first: every component breaks at its height.
    WorldRect component_reach = reach;
    bool sea_moved = false;
    const SeaHeight* sea_before = nullptr;
    const SeaHeight* sea_after = nullptr;
    if (marches.sea_march) {
        const SeaMarch& sm = *marches.sea_march;
        SeaMarch after = sm;
        const ShoreField& field = *marches.runs[sm.run].field;
        const PatchedDepths& depths = patched[sm.run];
        if (!edits[sm.run].empty() && sm.kept) {
            auto kept = std::make_shared<KeptMarch>(*sm.kept);
            const DiffractionChange change = rediffract_wave(
                sm.whole, marches.sea, field, depths, *sm.kept, reach,
                [&](std::size_t k) {
                    const auto n = static_cast<std::size_t>(field.resolution);
                    return sea_leaves(sm.whole,
                                      static_cast<double>(depths.at(static_cast<int>(k % n), static_cast<int>(k / n))));
                },
                sea_remarch(sm, kept.get()));
            // Every component breaks at the sea's height: where that moved, its march may
            // move too, however far from the stroke across its own direction.
            const auto n = static_cast<std::size_t>(field.resolution);
            for (const std::uint32_t k : change.texels) {
                const glm::dvec2 p = field.texel_center(static_cast<int>(k % n), static_cast<int>(k / n));
                component_reach.lo = glm::min(component_reach.lo, p - field.texel);
                component_reach.hi = glm::max(component_reach.hi, p + field.texel);
            }
            for (std::size_t c = 0; c < change.texels.size(); ++c)
                after.height.set(change.texels[c], change.share[c] > 0
                                                       ? static_cast<float>(2.0 * sm.whole.amplitude *
                                                                            static_cast<double>(change.amplitude[c]))
                                                       : 0.0f);
            after.kept = std::move(kept);
            sea_moved = !change.texels.empty();
        }
        out.sea_march = std::move(after);
        sea_before = &sm.height;
        sea_after = &out.sea_march->height;
    }

    // Then every wave of every run whose grid the edit reaches.
    struct Job {
        std::size_t run, wave;
    };
    std::vector<Job> jobs;
    for (std::size_t r = 0; r < run_count; ++r) {
        const RunMarches& run = marches.runs[r];
        out.runs[r].kept = run.kept;
        // A grid whose texel centres the stroke missed keeps its depths, but its waves
        // still break at the sea's height wherever that moved.
        if (edits[r].empty() && !sea_moved) continue;
        for (std::size_t w = 0; w < run.kept.size(); ++w)
            if (run.kept[w]) jobs.push_back({r, w});
    }
    std::vector<DiffractionChange> changes(jobs.size());
    std::vector<std::shared_ptr<const KeptMarch>> kept_after(jobs.size());
    std::size_t first_wave_of_run = 0;
    std::vector<std::size_t> first_wave(run_count);
    for (std::size_t r = 0; r < run_count; ++r) {
        first_wave[r] = first_wave_of_run;
        first_wave_of_run += marches.runs[r].kept.size();
    }
    parallel_for_each(jobs.size(), threads, [&](std::size_t j) {
        const std::size_t r = jobs[j].run, w = jobs[j].wave;
        const RunMarches& run = marches.runs[r];
        auto kept = std::make_shared<KeptMarch>(*run.kept[w]);
        Remarch how;
        how.sea_before = sea_before;
        how.sea_after = sea_after;
        how.updated = kept.get();
        // A component of a random sea breaks and shoals at the sea's height.
        how.settles = sea_after != nullptr;
        // What the first march left, where the model stores it.
        how.marched_before = [&](std::size_t k) -> std::optional<MarchedTexel> {
            const auto n = static_cast<std::size_t>(run.field->resolution);
            const std::optional<std::size_t> at = input.stored_at(r, static_cast<int>(k % n), static_cast<int>(k / n));
            if (!at) return std::nullopt;
            const float held = run.marched.amplitude(*at, w);
            return MarchedTexel{held, run.marched.reached(*at, w), run.marched.broken(*at, w),
                                MarchedAmplitudes::rounding(held)};
        };
        changes[j] = rediffract_wave(
            waves[first_wave[r] + w], marches.sea, *run.field, patched[r], *run.kept[w], component_reach,
            [&](std::size_t k) { return input.keep(r, w, k); }, how);
        kept_after[j] = std::move(kept);
    });

    // Per run: the texels its waves' marches moved at, and what they give there now.
    for (std::size_t r = 0; r < run_count; ++r) {
        RunMarchEdit& e = out.runs[r];
        e.field = field_after(marches.runs[r].field, shoreline_before, shoreline_after, patched[r]);
        const auto n = static_cast<std::size_t>(marches.runs[r].field->resolution);
        TexelRange moved{static_cast<int>(n), static_cast<int>(n), -1, -1};
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            if (jobs[j].run != r) continue;
            e.kept[jobs[j].wave] = kept_after[j];
            for (const std::uint32_t k : changes[j].texels) {
                const int i = static_cast<int>(k % n), jj = static_cast<int>(k / n);
                moved = {std::min(moved.i0, i), std::min(moved.j0, jj), std::max(moved.i1, i), std::max(moved.j1, jj)};
            }
        }
        e.moved = moved.empty() ? TexelRange{0, 0, -1, -1} : moved;
        e.changes.assign(e.moved, marches.runs[r].kept.size());
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            if (jobs[j].run != r) continue;
            const DiffractionChange& c = changes[j];
            for (std::size_t t = 0; t < c.texels.size(); ++t)
                e.changes.set(static_cast<int>(c.texels[t] % n), static_cast<int>(c.texels[t] / n), jobs[j].wave,
                              c.amplitude[t], c.share[t] > 0, c.broken[t] != 0);
        }
    }
    return out;
}

float marched_amplitude(const Wave& wave, double spacing, const RunMarchChanges& changes, MarchedAmplitudes& record,
                        std::size_t at, std::size_t w, int i, int j, float rays, float kx, float kz, double h) {
    const std::optional<MarchedTexel> moved = changes.find(i, j, w);
    const float amplitude = moved ? moved->amplitude : record.amplitude(at, w);
    const bool reached = moved ? moved->reached : record.reached(at, w);
    const bool broken = moved ? moved->broken.value_or(false) : record.broken(at, w);
    const std::uint8_t share =
        reached && (kx != 0.0f || kz != 0.0f) ? held_share(wave, kx, kz, spacing) : std::uint8_t{0};
    if (moved || share != record.share(at, w)) record.set(at, w, share, amplitude, reached, broken);
    return march_blend(share, record.amplitude(at, w), rays, h);
}

std::optional<Reblended> reblended_amplitude(const Wave& wave, double spacing, const MarchedAmplitudes& record,
                                             std::size_t at, std::size_t w, const MarchedTexel& march, float stored,
                                             float kx, float kz, double h) {
    Reblended out;
    out.share = march.reached && (kx != 0.0f || kz != 0.0f) ? held_share(wave, kx, kz, spacing) : std::uint8_t{0};
    const float held = MarchedAmplitudes::held(march.amplitude);
    const std::optional<float> rays = rays_under_blend(record.share(at, w), record.amplitude(at, w), stored, h);
    if (rays)
        out.amplitude = march_blend(out.share, held, *rays, h);
    else if (out.share == 255)  // held whole before and after: no rays' part in either
        out.amplitude = march_blend(out.share, held, 0.0f, h);
    else
        return std::nullopt;
    return out;
}

namespace {

/// Texels of a grid marked within a range.
struct TexelMarks {
    TexelRange range{0, 0, -1, -1};
    std::vector<char> marks;
    void assign(const TexelRange& r) {
        range = r;
        marks.assign(r.empty() ? 0 : static_cast<std::size_t>(r.width()) * static_cast<std::size_t>(r.height()), 0);
    }
    std::size_t at(int i, int j) const {
        return static_cast<std::size_t>(j - range.j0) * static_cast<std::size_t>(range.width()) +
               static_cast<std::size_t>(i - range.i0);
    }
    void mark(int i, int j) { marks[at(i, j)] = 1; }
    bool marked(int i, int j) const { return !range.empty() && range.contains(i, j) && marks[at(i, j)] != 0; }
};

/// The stored tiles of `tiles` whose slots (aprons included) hold a marked texel.
std::vector<std::size_t> tiles_holding(const ShoreTiles& tiles, const TexelMarks& marks) {
    const int m = tiles.tiles_per_side, kTile = ShoreTiles::kTile;
    std::vector<char> flagged(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), 0);
    auto flag = [&](int ti, int tj) {
        if (ti >= 0 && tj >= 0)
            flagged[static_cast<std::size_t>(tj) * static_cast<std::size_t>(m) + static_cast<std::size_t>(ti)] = 1;
    };
    const TexelRange& r = marks.range;
    for (int j = r.j0; j <= r.j1; ++j)
        for (int i = r.i0; i <= r.i1; ++i) {
            if (!marks.marked(i, j)) continue;
            // Its own tile's slot, and the aprons of the tiles before it.
            const int ti = i / kTile, tj = j / kTile;
            const bool first_i = i % kTile == 0, first_j = j % kTile == 0;
            flag(ti, tj);
            if (first_i) flag(ti - 1, tj);
            if (first_j) flag(ti, tj - 1);
            if (first_i && first_j) flag(ti - 1, tj - 1);
        }
    std::vector<std::size_t> out;
    for (std::size_t t = 0; t < flagged.size(); ++t)
        if (flagged[t] && tiles.pages[t] >= gpu::kShoreFirstStoredSlot) out.push_back(t);
    return out;
}

/// Calls visit(texel's floats, i, j, at) for every texel of the slots of `tile_list` whose
/// grid texel is marked (aprons included; `at` its record index), each slot made writable
/// first and written by one worker.
template <typename Visit>
void write_marked(ShoreTiles& tiles, const std::vector<std::size_t>& tile_list, const TexelMarks& marks,
                  const Visit& visit, unsigned threads) {
    const auto n = static_cast<std::size_t>(tiles.resolution);
    parallel_for_each(tile_list.size(), threads, [&](std::size_t t) {
        const std::size_t tile = tile_list[t];
        const std::uint32_t page = tiles.pages[tile];
        float* slot = tiles.slot_for_writing(page);
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const std::size_t g = tiles.grid_index(tile, k);
            const int i = static_cast<int>(g % n), j = static_cast<int>(g / n);
            if (!marks.marked(i, j)) continue;
            visit(slot + k * tiles.stride, i, j, (page - gpu::kShoreFirstStoredSlot) * ShoreTiles::kSlotTexels + k);
        }
    });
}

/// The texels of `run` where its marches moved outside its baked texels.
TexelMarks moved_outside(const MarchOnlyRun& run) {
    TexelMarks marks;
    marks.assign(run.changes->range());
    run.changes->each([&](int i, int j, std::size_t, const MarchedTexel&) {
        if (!run.baked.contains(i, j)) marks.mark(i, j);
    });
    return marks;
}

}  // namespace

bool blends_alone(const MarchOnlyRun& run, const MarchedAmplitudes& record) {
    const std::size_t nw = run.waves.size();
    bool alone = true;
    run.changes->each([&](int i, int j, std::size_t w, const MarchedTexel& march) {
        if (!alone || run.baked.contains(i, j)) return;
        const std::optional<std::size_t> at = run.tiles->stored_texel(i, j);
        if (!at) return;
        const float* t = run.tiles->texel(i, j);
        alone = reblended_amplitude(run.waves[w], run.spacing[w], record, *at, w, march, t[nw + w], t[2 * nw + w],
                                    t[3 * nw + w], static_cast<double>(run.depth(i, j)))
                    .has_value();
    });
    return alone;
}

void blend_again(const MarchOnlyRun& run, ShoreTiles& out, MarchedAmplitudes& record, MarchedEnergy& energy,
                 unsigned threads) {
    const std::size_t nw = run.waves.size();
    const TexelMarks marks = moved_outside(run);
    write_marked(
        out, tiles_holding(out, marks), marks,
        [&](float* t, int i, int j, std::size_t at) {
            const double h = static_cast<double>(run.depth(i, j));
            for (std::size_t w = 0; w < nw; ++w) {
                const std::optional<MarchedTexel> march = run.changes->find(i, j, w);
                if (!march) continue;
                const std::optional<Reblended> b = reblended_amplitude(
                    run.waves[w], run.spacing[w], record, at, w, *march, t[nw + w], t[2 * nw + w], t[3 * nw + w], h);
                if (!b) continue;  // blends_alone said none is so
                t[nw + w] = b->amplitude;
                record.set(at, w, b->share, march->amplitude, march->reached, march->broken.value_or(false));
            }
        },
        threads);
    // The energy from the records as they now are.
    const TexelRange& r = marks.range;
    for (int j = r.j0; j <= r.j1; ++j)
        for (int i = r.i0; i <= r.i1; ++i) {
            if (!marks.marked(i, j)) continue;
            const std::optional<std::size_t> at = out.stored_texel(i, j);
            if (!at) continue;
            const auto [e, b] = marched_energy(run.waves, record, *at, out.texel(i, j), energy.quantum());
            energy.assign(i, j, e, b);
        }
}

void foam_again(const ShoreGrid& model, ShoreTiles& shared, const CapRatios& ratios,
                std::span<const EnergyView> energies,
                std::span<const std::pair<const ShoreGrid*, const RunMarchChanges*>> changed, const TexelRange& baked,
                double breaking_index, unsigned threads) {
    // The model's texels whose bilinear taps on each run's grid hold a texel it moved at.
    TexelRange all{model.resolution, model.resolution, -1, -1};
    auto footprint = [&](const ShoreGrid& g, int i, int j) {
        const WorldRect box{g.corner + g.texel * glm::dvec2(i - 0.5, j - 0.5) - model.texel,
                            g.corner + g.texel * glm::dvec2(i + 1.5, j + 1.5) + model.texel};
        return texels_in(model.resolution, model.texel, model.corner, box);
    };
    for (const auto& [g, c] : changed) {
        const TexelRange& r = c->range();
        if (r.empty()) continue;
        const TexelRange lo = footprint(*g, r.i0, r.j0), hi = footprint(*g, r.i1, r.j1);
        all = {std::min(all.i0, lo.i0), std::min(all.j0, lo.j0), std::max(all.i1, hi.i1), std::max(all.j1, hi.j1)};
    }
    if (all.empty()) return;
    TexelMarks marks;
    marks.assign(all);
    for (const auto& run : changed) {
        const ShoreGrid& g = *run.first;
        int last_i = -1, last_j = -1;
        run.second->each([&](int i, int j, std::size_t, const MarchedTexel&) {
            if (i == last_i && j == last_j) return;  // its waves follow each other
            last_i = i;
            last_j = j;
            const TexelRange f = footprint(g, i, j);
            for (int b = f.j0; b <= f.j1; ++b)
                for (int a = f.i0; a <= f.i1; ++a)
                    if (!baked.contains(a, b)) marks.mark(a, b);
        });
    }
    write_marked(
        shared, tiles_holding(shared, marks), marks,
        [&](float* t, int i, int j, std::size_t at) {
            const double h = static_cast<double>(t[0]);
            if (!(h > 0.0)) return;
            const double ratio = static_cast<double>(ratios.at(at));
            t[1] = shared_foam(
                ratio, cap_energy(ratio, h, breaking_index),
                marched_energy_at(energies, model, i, j, model.corner + model.texel * glm::dvec2(i + 0.5, j + 0.5)));
        },
        threads);
}

std::pair<std::uint32_t, std::uint32_t> marched_energy(std::span<const Wave> waves, const MarchedAmplitudes& record,
                                                       std::size_t at, const float* texel, double quantum) {
    const std::size_t nw = waves.size();
    std::uint32_t energy = 0, breaking = 0;
    for (std::size_t w = 0; w < nw; ++w) {
        if (!record.reached(at, w)) continue;
        const bool rays = carries_wave(texel, nw, w);
        const double share = rays ? static_cast<double>(record.share(at, w)) / 255.0 : 1.0;
        if (share == 0.0) continue;
        const std::uint32_t e =
            energy_quanta(waves[w].amplitude * static_cast<double>(record.amplitude(at, w)), share, quantum);
        MarchedEnergy::saturating_add(energy, e);
        if (record.broken(at, w)) MarchedEnergy::saturating_add(breaking, e);
    }
    return {energy, breaking};
}

}  // namespace tidewater::detail
