// Scenes and presets: JSON loading with errors that name the file, the JSON
// path and the allowed range. The format is documented in docs/scene-format.md.
//
// Parsing only reads and validates: it never bakes. bake_scene (scene_bake.hpp)
// derives what the renderer and the shore-aware queries need.
//
// Threading: loading functions are reentrant; a Scene is a plain value.
#pragma once

#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/clip_volume.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/wakes.hpp"
#include "tidewater/water_body.hpp"

namespace tidewater {

inline constexpr int kSceneFormatVersion = 1;

/// A viewpoint stored with a scene (the renderer's default camera for it).
struct SceneCamera {
    glm::dvec3 position{0.0, 25.0, 120.0};  ///< m
    glm::dvec3 target{0.0};                 ///< m
    double fov_y_deg = 55.0;                ///< degrees, in (1, 179)
};

/// SceneShore::texels_per_wavelength by default.
inline constexpr double kDefaultShoreTexelsPerWavelength = 8.0;

/// How a scene's waves feel its shore (the scene's "shore" object).
struct SceneShore {
    bool enabled = true;
    int resolution = 256;  ///< Texels per side of the shore model, 16 to 8192.
    /// Texels per side of the signed distance field the model samples, 8 to 8192 and at
    /// least `resolution`; 0 = `resolution`.
    int distance_resolution = 0;
    double breaking_index = 0.78;  ///< Breaker height / depth (McCowan), 0.3 to 1.2.
    /// Texels a deep-water wavelength each wave's fields keep at least, 0 or 4 to 64: runs of
    /// long waves are baked on grids of 2, 4, 8 ... times the model's texel (depth, breaking
    /// and shore distance stay on the model's). 0: every wave on the model's grid.
    double texels_per_wavelength = kDefaultShoreTexelsPerWavelength;
    /// Refraction with diffraction, nonlinear shoaling and breaking by dissipation from the
    /// depth (the parabolic mild-slope march of each wave) where it holds; false: the rays
    /// alone, shoaled linearly and capped at breaking_index (which caps the rays' share in
    /// either case). An edit under the water re-bakes the whole model when true.
    bool diffraction = true;
    std::filesystem::path bake_folder;  ///< A saved bake for bake_scene to load (empty: bake).
};

/// Something the scene sets afloat (tidewater/scene_floaters.hpp): a barrel (an upright
/// cylinder), a box or a sphere of uniform density, starting at rest on the water.
struct SceneFloat {
    /// An open box is a box without its lid (a skiff, a barge's hold): it floats as the
    /// closed box does and keeps the water out of its hold (SceneFloaters::Body::clip).
    enum class Shape { barrel, box, sphere, open_box };
    std::string name;
    Shape shape = Shape::barrel;
    glm::dvec3 size{0.6, 0.9,
                    0.6};  ///< m: barrel: diameter, height, diameter; box, open box: x, y, z; sphere: diameter
    double mass = 100.0;   ///< kg (> 0, less than the water its hull displaces)
    glm::dvec2 at{0.0};    ///< world (x, z) where it starts, m
    glm::vec3 color{0.85, 0.35, 0.05};  ///< paint, linear RGB 0..1
};

/// A lake: the terrain below `level` connected to `at` (found by bake_scene), with its own
/// waves. Its body's level() is the lake's level.
struct SceneLake {
    std::string name;    ///< Unique among the scene's bodies.
    glm::dvec2 at{0.0};  ///< World xz, m: a point under the lake's level.
    WaterBody body;      ///< Waves and ripples of its preset, at the lake's level.
};

/// A river: a centreline from source to mouth with its discharge. Its falling surface,
/// carved bed and current come from bake_scene.
struct SceneRiver {
    std::string name;              ///< Unique among the scene's bodies.
    std::vector<glm::dvec2> path;  ///< World xz, m, source first; at least two points.
    std::vector<double> width;     ///< Wetted width per path point, m (> 0).
    double discharge = 1.0;        ///< Q, m^3/s (> 0).
    double manning = 0.035;        ///< Manning roughness n, s/m^(1/3).
    bool carve = true;             ///< Cut the channel into terrain that has none.
    /// Waves and ripples of its preset, directions relative to downstream (level unused).
    WaterBody body;
};

struct SceneBake;

struct Scene {
    std::string name;
    /// Where the scene was read from: load_scene's path, or parse_scene's `source`
    /// ("<default scene>" for the bundled one); empty for a scene built in code. Errors
    /// found later (baking, loading its bake) name the scene by it (scene_label).
    std::string source;
    Terrain terrain;
    /// The water; its level() is the scene's rest water level (stored only there) and its
    /// shore() the model the waves feel: null as parsed, set by bake_scene unless the
    /// shore is disabled or all deep water.
    WaterBody ocean;
    SceneShore shore;
    /// False in an inland scene (no "ocean"): `ocean` is then an empty body nothing
    /// draws or queries, and the lakes and rivers are the only water.
    bool has_ocean = true;
    std::vector<SceneLake> lakes;
    std::vector<SceneRiver> rivers;
    /// Scripted boats (tidewater/wakes.hpp): query_world and the renderer add their wakes.
    std::vector<SceneBoat> boats;
    /// Barrels, boxes and buoys afloat (SceneFloaters rides them with the boats).
    std::vector<SceneFloat> floats;
    /// Where the water is removed (tidewater/clip_volume.hpp): the scene's "clip_volumes",
    /// which stay put. The queries of the whole scene (query_world) report the surface dry
    /// inside them and the renderer draws no water there.
    std::vector<ClipVolume> clip_volumes;
    std::optional<SceneCamera> camera;  ///< Default viewpoint, if the scene gives one.
    std::vector<std::string> warnings;  ///< Non-fatal notes (e.g. clamped steepness).
    /// What bake_scene made (null as parsed). Copies share it; it is never modified.
    std::shared_ptr<const SceneBake> bake;

    double water_level() const { return ocean.level(); }  ///< m, world y of the rest water surface.
    /// True when the scene is ready to draw and query: its shore is disabled, or `bake`
    /// was made from this terrain, water level and shore settings and the ocean carries
    /// its model. A copy edited since its bake (say, a new terrain) is not baked.
    bool baked() const;
};

/// How messages name a scene: its `source` (a file's path), else `scene "NAME"`, else
/// "the scene".
std::string scene_label(const Scene& scene);

/// Parses scene JSON text. `source` names it in messages (a path or "<default scene>");
/// relative preset files and bake folders resolve against `base_dir`. Reads and
/// validates only; a saved bake the scene names is checked when bake_scene loads it.
Result<Scene> parse_scene(std::string_view json_text, const std::string& source,
                          const std::filesystem::path& base_dir = {});
/// Reads and parses a scene file.
Result<Scene> load_scene(const std::filesystem::path& path);
/// The bundled default scene (examples/scenes/default.json, embedded at build time).
Result<Scene> default_scene();

/// Parses a preset (a WaterProfile with "version" and "name").
Result<WaterProfile> parse_preset(std::string_view json_text, const std::string& source);
/// Loads a preset by bundled name ("ocean_rolling") or from a .json file path.
Result<WaterProfile> load_preset(const std::string& name_or_path, const std::filesystem::path& base_dir = {});
/// Names of the bundled presets (examples/presets/*.json).
std::vector<std::string> bundled_preset_names();

}  // namespace tidewater
