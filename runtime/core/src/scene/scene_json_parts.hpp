// Readers shared by the scene parser's files (private).
#pragma once

#include <filesystem>
#include <glm/vec2.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/detail/json_reader.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::detail {

/// The largest |height| or |level| a scene may give, m.
inline constexpr double kMaxAbsHeight = 1e5;

/// Reads [a, b] at `key` into `out`; each value within |v| <= limit.
Status read_pair(const ObjectReader& r, std::string_view key, glm::dvec2& out, bool required, double limit);

/// Reads `key` (absent: `out` untouched) as an array of `n` numbers, each finite and in
/// [lo, hi] (scene_floats_json.cpp).
Status read_numbers(const ObjectReader& r, std::string_view key, int n, double lo, double hi, const char* unit,
                    double* out);

/// Fails unless lo <= v <= hi, naming the key, the value and the range.
Status check_range(const ObjectReader& r, std::string_view key, double v, double lo, double hi, const char* unit);

/// A body's waves: a bundled preset name, a preset file, or an object with "preset",
/// "waves" or "spectrum" and the profile settings. `path` is its JSON path.
Result<WaterProfile> read_water_profile(const nlohmann::json& value, const std::string& source, const std::string& path,
                                        const std::filesystem::path& base_dir);

/// A profile's "optics" (water_optics_json.cpp): a Jerlov "water_type" or an
/// "extinction", and optionally a "color".
Status read_optics(const ObjectReader& parent, std::optional<WaterOptics>& out);

/// The scene's "lakes" and "rivers" (absent: none). Names must be unique among them and
/// must not be "ocean"; `warnings` collects the profiles' notes.
Status read_lakes(const ObjectReader& scene, const std::filesystem::path& base_dir, std::vector<SceneLake>& lakes,
                  std::vector<std::string>& warnings);
Status read_rivers(const ObjectReader& scene, const std::filesystem::path& base_dir, std::vector<SceneRiver>& rivers,
                   std::vector<std::string>& warnings);
/// The scene's "boats" (absent: none): scripted boats whose wakes the queries and the
/// renderer add; their wakes together must fit kMaxWakePoints.
Status read_boats(const ObjectReader& scene, std::vector<SceneBoat>& boats);
/// "clip_volumes": boxes, spheres, capsules, convex meshes and distance textures (their
/// files relative to `base_dir`) where the water is removed (scene_clip_volumes_json.cpp).
Status read_clip_volumes(const ObjectReader& scene, const std::filesystem::path& base_dir,
                         std::vector<ClipVolume>& volumes);
/// "floats": barrels, boxes and spheres set afloat (scene_floats_json.cpp).
Status read_floats(const ObjectReader& scene, std::vector<SceneFloat>& floats);
/// Points (x, z) at "path": at least two, finite, consecutive points apart.
Status read_path(const ObjectReader& r, std::vector<glm::dvec2>& path);
/// The scene's "terrain": one of flat, plane, heightmap (a PNG, a raw file or a raster
/// GDAL reads) and island (scene_terrain_json.cpp).
Result<Terrain> read_terrain(const ObjectReader& scene, const std::filesystem::path& base_dir);
/// Every body name once, none called "ocean" but the ocean.
Status check_body_names(const ObjectReader& scene, const Scene& parsed);

}  // namespace tidewater::detail
