// Baking a scene: what is derived once from its terrain, levels and waves rather
// than per frame or per query: the lakes' extents; each river's falling surface, carved
// channel and current (a stream function, so that water is conserved); the ocean's
// shore model (per-wave fields from fast marching over the depth) and the exact signed
// distance to the shoreline (CGAL) it is built on.
//
// parse_scene (scene.hpp) only reads. bake_scene (Tidewater::bake) does the work, or
// loads the saved bake the scene names ("shore": {"bake": folder}) without redoing it
// (load_scene_bake, baked_scene.hpp: Tidewater::core alone), and returns a new scene
// ready for the renderer and the queries. An editor re-bakes after a
// terrain edit on a worker thread, with progress and cancellation, while other
// threads keep drawing and querying the previous result.
//
// Lifetime: the result is a std::shared_ptr<const Scene>; every holder keeps it alive,
// and nothing in it changes after bake_scene returns.
// Threading: bake_scene is reentrant and only reads its input, so it may run beside
// queries and rendering of any scene. Its parallel loops share the library's one task
// scheduler (oneTBB) with the queries. Units: metres, seconds.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <stop_token>
#include <string_view>
#include <vector>

#include "tidewater/baked_scene.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

struct SceneBakeOptions {
    unsigned threads = 0;  ///< Worker threads, 0 = all.
    /// Texels per side of the signed distance field, 8 to 8192 and at least the shore
    /// model's grid; 0 = the scene's `shore.distance_resolution` (itself 0 = the model's grid). The model samples this
    /// one field: the shoreline is baked once, and a finer field makes a slightly better model.
    int distance_resolution = 0;
    /// Told the stage ("water bodies", "lake shores", "shoreline", "shore waves" or "loading") and the fraction of the
    /// whole bake done, 0 to 1, never decreasing. One call at a time, from a baking thread.
    BakeProgressCallback progress;
    /// Request a stop from any thread: bake_scene returns ErrorCode::cancelled soon after
    /// (within one wave or one tile row of the work) and keeps nothing.
    std::stop_token cancel;
    /// The baked scene this one was edited from (an editor's last good scene), or null.
    /// What the edit leaves unchanged is taken from it instead of baked again: rivers with
    /// the same inputs over the same terrain, lakes' shore models whose basin, waves and
    /// shore settings are the same, and the ocean's shore model when the carved terrain,
    /// its waves, level and shore settings are; when only a heightmap's pixels changed,
    /// on dry land a texel or more from water, the ocean's shore model keeps everything but
    /// the ground's height there (SceneBake::Reused). The result is the same as a full bake.
    std::shared_ptr<const Scene> previous;
    /// Keep what the march of the ocean's waves needs (SceneBake::ocean_marches, about
    /// 100 MB for 24 waves on an 8 km island) so that a later bake with this one as
    /// `previous` re-bakes a stroke on the seabed where it reaches, with diffraction on
    /// (shore.diffraction, the default); without it such a stroke re-bakes the ocean's
    /// shore in full. An editor's.
    bool keep_marches = false;
};

/// Bakes `scene` (or loads its saved bake) into a new scene whose ocean feels its shore.
/// Errors name the scene's "shore" entry, the saved bake's file and field, or the
/// terrain where it cannot be baked.
Result<std::shared_ptr<const Scene>> bake_scene(const Scene& scene, const SceneBakeOptions& options = {});

/// Writes a baked scene's bake to `dir`, whole or not at all, for "shore": {"bake": dir}.
/// Fails when the scene has no bake or its shore is disabled.
Status save_scene_bake(const std::filesystem::path& dir, const Scene& baked);

}  // namespace tidewater
