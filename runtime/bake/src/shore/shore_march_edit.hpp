// A stroke on the seabed under waves baked with the parabolic march: each wave's march
// (the random sea's first, whose height every component breaks at) taken up again round
// the stroke and downstream of it from what the bake kept (shore_marches.hpp), and the
// march's part of each wave's amplitude and of the foam put back where it moved. The
// rays' part is shore_water_edit.cpp's, which calls these. Private to the bake.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "shore/shore_edit_region.hpp"
#include "shore/shore_marches.hpp"

namespace tidewater::detail {

/// Per texel of a run's grid and wave of the run, what its march gives after the edit
/// where that moved: the amplitude factor, whether it reaches the texel and whether the
/// wave is broken there.
class RunMarchChanges {
  public:
    void assign(const TexelRange& range, std::size_t waves);
    void set(int i, int j, std::size_t w, float amplitude, bool reached, bool broken);
    /// What the march gives now at (i, j) for wave w; none where it did not move.
    std::optional<MarchedTexel> find(int i, int j, std::size_t w) const {
        if (range_.empty() || !range_.contains(i, j)) return std::nullopt;
        return held(at(i, j, w));
    }
    const TexelRange& range() const { return range_; }
    /// Calls each(i, j, w, what the march gives now) where the march moved.
    template <typename Each>
    void each(const Each& each) const {
        for (int j = range_.j0; j <= range_.j1; ++j)
            for (int i = range_.i0; i <= range_.i1; ++i)
                for (std::size_t w = 0; w < waves_; ++w)
                    if (const std::optional<MarchedTexel> t = held(at(i, j, w))) each(i, j, w, *t);
    }

  private:
    static constexpr std::uint8_t kReached = 1, kBroken = 2;
    std::size_t at(int i, int j, std::size_t w) const;
    /// Entry k; none where it was not set (NaN).
    std::optional<MarchedTexel> held(std::size_t k) const {
        if (std::isnan(amplitude_[k])) return std::nullopt;
        return MarchedTexel{amplitude_[k], (flags_[k] & kReached) != 0, (flags_[k] & kBroken) != 0};
    }
    TexelRange range_{0, 0, -1, -1};
    std::size_t waves_ = 0;
    std::vector<float> amplitude_;
    std::vector<std::uint8_t> flags_;
};

/// One run's marches after the edit.
struct RunMarchEdit {
    std::shared_ptr<const ShoreField> field;  ///< its grid, the depths after the edit
    std::vector<std::shared_ptr<const KeptMarch>> kept;
    RunMarchChanges changes;
    TexelRange moved{0, 0, -1, -1};  ///< the texels some wave's march moved at (empty: none)
};

struct MarchEdit {
    std::vector<RunMarchEdit> runs;
    std::optional<SeaMarch> sea_march;
};

/// What the edit's run needs told: per run, the texels whose depth may have changed and
/// their depth after it; per run, wave and grid texel, whether the march leaves the
/// texel to the open sea (as the bake's `keep`), over the rays after the edit; per run
/// and grid texel, its place in the run's record (MarchedAmplitudes; none where its tile
/// is not stored).
struct MarchEditInput {
    std::function<TexelRange(std::size_t run)> edited;
    std::function<float(std::size_t run, int i, int j)> depth_after;
    std::function<bool(std::size_t run, std::size_t wave, std::size_t k)> keep;
    std::function<std::optional<std::size_t>(std::size_t run, int i, int j)> stored_at;
};

/// Every wave's march of `marches` (baked for `waves`) taken up again after an edit
/// within `reach`; `threads` workers. `shoreline_after` is the shoreline's field after
/// the edit: a run on its grid takes its depths from it.
MarchEdit remarch_marches(const ShoreMarches& marches, std::span<const Wave> waves, const WorldRect& reach,
                          const MarchEditInput& input, const std::shared_ptr<const ShoreField>& shoreline_before,
                          const std::shared_ptr<const ShoreField>& shoreline_after, unsigned threads);

/// Wave `w` of a run (its `spacing`) at stored texel `at`, grid texel (i, j) of depth h,
/// after the edit: the rays' capped amplitude `rays` blended with the march's as the
/// bake's cap does, the march's share by the angle of the rays' wavevector (kx, kz)
/// there; `record` updated where that moved.
float marched_amplitude(const Wave& wave, double spacing, const RunMarchChanges& changes, MarchedAmplitudes& record,
                        std::size_t at, std::size_t w, int i, int j, float rays, float kx, float kz, double h);

/// Wave `w` of a run at stored texel `at`, depth h, where only its march moved, to
/// `march` (the rays and the cap as they were: the rays' wavevector (kx, kz) there):
/// `stored` is the amplitude the model holds, the march's as `record` holds it blended
/// in. The amplitude with `march` blended in instead, and the march's share now. None
/// where the rays' part cannot be told from `stored` (the march held the amplitude whole
/// and no longer does): the texel must be baked again from the rays.
struct Reblended {
    float amplitude = 0.0f;
    std::uint8_t share = 0;
};
std::optional<Reblended> reblended_amplitude(const Wave& wave, double spacing, const MarchedAmplitudes& record,
                                             std::size_t at, std::size_t w, const MarchedTexel& march, float stored,
                                             float kx, float kz, double h);

/// One run of waves where its marches moved outside `baked`, the texels baked again from
/// the rays (the cap's region): there the rays and the cap are as they were, and only
/// the march's blend and energy are made again (blend_again).
struct MarchOnlyRun {
    std::span<const Wave> waves;      ///< the run's
    std::span<const double> spacing;  ///< per wave, its march's
    const RunMarchChanges* changes = nullptr;
    TexelRange baked;
    const ShoreTiles* tiles = nullptr;         ///< the run's tiles before the edit
    std::function<float(int i, int j)> depth;  ///< texel (i, j)'s depth (m)
};

/// Whether every texel where `run`'s marches moved outside its baked texels can be
/// blended again from what the model holds (reblended_amplitude); `record` is the run's
/// before the edit.
bool blends_alone(const MarchOnlyRun& run, const MarchedAmplitudes& record);

/// The march's blend and energy made again in `out` (a copy of the run's tiles),
/// `record` and `energy` where `run`'s marches moved outside its baked texels (each
/// blends_alone); the tiles written are the ones that hold such a texel.
void blend_again(const MarchOnlyRun& run, ShoreTiles& out, MarchedAmplitudes& record, MarchedEnergy& energy,
                 unsigned threads);

/// The foam (the shared tiles' breaking row) made again from `ratios` (CapRatios) and the
/// runs' marched energy `energies` now, at the model's texels outside `baked` (the
/// shared rows baked again) whose energy any of `changed` (per run, its grid and where
/// its marches moved) may have moved.
void foam_again(const ShoreGrid& model, ShoreTiles& shared, const CapRatios& ratios,
                std::span<const EnergyView> energies,
                std::span<const std::pair<const ShoreGrid*, const RunMarchChanges*>> changed, const TexelRange& baked,
                double breaking_index, unsigned threads);

/// A stored texel's marched energy and its breaking part in quanta of `quantum` m^2, from
/// the run's `record` at `at`, as the bake sums it over the run's `waves`; `texel` is the
/// texel's rows (a wave the rays do not reach, no wavevector, counts the march whole).
std::pair<std::uint32_t, std::uint32_t> marched_energy(std::span<const Wave> waves, const MarchedAmplitudes& record,
                                                       std::size_t at, const float* texel, double quantum);

/// A wave's marched energy at a texel in quanta of `quantum`: its amplitude `amplitude`
/// (m) times the march's share, squared; the bake's and the edit's one expression.
inline std::uint32_t energy_quanta(double amplitude, double share, double quantum) {
    return static_cast<std::uint32_t>(std::min(std::llround(amplitude * amplitude * share / quantum), 0xFFFFFFFFll));
}

}  // namespace tidewater::detail
