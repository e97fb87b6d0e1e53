// The shore model's bake (internal to Tidewater::bake): the per-wave fields that make
// Gerstner waves feel the bottom (tidewater/detail/shore_waves.hpp says what they mean).
// Threading: reentrant; `threads` workers; cancellable through ShoreWaveOptions::cancel.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stop_token>

#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"

namespace tidewater {

struct ShoreWaveOptions {
    int resolution = 256;  ///< Texels per side over the terrain's extent, 16 to 4096.
    /// The square the model covers; none: the terrain's extent (a lake's: its basin). Not
    /// with a shoreline baked elsewhere.
    std::optional<SquareRegion> region;
    unsigned threads = 0;                  ///< 0 = every hardware thread.
    double breaking_index = 0.78;          ///< Breaker height / depth (McCowan), in (0, 1.2].
    std::function<void(double)> progress;  ///< Called with 0..1, one call at a time (optional).
    std::stop_token cancel;                ///< Requested: the bake returns ErrorCode::cancelled.
};

/// Bakes the model over `terrain` at `water_level`. `shoreline`, when given, is a signed
/// distance field already baked there (any resolution): the model samples it instead
/// of baking the shoreline again.
Result<std::shared_ptr<const ShoreWaves>> bake_shore_waves(const WaveSet& set, const Terrain& terrain,
                                                           double water_level, const ShoreWaveOptions& options = {},
                                                           const ShoreField* shoreline = nullptr);

/// The whole-extent fields bake_shore_waves cuts into the model's tiles (for tests and
/// tools that look at what the tiles leave out).
Result<ShoreWaveFields> bake_shore_wave_fields(const WaveSet& set, const Terrain& terrain, double water_level,
                                               const ShoreWaveOptions& options = {},
                                               const ShoreField* shoreline = nullptr);

}  // namespace tidewater
