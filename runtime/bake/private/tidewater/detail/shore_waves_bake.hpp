// The shore model's bake (internal to Tidewater::bake): the per-wave fields that make
// Gerstner waves feel the bottom (tidewater/detail/shore_waves.hpp says what they mean),
// computed and kept only in the tiles where they differ from the open sea's and dry
// land's (shore_tiles.hpp): the model's memory grows with the coast, not the area.
// Threading: reentrant; `threads` workers; cancellable through ShoreWaveOptions::cancel.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stop_token>

#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

namespace detail {
struct ShoreMarches;
}

struct ShoreWaveOptions {
    int resolution = 256;  ///< Texels per side over the terrain's extent, 16 to 8192.
    /// The square the model covers; none: the terrain's extent (a lake's: its basin). Not
    /// with a shoreline baked elsewhere.
    std::optional<SquareRegion> region;
    unsigned threads = 0;                  ///< 0 = every hardware thread.
    double breaking_index = 0.78;          ///< Breaker height / depth (McCowan), in (0, 1.2].
    std::function<void(double)> progress;  ///< Called with 0..1, one call at a time (optional).
    std::stop_token cancel;                ///< Requested: the bake returns ErrorCode::cancelled.
    /// Store every tile, the open sea and dry land too (tests compare the band with it).
    bool store_every_tile = false;
    /// Texels a deep-water wavelength that each wave's fields keep at least: a run of waves
    /// whose shortest is long enough is baked and stored on a grid of 2, 4, 8 ... times the
    /// model's texel (the breaking, depth and shore distance stay on the model's grid).
    /// 0: every wave on the model's grid.
    double texels_per_wavelength = kDefaultShoreTexelsPerWavelength;
    /// Each wave marched by the parabolic mild-slope equation too (refraction with
    /// diffraction, nonlinear shoaling, breaking by dissipation), its fields put in the
    /// rays' place where the march holds (shore_diffraction.hpp).
    bool diffraction = true;
    /// Where given (with `diffraction`), what the march keeps for a re-bake after a stroke
    /// on the seabed is put there (shore/shore_marches.hpp); null when nothing was marched.
    std::shared_ptr<const detail::ShoreMarches>* keep_marches = nullptr;
};

/// Bakes the model over `terrain` at `water_level`. `shoreline`, when given, is a signed
/// distance field already baked there (any resolution): the model samples it instead
/// of baking the shoreline again.
Result<std::shared_ptr<const ShoreWaves>> bake_shore_waves(const WaveSet& set, const Terrain& terrain,
                                                           double water_level, const ShoreWaveOptions& options = {},
                                                           const ShoreField* shoreline = nullptr);

}  // namespace tidewater
