// Scenes and presets: JSON loading with errors that name the file, the JSON
// path and the allowed range. The format is documented in docs/scene-format.md.
//
// Threading: loading functions are reentrant; a Scene is a plain value.
#pragma once

#include <filesystem>
#include <optional>

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/shore_waves.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/water_body.hpp"

namespace tidewater {

inline constexpr int kSceneFormatVersion = 1;

/// A viewpoint stored with a scene (the renderer's default camera for it).
struct SceneCamera {
    glm::dvec3 position{0.0, 25.0, 120.0};  ///< m
    glm::dvec3 target{0.0};                 ///< m
    double fov_y_deg = 55.0;                ///< degrees, in (1, 179)
};

/// How a scene's waves feel its shore (the scene's "shore" object).
struct SceneShore {
    bool enabled = true;
    ShoreWaveOptions options;            ///< Grid and breaking index of a bake on load.
    std::filesystem::path bake_folder;   ///< A saved bake to load instead (empty: bake on load).
};

struct Scene {
    std::string name;
    Terrain terrain;
    /// The water; its level() is the scene's rest water level (stored only there) and its
    /// shore() the model the waves feel (null: none or all deep water).
    WaterBody ocean;
    SceneShore shore;
    std::optional<SceneCamera> camera;   ///< Default viewpoint, if the scene gives one.
    std::vector<std::string> warnings;  ///< Non-fatal notes (e.g. clamped steepness).

    double water_level() const { return ocean.level(); }  ///< m, world y of the rest water surface.
};

struct SceneLoadOptions {
    /// Bake (or load) the shore model. Off, the ocean has no shore until bake_scene_shore().
    bool shore_model = true;
};

/// Parses scene JSON text. `source` names it in messages (a path or "<default scene>");
/// relative preset files and bake folders resolve against `base_dir`.
Result<Scene> parse_scene(std::string_view json_text, const std::string& source,
                          const std::filesystem::path& base_dir = {}, const SceneLoadOptions& options = {});
/// Reads and parses a scene file.
Result<Scene> load_scene(const std::filesystem::path& path, const SceneLoadOptions& options = {});
/// The bundled default scene (examples/scenes/default.json, embedded at build time).
Result<Scene> default_scene(const SceneLoadOptions& options = {});

/// (Re)makes the shore model of `scene` from its terrain, water level and waves as
/// `scene.shore` says: baked, or loaded from `scene.shore.bake_folder`, or none when
/// disabled. An editor calls this after editing the terrain; it then hands the scene to
/// the renderer (Renderer::set_scene). On failure the scene is unchanged.
Status bake_scene_shore(Scene& scene);

/// Parses a preset (a WaterProfile with "version" and "name").
Result<WaterProfile> parse_preset(std::string_view json_text, const std::string& source);
/// Loads a preset by bundled name ("ocean_rolling") or from a .json file path.
Result<WaterProfile> load_preset(const std::string& name_or_path,
                                 const std::filesystem::path& base_dir = {});
/// Names of the bundled presets (examples/presets/*.json).
std::vector<std::string> bundled_preset_names();

}  // namespace tidewater
