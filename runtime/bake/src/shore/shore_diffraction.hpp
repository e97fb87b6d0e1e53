// A wave's refraction, diffraction, nonlinear shoaling and breaking over a shore grid by
// the parabolic march (parabolic_waves.hpp) along the wave's offshore direction: its
// amplitude is put in the place of the rays' where the march holds (where the wave
// travels within a small angle of the march and the march resolves its local
// wavelength); elsewhere, and in deep water, the rays' amplitude stays. The phase stays
// the rays' first arrival everywhere: the two phases differ by whole wavelengths over a
// coast (the march keeps the amplitude's own dispersion, and crossing waves), and a
// texel field cannot pass from one to the other without a crease. Private to the bake.
#pragma once

#include <complex>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "shore/fast_marching.hpp"
#include "shore/parabolic_waves.hpp"
#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::detail {

struct KeptMarch;

/// The sea a component breaks with: every component breaks where the sea does.
struct SeaState {
    double energy = 0.0;       ///< sum of A^2, m^2
    double mean_period = 0.0;  ///< energy-weighted mean period, s
    int components = 0;        ///< with an amplitude: more than one is a random sea
};
SeaState sea_state(std::span<const Wave> waves);

/// Per texel of the grid: where the march reached (share 255; 0: the rays' stand; the
/// bake puts march_share in its place, once the rays' direction there is known), the
/// march's amplitude factor (over the open-sea amplitude) and whether the wave is broken
/// there; and the march's spacing.
struct DiffractedWave {
    std::vector<std::uint8_t> share;  ///< 0..255
    std::vector<float> amplitude;
    std::vector<std::uint8_t> broken;
    double spacing = 0.0;  ///< between the march's points, m
    /// The share the model holds at the stored texels, once the bake has put the rays'
    /// direction in (held_share; 255 where the rays do not reach); `share` elsewhere.
    std::vector<std::uint8_t> held;
    double held_of(std::size_t k) const { return held[k] / 255.0; }
};

/// A random sea marched as a whole: one wave of its mean period and energy-weighted mean
/// direction carrying all its energy (amplitude sqrt(sum A^2), so twice its amplitude is
/// the sea's H_rms), broken as Battjes and Janssen say. Its rms height per texel of the
/// grid it was marched on (m; 0 on land, in deep water and where the march did not
/// reach). Battjes and Janssen's balance is of the sea's energy: a component that judged
/// the sea by its own amplitude (scaled as the sea's was where they entered) shoaled and
/// turned with its own period and direction, and the spectrum as a whole broke too little.
struct SeaHeight {
    std::shared_ptr<const ShoreField> field;
    /// Per texel of the field (m; 0 where the sea's march left none): written through set().
    std::vector<float> height;
    /// No height `height` holds is over this (m): the most set() was given (at()'s means of
    /// them, rounded to float as a march reads them, are not either).
    double highest = 0.0;
    /// At a world point: bilinear over the texels that have a height, 0 where none has.
    double at(glm::dvec2 p) const;
    /// Texel k's height (m).
    void set(std::size_t k, float h) {
        height[k] = h;
        highest = std::max(highest, static_cast<double>(h));
    }
};
SeaHeight march_sea(std::span<const Wave> waves, const SeaState& sea, std::shared_ptr<const ShoreField> field,
                    KeptMarch* kept = nullptr);
/// The one wave a random sea is marched as (march_sea): none for a regular wave or no sea.
std::optional<Wave> whole_sea_wave(std::span<const Wave> waves, const SeaState& sea);
/// Whether the sea's march leaves a texel of depth `depth` (m) alone: deep water for its
/// mean wave, the open sea's, where nothing breaks.
inline bool sea_leaves(const Wave& whole, double depth) {
    return depth * whole.k >= kDeepKh;
}

/// What a wave's march keeps so that a window of it can be marched again after an edit
/// of the depth, instead of the whole march: its state (complex amplitude and breaking at
/// every point across) every kKeptRowsEvery rows from its first, where a window is taken
/// up, and at every kKeptPointsEvery-th point after every advance, where a window's sides
/// are held. The march ends at the row after the last texel it fills (nothing past it
/// reads it), so the rows kept end there too. Empty where the march did not run (no
/// amplitude, a wave left to the rays, nothing to fill).
struct KeptMarch {
    static constexpr int kKeptRowsEvery = 32, kKeptPointsEvery = 32;
    int start = 0;                                ///< the march's first row, of its frame
    int points = 0;                               ///< across a row
    std::vector<std::complex<double>> amplitude;  ///< kept row n (row start + n * every) at n * points
    std::vector<char> broken;
    MarchColumns columns;
    std::size_t rows() const { return points > 0 ? amplitude.size() / static_cast<std::size_t>(points) : 0; }
    /// The march's last row, of its frame (the columns are kept on every row to it).
    int end() const { return start + static_cast<int>(columns.phase.size()) - 1; }
    /// Holds rows start to `last` from now: the rows past it are dropped, or rows added up
    /// to it (zero until written).
    void end_at(int last);
    std::size_t bytes() const { return amplitude.size() * sizeof(amplitude[0]) + broken.size() + columns.bytes(); }
};

/// Marches `wave` over `field` along its direction; texels where `keep` holds (deep water,
/// where the open sea's fields stand) and land are left at share 0. With `sea_height`,
/// the component breaks at the sea's marched height (a random sea). With `kept`, the
/// march's rows are kept there (KeptMarch).
DiffractedWave diffract_wave(const Wave& wave, const SeaState& sea, const ShoreField& field,
                             const std::function<bool(std::size_t)>& keep, const SeaHeight* sea_height = nullptr,
                             KeptMarch* kept = nullptr);

/// A grid's depths with a patch of texels changed (an edit's), over the field that holds
/// the rest and the grid's geometry. `field` must outlive it.
struct PatchedDepths {
    const ShoreField* field = nullptr;
    int i0 = 0, j0 = 0, width = 0, height = 0;  ///< the patch's first texel and size
    std::vector<float> depth;                   ///< over the patch, row by row
    /// Texel (i, j)'s depth, m.
    float at(int i, int j) const {
        const int a = i - i0, b = j - j0;
        if (a >= 0 && b >= 0 && a < width && b < height)
            return depth[static_cast<std::size_t>(b) * static_cast<std::size_t>(width) + static_cast<std::size_t>(a)];
        return field->depth[field->index(i, j)];
    }
    /// Bilinear between texel centres, clamped at the edges (ShoreField::sample's).
    double sample(glm::dvec2 p) const;
};

/// What an edit of the depth under the water changes in a wave's march: the texels where
/// the march's amplitude factor moved by over the tolerance, or its reach or breaking
/// changed, with what the march gives there now.
struct DiffractionChange {
    std::vector<std::uint32_t> texels;  ///< grid indices
    std::vector<float> amplitude;       ///< the amplitude factor after the edit (over the open-sea amplitude)
    std::vector<std::uint8_t> share;    ///< 255 where the march reaches the texel after the edit, else 0
    std::vector<std::uint8_t> broken;   ///< whether the wave is broken there after the edit
    std::size_t points_visited = 0;     ///< points the re-marches visited, both depths and every window tried
    int windows = 0;                    ///< windows marched (one more each time it was widened)
};

/// A change is left out under this (the amplitude factor, over the open-sea amplitude):
/// about the half precision the model holds amplitudes in.
inline constexpr double kMarchAmplitudeTolerance = 1e-3;

/// What the first march left at a texel, as the model holds it.
struct MarchedTexel {
    float amplitude = 0.0f;  ///< the amplitude factor (over the open-sea amplitude)
    bool reached = false;
    std::optional<bool> broken;  ///< none: not kept (the sea's march keeps its height alone)
    /// How far `amplitude` may lie from the march's own value (half its rounding step
    /// where it is held rounded): a change is told from the rounding past the tolerance.
    double rounding = 0.0;
};

/// How rediffract_wave marches again, past the wave and the depths.
struct Remarch {
    double tolerance = kMarchAmplitudeTolerance;
    /// The sea's heights over the old and the new depths (diffract_wave's `sea_height`).
    const SeaHeight* sea_before = nullptr;
    const SeaHeight* sea_after = nullptr;
    /// A copy of the march's kept rows: updated there to the new depths' within the
    /// window (in the phase they carry), so that a later edit takes up the march over
    /// these depths.
    KeptMarch* updated = nullptr;
    /// Where given: what the first march left at texel k (none where nothing reads it).
    /// A window as wide as a third of the march is then the whole row, marched over the
    /// new depths alone and compared with these, instead of beside the old depths' march.
    std::function<std::optional<MarchedTexel>(std::size_t k)> marched_before;
    /// Whether the wave breaks and shoals at the sea's height (`sea_after`), not its own:
    /// its march is then smooth in its own amplitude, and a whole row that agrees with the
    /// first march's kept row to kSettledAmplitude past everything the edit changed may
    /// end the march there (no threshold for a difference that small to tip).
    bool settles = false;
};

/// A whole row marched again ends the march where, past the edit, every point is within
/// this part of the wave's amplitude of the first march's kept row and breaks as it did.
/// Spread by shoaling and focusing over the rest of the march, a difference this small
/// stays far under kMarchAmplitudeTolerance.
inline constexpr double kSettledAmplitude = 1e-7;

/// `wave`'s march over `after`, taken up again from its rows kept over `before` (`after`'s
/// field; its depths differ only in `changed`): from the last kept row before the edit it
/// is marched over the old and the new depths side by side in a window across the march
/// round the edit, and what the two differ by is the change. The window's sides are held
/// at the first march's values (at kept columns), so that over the old depths it is that
/// march; where next to a side the two differ by over a twentieth of the tolerance (in
/// phase too) or in breaking, the new march's side is not the first one's and the window
/// is widened and marched again (with `how.marched_before`, as the whole row past a
/// third of the march). The march stops where, past the edit, the two agree exactly (the
/// edit's wake has died out), or a whole row marched alone agrees with the first march's
/// kept row to kSettledAmplitude (`how.settles`), or a row after the last texel it fills
/// over the new depths (a window with sides: where the first march ended). An edit that
/// reaches past the first march's end is marched across the whole row; `how.updated`
/// then ends where this march did. `keep` as diffract_wave's.
DiffractionChange rediffract_wave(const Wave& wave, const SeaState& sea, const ShoreField& before,
                                  const PatchedDepths& after, const KeptMarch& kept, const WorldRect& changed,
                                  const std::function<bool(std::size_t)>& keep, const Remarch& how = {});

/// The march holds a wave's amplitude fully within this angle of its direction and not
/// past the second (the small-angle form's wavenumber along the march is 1.6 % off at 35
/// degrees, 6 % at 50; the amplitude, which is all the model takes, suffers less); the
/// angle is the rays' (their first arrival turns smoothly, where crossing waves make the
/// march's own phase a poor guide).
inline constexpr double kFullAngle = 35.0 * 3.14159265358979323846 / 180.0;
inline constexpr double kNoAngle = 50.0 * 3.14159265358979323846 / 180.0;
/// 0 under `none`, 1 over `full`, linear between.
double ramp(double value, double none, double full);
/// The march's share of a wave turned `angle` (rad) from its offshore direction, whose
/// local wavelength is `wavelength` (m), on a march `spacing` m apart: by the angle, and
/// by the points the march has across the wave's crests (its wavelength across the march,
/// wavelength / sin(angle): along the march the phase is taken exactly). A wave running
/// along the march needs no points across it.
double march_share(double angle, double wavelength, double spacing);

/// The march's share (0..255) that the model holds at a texel the march reached, where
/// the rays' wavevector is (kx, kz) (not zero): march_share by the rays' turn from the
/// wave's offshore direction and their local wavelength, `spacing` the march's.
std::uint8_t held_share(const Wave& wave, float kx, float kz, double spacing);

/// The most points a wave's march holds at once in its rows is small; the points it
/// visits are at most this many (its spacing grows past that).
inline constexpr double kMaxDiffractionPoints = 64.0e6;

}  // namespace tidewater::detail
