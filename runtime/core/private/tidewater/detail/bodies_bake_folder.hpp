// Saved lakes and rivers (internal; loaded here, written by Tidewater::bake): beside a scene's shore bake in the folder
// `tidewater bake` writes, a sidecar `bodies.json` with what they were baked from and
// their centreline profiles, 16-bit PNG fields per lake and river (bake_files.hpp),
// and each lake's shore model in `lake_NN/` (a shore bake over its basin). The format is
// in docs/scene-format.md.
//
// Loading refuses, naming the file and field, a bake that no longer fits: other lakes or
// rivers (names, levels, paths, widths, discharges, roughness, carving), another water
// level or shore resolution, or another terrain (checked on the lakes' grid and at every
// river texel).
// Threading: reentrant. Units: metres, seconds, m^3/s.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

class ShoreWaves;

inline constexpr int kBodiesBakeFormatVersion = 1;
inline constexpr const char* kBodiesSidecar = "bodies.json";

/// The lakes and rivers as loaded, with each lake's shore model (null where none).
struct LoadedBodies {
    detail::WaterBodiesBake bodies;
    std::vector<std::shared_ptr<const ShoreWaves>> lake_shores;
    /// The shore settings the lakes' models were baked with (load_shore_bake's `settings`),
    /// over the scene's: none without a lake's shore model.
    std::optional<SceneShore> shore_settings;
};

/// Loads the lakes and rivers saved in `dir` for `scene` (parsed, not baked), with its
/// lakes' shore models when `lake_shores` is set.
Result<LoadedBodies> load_bodies_bake(const std::filesystem::path& dir, const Scene& scene,
                                      const detail::BodiesBakeOptions& options, bool lake_shores);

namespace detail {
/// The grid lakes are found on, over the terrain's extent: a saved bake stores the
/// terrain's shape on it, and loading checks it there.
FieldGrid saved_lake_grid(const Terrain& terrain, int resolution);
}  // namespace detail

}  // namespace tidewater
