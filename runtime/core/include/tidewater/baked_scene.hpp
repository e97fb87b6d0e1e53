// A baked scene: what is derived once from a scene's terrain, levels and waves (the
// lakes' extents; each river's falling surface, carved channel and current; the shore
// models of the ocean and the lakes), and how Tidewater::core loads it from the saved
// bake a scene names ("shore": {"bake": folder}) without baking anything.
//
// Baking is Tidewater::bake's (tidewater/scene_bake.hpp: bake_scene, save_scene_bake):
// a game server that ships saved bakes links Tidewater::core alone and calls
// load_scene_bake.
//
// Lifetime: the result is a std::shared_ptr<const Scene>; every holder keeps it alive,
// and nothing in it changes once made. Threading: load_scene_bake is reentrant and
// only reads its input. Units: metres, seconds.
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

class ShoreWaves;
struct ShoreField;
namespace detail {
struct WaterBodiesBake;
struct ShoreMarches;
}  // namespace detail

/// What bake_scene made. Immutable; scenes copied from a baked one share it.
struct SceneBake {
    /// The ocean's shore model as baked or loaded, even when it is all deep water (the
    /// ocean itself then carries none, and queries skip the shore). Null when the scene's
    /// shore is disabled.
    std::shared_ptr<const ShoreWaves> ocean_shore;
    /// The exact signed distance to the simplified shoreline (m, positive over water) at
    /// the resolution it was baked at. Null when the shore is disabled or was loaded.
    std::shared_ptr<const ShoreField> shoreline;
    /// The lakes' extents and the rivers' surfaces, carved beds and currents (null when
    /// the scene has neither). Internal: reach them through the queries.
    std::shared_ptr<const detail::WaterBodiesBake> bodies;
    /// Each lake's shore model, in the scene's order (null where the shore is disabled);
    /// the baked scene's lakes carry the ones that change their waves.
    std::vector<std::shared_ptr<const ShoreWaves>> lake_shores;
    /// What the ocean's march keeps so that a stroke on the seabed is re-baked where it
    /// reaches (SceneBakeOptions::keep_marches); null otherwise. Internal.
    std::shared_ptr<const detail::ShoreMarches> ocean_marches;
    bool loaded = false;   ///< Loaded from the scene's saved bake rather than baked.
    double seconds = 0.0;  ///< Wall-clock time of the bake or load.
    /// What was taken unchanged from SceneBakeOptions::previous.
    struct Reused {
        std::size_t rivers = 0, lake_shores = 0;
        bool ocean_shore = false;
        /// The ocean's shore model and distance field taken from the previous bake with
        /// only the ground's height re-baked under an edit of dry land (a heightmap's
        /// pixels changed, or a river's channel re-carved, where no water is within a
        /// texel): the same as a full bake.
        bool ocean_shore_land_edit = false;
        /// The same, re-baked round an edit of the seabed or across the waterline: each
        /// wave marched again in a window round the edit and downstream of it, until its
        /// phase moves by under kOpenSeaPhaseTolerance, and the fields baked again there;
        /// every other tile is the previous bake's. Across the waterline the distance
        /// field (`shoreline`) is updated where the edit reaches first.
        bool ocean_shore_water_edit = false;
    } reused;
    int distance_resolution = 0;  ///< texels per side of the shoreline's distance field (0: none baked)
    /// What it was made from, so that Scene::baked() can tell an edited copy: the terrain
    /// with the rivers' channels cut into it (the baked scene's terrain too).
    Terrain terrain;
    double water_level = 0.0;
    SceneShore shore;
    std::vector<SceneLake> lakes;    ///< as baked (levels and seeds)
    std::vector<SceneRiver> rivers;  ///< as baked (paths, widths, discharges)
};

/// Told the stage and the fraction done, 0 to 1, never decreasing; one call at a time.
using BakeProgressCallback = std::function<void(std::string_view stage, double fraction)>;

/// Loads the saved bake `scene` names ("shore": {"bake": folder}, written by `tidewater
/// bake` or save_scene_bake) into a new scene ready for the renderer and the queries,
/// the same as bake_scene gives for it. A scene with nothing to bake (no shore, lakes
/// or rivers) comes back as it is. Errors name the saved bake's file and field, or say
/// that the scene names no saved bake. `progress` is told ("loading", fraction).
///
/// The shore models' tiles are read on demand: the load reads the bake's index and checks
/// its open-sea and dry-land tiles against the terrain; each stored tile is read (and its
/// depths checked) the first time a query, Renderer::set_scene (which reads them all) or
/// a save needs it, then kept. A tile that cannot be read, or was saved over another
/// terrain, makes the call that needed it fail, naming the file, and every later one.
Result<std::shared_ptr<const Scene>> load_scene_bake(const Scene& scene, const BakeProgressCallback& progress = {});

/// Reads every tile of the saved bake `scene` was loaded from that is not read yet, in
/// parallel, and returns the first that cannot be read or does not fit the terrain: for a
/// host that wants a bad bake found at load rather than at first use. Ok at once for a
/// scene baked in memory. Threading: may run while other threads query the scene.
Status read_scene_bake_tiles(const Scene& scene);

}  // namespace tidewater
