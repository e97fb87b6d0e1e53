// Shoreline-aware waves: per-wave fields baked over the terrain that make
// Gerstner waves feel the bottom (DESIGN.md, "Shoreline-aware waves").
//
// For wave i (deep-water wavenumber k0, frequency w, direction D), over water:
// - the local wavenumber solves w^2 = g k tanh(k h): waves shorten and slow;
// - the phase phi solves |grad phi| = k(h) by fast marching (first arrivals), with
//   phi = k0 D.x in deep water (k h >= pi) and on the domain edges waves enter
//   from. Stored as phi - k0 D.x, which is 0 offshore: no seam. On a straight
//   beach this is Snell's law (the along-shore wavenumber is conserved);
// - the amplitude is A0 * Ks * Kr: shoaling Ks = sqrt(cg0 / cg(h)) (energy flux),
//   refraction Kr = sqrt(cos(theta0) / cos(theta)) against the shore normal;
// - breaking: where the local height 2 sqrt(sum A^2) exceeds 0.78 h (the breaking
//   index) every amplitude is scaled down to it and `breaking` (foam) rises; 0 on land;
// - steepness: Q is scaled so that sum(Q k A) stays <= 0.95 (no folding).
// Local fields vary slowly against a wavelength, so derivatives use the local
// wavevector and treat amplitude and direction as constant over a wave.
// The model keeps its fields in tiles (shore_tiles.hpp): only where the waves feel
// the bottom; elsewhere it reads the open sea's or dry land's values. The tiles form
// layers: the shared fields (depth, breaking, steepness scale, shore distance) on the
// model's grid, and the waves in runs of consecutive waves, each run on a grid whose
// texel its shortest wave needs (a power of two times the model's: a 200 m swell does
// not need 2 m texels for its phase).
// Internal: hosts get a model through bake_scene (scene_bake.hpp) and use it through
// WaterBody::shore(); the raw grids are for the renderer, saved bakes and tests.
// Threading: immutable after bake (a saved bake's tiles are read on demand behind
// locks: lazy_shore_slots.hpp); share it freely.
#pragma once

#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <span>
#include <stop_token>
#include <vector>

#include "tidewater/detail/shore_tiles.hpp"
#include "tidewater/detail/square_region.hpp"
#include "tidewater/gerstner.hpp"
#include "tidewater/result.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/waves.hpp"

namespace tidewater {

/// What the shore does to one wave at one place.
struct LocalWave {
    double phase_residual = 0.0;    ///< phi - k0 D.x, rad.
    double amplitude_factor = 1.0;  ///< A / A0.
    glm::dvec2 wavevector{0.0};     ///< grad phi, rad/m (turns toward the shore, grows with shoaling).
};

struct LocalShore {
    /// Water level - terrain, m (< 0 on land); +-kShoreFarValue in a tile not stored.
    double depth = 0.0;
    /// Signed distance to the shoreline, m (+ over water); +-kShoreFarValue in a tile not stored.
    double shore_distance = 0.0;
    double breaking = 0.0;         ///< 0..1 foam from breaking.
    double steepness_scale = 1.0;  ///< Multiplies every Q here.
};

/// The fields a bake makes: grids over the terrain's square extent, values at texel
/// centres, row-major with rows along +z. A model keeps them in tiles (ShoreTiles).
struct ShoreWaveFields {
    int resolution = 0;      ///< Texels per side.
    double texel = 1.0;      ///< m.
    glm::dvec2 corner{0.0};  ///< World xz of the grid's outer corner, m.
    /// Per wave, then per texel: phi - k0 D.x (rad), A / A0, and grad phi (rad/m).
    std::vector<std::vector<float>> phase_residual, amplitude_factor, wavevector_x, wavevector_z;
    std::vector<float> depth;            ///< Water level - terrain, m (< 0 on land).
    std::vector<float> shore_distance;   ///< Signed distance to the shoreline, m (+ over water).
    std::vector<float> breaking;         ///< 0..1 foam from breaking.
    std::vector<float> steepness_scale;  ///< Multiplies every Q, 0..1.
};

/// Waves [first, first + count) of the set on a grid of their own: per texel (ShoreTiles,
/// stride 4 * count) count phase residuals, amplitude factors, wavevectors x and z.
struct ShoreWaveLayer {
    ShoreGrid grid;
    std::size_t first = 0, count = 0;
    ShoreTiles tiles;
};

class ShoreWaves {
  public:
    /// A model from fields made elsewhere for `waves`, every wave on the fields' grid (one
    /// run). Fails unless every grid is resolution^2 finite values and there is one of each
    /// per-wave field per wave.
    static Result<std::shared_ptr<const ShoreWaves>> from_fields(ShoreWaveFields fields, std::span<const Wave> waves);
    /// A model from tiles made or read elsewhere (a bake, a saved bake) for `waves`: the
    /// shared layer on `grid` and the runs of waves in order, together covering every
    /// wave (none for an empty set); slots 0 and 1 of each are written here. Fails unless
    /// the tiles fit their grids and the waves, every run's grid covers `grid`, and every
    /// stored value is finite.
    static Result<std::shared_ptr<const ShoreWaves>> from_tiles(const ShoreGrid& grid, ShoreTiles shared,
                                                                std::vector<ShoreWaveLayer> layers,
                                                                std::span<const Wave> waves);

    /// The same model on every `stride`-th texel of each layer (each layer's first texel
    /// centre kept): what a renderer over its memory budget draws. A coarse tile is open sea
    /// (dry land) where every tile its texels come from is; the rest are stored. `stride` 1: a copy.
    /// With `before` and `before_coarse` (another model and its coarsening at this stride,
    /// laid out as this one: this model re-baked from it after an edit), every coarse tile
    /// made only from tiles this model shares with `before` is `before_coarse`'s, shared:
    /// the two coarsenings differ only under the edit.
    std::shared_ptr<const ShoreWaves> coarsened(int stride, const ShoreWaves* before = nullptr,
                                                const ShoreWaves* before_coarse = nullptr) const;
    /// What coarsened(stride) takes on the GPU (ShoreTiles::device_bytes), without making it.
    std::uint64_t coarsened_device_bytes(int stride) const;
    /// This model with the still-water depth of shared grid texels [i0, i0 + w) x [j0, j0 + h)
    /// replaced by `depths` (row-major, w * h values), in every stored slot that holds one,
    /// aprons included; every other value stays bit for bit, and the wave runs are shared,
    /// not copied. For an edit of dry land that leaves the waves and the shoreline as they
    /// were (the caller checks that).
    std::shared_ptr<const ShoreWaves> with_depths(int i0, int j0, int w, int h, std::span<const float> depths) const;

    /// This model with its tiles replaced: the shared layer's by `shared` and each run's by
    /// `runs` (one per layer, in order), each with the same pages as before and its edited
    /// slots finite (the caller checks that: a local re-bake that rewrote them). Slots
    /// not written stay shared with this model.
    std::shared_ptr<const ShoreWaves> with_tiles(ShoreTiles shared, std::vector<ShoreTiles> runs) const;

    /// Bilinear sample at world xz from the tiles (each layer's own); `waves` must have one
    /// entry per wave of the set.
    LocalShore sample(glm::dvec2 p, std::span<LocalWave> waves) const;

    const ShoreGrid& grid() const { return grid_; }
    int resolution() const { return grid_.resolution; }
    double texel() const { return grid_.texel; }
    glm::dvec2 corner() const { return grid_.corner; }
    glm::dvec2 texel_center(int i, int j) const { return grid_.corner + grid_.texel * glm::dvec2(i + 0.5, j + 0.5); }
    std::size_t wave_count() const { return open_wavevectors_.size(); }
    /// True when every tile is open sea: the waves are unchanged and queries may skip the shore.
    bool trivial() const { return trivial_; }
    /// The shared fields in tiles on grid(): kShoreSharedRows floats a texel.
    const ShoreTiles& shared() const { return shared_; }
    /// The runs of waves, in order: each wave's fields on its run's grid, interleaved per
    /// texel for the query kernel and the GPU (ShoreWaveLayer).
    std::span<const ShoreWaveLayer> layers() const { return *layers_; }
    /// Shared texel (i, j)'s values (0 <= i, j < resolution()): from its tile's slot, the
    /// open sea's or dry land's where its tile is not stored.
    ShoreTexelView texel_values(int i, int j) const { return {shared_.texel(i, j)}; }
    /// The floats every tile takes on the CPU, every layer's.
    std::size_t bytes() const;
    /// What the tiles take on the GPU (ShoreTiles::device_bytes of every layer).
    std::uint64_t device_bytes() const;
    /// Tiles stored, over every layer (the shared one's and every run's).
    std::size_t stored_tiles() const;
    /// A saved bake's model reads its tiles on demand (lazy_shore_slots.hpp): this reads
    /// every one not read yet, in parallel, and returns the first that could not be read
    /// or does not fit the terrain. Ok at once for a model made in memory.
    Status read_all() const;
    /// The first tile read on demand that failed (its file and why); ok while none has.
    /// Queries, the renderer and saves check it after reading the model.
    Status status() const;

  private:
    using Layers = std::vector<ShoreWaveLayer>;
    static std::shared_ptr<ShoreWaves> made(const ShoreGrid& grid, ShoreTiles shared,
                                            std::shared_ptr<const Layers> layers,
                                            std::vector<glm::dvec2> open_wavevectors);

    ShoreGrid grid_;
    std::vector<glm::dvec2> open_wavevectors_;  ///< each wave's k0 D, rad/m
    ShoreTiles shared_;
    std::shared_ptr<const Layers> layers_;  ///< shared between a model and its with_depths edits
    bool trivial_ = false;
};

/// evaluate_lagrangian with the shore's local wavevectors and amplitudes.
LagrangianSample evaluate_lagrangian_shore(const WaveSet& set, const ShoreWaves& shore, glm::dvec2 rest, double time,
                                           LocalShore* local = nullptr);

}  // namespace tidewater
