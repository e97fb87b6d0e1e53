// Saved shore bakes: a JSON sidecar (`shore.json`) and the shore model's stored tiles
// (`tiles/`, one 16-bit grey PNG each: row r holds field row r at the slot's texels),
// with the distance field as whole-grid PNGs; written by `tidewater bake`
// (Tidewater::bake's shore_bake_write.hpp) and loaded here for scenes that name it
// (`"shore": {"bake": "folder"}`). The format is in docs/scene-format.md.
//
// Each row decodes as value = (pixel - zero_pixel) * step, so 0 (the offshore
// phase residual) is exact and every value is within step / 2 of the bake.
// Threading: reentrant. Units: metres, radians, seconds.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/waves.hpp"

namespace tidewater {

inline constexpr int kShoreBakeFormatVersion = 3;
inline constexpr const char* kShoreSidecar = "shore.json";
/// The distance field as one GDAL raster (a VRT over its PNGs, in metres) for GIS tools.
inline constexpr const char* kDistanceVrt = "distance.vrt";

/// The file of stored tile (ti, tj) of the layer in folder tiles/`layer` inside a bake folder.
std::string shore_tile_file(const std::string& layer, int ti, int tj);
/// The folder (under tiles/) of the shared layer's tiles, and of wave run `run`'s.
std::string shore_layer_folder(int run);

/// Loads the model saved in `dir` for `waves` over `terrain` at `water_level`: the index
/// now, each stored tile's fields the first time they are needed (lazy_shore_slots.hpp).
/// Fails, naming the file and field, on a missing file, a corrupt index, and when the bake
/// was made for other waves, another water level or another terrain (the open-sea and
/// dry-land tiles are checked against `terrain` here). A stored tile that is corrupt or
/// whose depths do not fit `terrain` is found as it is read: ShoreWaves::status() and
/// read_all() name it. The model covers the terrain's extent, or `region` where given (a
/// lake's basin). `settings`, where given, takes what the bake was made with: the model's
/// and the distance field's resolutions and the breaking index, and the texels per
/// wavelength and diffraction where the bake records them (bakes saved before 2026-12-07
/// do not: those are left as they were).
Result<std::shared_ptr<const ShoreWaves>> load_shore_bake(const std::filesystem::path& dir, const WaveSet& waves,
                                                          double water_level, const Terrain& terrain,
                                                          const SquareRegion* region = nullptr,
                                                          SceneShore* settings = nullptr);

}  // namespace tidewater
