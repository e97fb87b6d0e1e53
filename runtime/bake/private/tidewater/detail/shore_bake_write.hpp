// Writing saved shore bakes (internal to Tidewater::bake): a folder of 16-bit grey PNG
// fields with a JSON sidecar, loaded by shore_bake_folder.hpp. Threading: reentrant.
#pragma once

#include <filesystem>
#include <string>

#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

struct ShoreBakeContents {
    const ShoreWaves* model = nullptr;  ///< Required: the per-wave fields the runtime samples.
    const WaveSet* waves = nullptr;     ///< Required: the waves `model` was baked for.
    double water_level = 0.0;           ///< m.
    double breaking_index = 0.78;       ///< As baked (recorded, not checked when loading).
    /// As baked (recorded, not checked when loading): a scene loaded from the bake takes
    /// them, with the grids' resolutions, so that an edit of it is baked as it was.
    double texels_per_wavelength = kDefaultShoreTexelsPerWavelength;
    bool diffraction = true;
    std::string scene_name;                      ///< Recorded for people.
    const ShoreField* distance_field = nullptr;  ///< Optional: a finer signed distance field and its shoreline.
};

/// Writes the bake into `dir` whole or not at all: into a temporary sibling folder that
/// replaces `dir` when complete. An existing `dir` is replaced only on success.
Status save_shore_bake(const std::filesystem::path& dir, const ShoreBakeContents& contents);

/// The same files written straight into an existing folder `dir` (for a bake that holds
/// several models, itself written atomically).
Status write_shore_bake_into(const std::filesystem::path& dir, const ShoreBakeContents& contents);

}  // namespace tidewater
