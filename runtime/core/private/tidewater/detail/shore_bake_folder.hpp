// Saved shore bakes: a folder of 16-bit grey PNG fields with a JSON sidecar
// (`shore.json`), written by `tidewater bake` and loaded by scenes that name it
// (`"shore": {"bake": "folder"}`). The format is in docs/scene-format.md.
//
// Each field decodes as value = (pixel - zero_pixel) * step, so 0 (the offshore
// phase residual) is exact and every value is within step / 2 of the bake.
// Threading: both functions are reentrant. Units: metres, radians, seconds.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "tidewater/result.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/waves.hpp"

namespace tidewater {

inline constexpr int kShoreBakeFormatVersion = 1;

struct ShoreBakeContents {
    const ShoreWaves* model = nullptr;      ///< Required: the per-wave fields the runtime samples.
    const WaveSet* waves = nullptr;         ///< Required: the waves `model` was baked for.
    double water_level = 0.0;               ///< m.
    double breaking_index = 0.78;           ///< As baked (recorded, not checked when loading).
    std::string scene_name;                 ///< Recorded for people.
    const ShoreField* distance_field = nullptr;  ///< Optional: a finer signed distance field and its shoreline.
};

/// Writes the bake into `dir` whole or not at all: into a temporary sibling folder that
/// replaces `dir` when complete. An existing `dir` is replaced only on success.
Status save_shore_bake(const std::filesystem::path& dir, const ShoreBakeContents& contents);

/// The same files written straight into an existing folder `dir` (for a bake that holds
/// several models, itself written atomically).
Status write_shore_bake_into(const std::filesystem::path& dir, const ShoreBakeContents& contents);

/// Loads the model saved in `dir` for `waves` over `terrain` at `water_level`. Fails,
/// naming the file and field, on a missing or corrupt file, and when the bake was made
/// for other waves, another water level or another terrain (its depth field is checked
/// against `terrain` at every texel). The model covers the terrain's extent, or `region`
/// where given (a lake's basin).
Result<std::shared_ptr<const ShoreWaves>> load_shore_bake(const std::filesystem::path& dir, const WaveSet& waves,
                                                          double water_level, const Terrain& terrain,
                                                          const SquareRegion* region = nullptr);

}  // namespace tidewater
