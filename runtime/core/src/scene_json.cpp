// Scene and preset JSON -> Scene / WaterProfile. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "embedded_text.hpp"
#include "scene/scene_json_parts.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/json_reader.hpp"
#include "tidewater/detail/shore_settings_limits.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

namespace {

using detail::check_range;
using detail::kMaxAbsHeight;
using detail::ObjectReader;
using detail::read_pair;
using nlohmann::json;

Status read_version(const ObjectReader& r) {
    std::int64_t version = 0;
    if (auto st = r.integer("version", version, 0, 1'000'000, true); !st) return st;
    if (version != kSceneFormatVersion) {
        return r.error("version", fmt::format("unsupported version {} (this build reads version {})", version,
                                              kSceneFormatVersion));
    }
    return {};
}

Status read_wave(const json& value, const std::string& source, const std::string& path, WaveSpec& w) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"direction", "wavelength", "amplitude", "steepness", "phase"}); !st) return st;
    if (auto st = r->number("direction", w.direction_deg, true); !st) return st;
    if (auto st = r->number("wavelength", w.wavelength, true); !st) return st;
    if (auto st = r->number("amplitude", w.amplitude, true); !st) return st;
    if (auto st = r->number("steepness", w.steepness, true); !st) return st;
    w.phase = 0.0;
    return r->number("phase", w.phase);
}

Status read_waves(const ObjectReader& r, std::vector<WaveSpec>& out) {
    const json& list = r.at("waves");
    if (!list.is_array()) {
        return r.error("waves", fmt::format("expected an array of waves, found {}", detail::json_type_name(list)));
    }
    if (list.size() > kMaxWaves) {
        return r.error("waves", fmt::format("{} waves given, at most {} allowed", list.size(), kMaxWaves));
    }
    out.assign(list.size(), WaveSpec{});
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (auto st = read_wave(list[i], r.source(), fmt::format("{}/{}", r.child_path("waves"), i), out[i]); !st)
            return st;
    }
    return {};
}

Status read_spectrum(const ObjectReader& parent, SpectrumSpec& s) {
    auto r = ObjectReader::open(parent.at("spectrum"), parent.source(), parent.child_path("spectrum"));
    if (!r) return r.error();
    if (auto st = r->allow_only({"type", "wind_speed", "fetch", "peak_enhancement", "direction", "spreading",
                                 "wave_count", "seed", "steepness"});
        !st)
        return st;
    std::string type;
    if (auto st = r->string("type", type, true); !st) return st;
    if (type == "jonswap") {
        s.kind = SpectrumKind::jonswap;
    } else if (type == "pierson_moskowitz") {
        s.kind = SpectrumKind::pierson_moskowitz;
    } else {
        return r->error("type",
                        fmt::format("\"{}\" is not a spectrum (allowed: \"jonswap\", \"pierson_moskowitz\")", type));
    }
    std::int64_t count = s.wave_count, seed = static_cast<std::int64_t>(s.seed);
    if (auto st = r->number("wind_speed", s.wind_speed, true); !st) return st;
    if (auto st = r->number("fetch", s.fetch); !st) return st;
    if (auto st = r->number("peak_enhancement", s.peak_enhancement); !st) return st;
    if (auto st = r->number("direction", s.mean_direction_deg); !st) return st;
    if (auto st = r->number("spreading", s.spreading); !st) return st;
    if (auto st = r->integer("wave_count", count, 1, static_cast<std::int64_t>(kMaxWaves)); !st) return st;
    if (auto st = r->integer("seed", seed, 0, std::int64_t{1} << 53); !st) return st;
    if (auto st = r->number("steepness", s.steepness); !st) return st;
    s.wave_count = static_cast<int>(count);
    s.seed = static_cast<std::uint64_t>(seed);
    return validate(s, r->context());
}

Status read_ripples(const ObjectReader& parent, RippleSpec& s) {
    auto r = ObjectReader::open(parent.at("ripples"), parent.source(), parent.child_path("ripples"));
    if (!r) return r.error();
    if (auto st = r->allow_only({"amplitude", "wavelength", "octaves", "speed", "direction", "seed"}); !st) return st;
    std::int64_t octaves = s.octaves, seed = s.seed;
    if (auto st = r->number("amplitude", s.amplitude); !st) return st;
    if (auto st = r->number("wavelength", s.wavelength); !st) return st;
    if (auto st = r->integer("octaves", octaves, 1, 8); !st) return st;
    if (auto st = r->number("speed", s.speed); !st) return st;
    if (auto st = r->number("direction", s.direction_deg); !st) return st;
    if (auto st = r->integer("seed", seed, 0, 0xffffffffLL); !st) return st;
    s.octaves = static_cast<int>(octaves);
    s.seed = static_cast<std::uint32_t>(seed);
    return validate(s, r->context());
}

Status read_flow_detail(const ObjectReader& parent, FlowDetailSpec& s) {
    auto r = ObjectReader::open(parent.at("flow"), parent.source(), parent.child_path("flow"));
    if (!r) return r.error();
    if (auto st = r->allow_only({"tiling", "speed", "strength", "offset", "period", "jump", "seed"}); !st) return st;
    std::int64_t seed = s.seed;
    if (auto st = r->number("tiling", s.tiling); !st) return st;
    if (auto st = r->number("speed", s.speed); !st) return st;
    if (auto st = r->number("strength", s.strength); !st) return st;
    if (auto st = r->number("offset", s.offset); !st) return st;
    if (auto st = r->number("period", s.period); !st) return st;
    if (auto st = read_pair(*r, "jump", s.jump, false, 0.5); !st) return st;
    if (auto st = r->integer("seed", seed, 0, 65535); !st) return st;
    s.seed = static_cast<std::uint32_t>(seed);
    return validate(s, r->context());
}

Status read_fold_policy(const ObjectReader& r, FoldPolicy& policy) {
    if (!r.has("fold_policy")) return {};
    std::string text;
    if (auto st = r.string("fold_policy", text); !st) return st;
    if (text == "reject") {
        policy = FoldPolicy::reject;
    } else if (text == "clamp") {
        policy = FoldPolicy::clamp;
    } else {
        return r.error("fold_policy", fmt::format("\"{}\" is not a policy (allowed: \"reject\", \"clamp\")", text));
    }
    return {};
}

/// Reads the wave content of a profile: exactly one of `waves` and `spectrum`.
Status read_wave_source(const ObjectReader& r, WaterProfile& p, bool preset_allowed) {
    const int sources = int(r.has("waves")) + int(r.has("spectrum")) + int(preset_allowed && r.has("preset"));
    if (sources != 1) {
        return Error{ErrorCode::schema_error, fmt::format("{}: give exactly one of {}\"waves\" and \"spectrum\"",
                                                          r.context(), preset_allowed ? "\"preset\", " : "")};
    }
    if (r.has("waves")) return read_waves(r, p.waves);
    if (r.has("spectrum")) {
        SpectrumSpec spec;
        if (auto st = read_spectrum(r, spec); !st) return st;
        auto waves = generate_waves(spec, r.context("spectrum"));
        if (!waves) return waves.error();
        p.waves = std::move(waves).value();
        p.spectrum = spec;
    }
    return {};
}

/// Optional settings shared by presets and inline oceans; they override what a preset set.
Status read_profile_settings(const ObjectReader& r, WaterProfile& p) {
    if (auto st = r.string("name", p.name); !st) return st;
    if (auto st = r.string("description", p.description); !st) return st;
    if (r.has("ripples")) {
        if (auto st = read_ripples(r, p.ripples); !st) return st;
    }
    if (r.has("flow")) {
        if (auto st = read_flow_detail(r, p.flow); !st) return st;
    }
    if (r.has("optics")) {
        if (auto st = detail::read_optics(r, p.optics); !st) return st;
    }
    if (auto st = read_fold_policy(r, p.fold_policy); !st) return st;
    return r.number("time_offset", p.time_offset);
}

Result<SceneCamera> read_camera(const ObjectReader& scene) {
    auto r = ObjectReader::open(scene.at("camera"), scene.source(), "/camera");
    if (!r) return r.error();
    if (auto st = r->allow_only({"position", "target", "fov"}); !st) return st.error();
    SceneCamera cam;
    for (const char* key : {"position", "target"}) {
        if (!r->has(key)) return r->error(key, "required [x, y, z] is missing");
        const json& v = r->at(key);
        if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
            return r->error(key, "expected [x, y, z], three numbers");
        const glm::dvec3 p{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
        for (double c : {p.x, p.y, p.z})
            if (!std::isfinite(c) || std::abs(c) > 1e7)
                return r->error(key, fmt::format("{} is out of range (|value| <= 1e7 m)", c));
        (std::string(key) == "position" ? cam.position : cam.target) = p;
    }
    if (auto st = r->number("fov", cam.fov_y_deg); !st) return st.error();
    if (auto st = check_range(*r, "fov", cam.fov_y_deg, 5.0, 150.0, " degrees"); !st) return st.error();
    if (glm::dvec3 d = cam.target - cam.position; d.x * d.x + d.y * d.y + d.z * d.z < 1e-6)
        return r->error("target", "must differ from position");
    return cam;
}

Result<SceneShore> read_shore(const ObjectReader& scene, const std::filesystem::path& base_dir) {
    SceneShore shore;
    if (!scene.has("shore")) return shore;
    auto r = ObjectReader::open(scene.at("shore"), scene.source(), "/shore");
    if (!r) return r.error();
    if (auto st = r->allow_only({"enabled", "resolution", "distance_resolution", "breaking_index",
                                 "texels_per_wavelength", "diffraction", "bake"});
        !st)
        return st.error();
    if (r->has("enabled")) {
        if (!r->at("enabled").is_boolean()) return r->error("enabled", "expected true or false");
        shore.enabled = r->at("enabled").get<bool>();
    }
    if (r->has("diffraction")) {
        if (!r->at("diffraction").is_boolean()) return r->error("diffraction", "expected true or false");
        shore.diffraction = r->at("diffraction").get<bool>();
    }
    std::int64_t resolution = shore.resolution;
    if (auto st = r->integer("resolution", resolution, 16, 8192); !st) return st.error();
    shore.resolution = static_cast<int>(resolution);
    std::int64_t distance_resolution = shore.distance_resolution;
    if (auto st = r->integer("distance_resolution", distance_resolution, 8, 8192); !st) return st.error();
    if (r->has("distance_resolution") && distance_resolution < shore.resolution)
        return r->error("distance_resolution",
                        fmt::format("{} is coarser than the shore model's grid ({}), which samples it",
                                    distance_resolution, shore.resolution));
    shore.distance_resolution = static_cast<int>(distance_resolution);
    if (auto st = r->number("breaking_index", shore.breaking_index); !st) return st.error();
    if (auto st = check_range(*r, "breaking_index", shore.breaking_index, detail::kLowestBreakingIndex,
                              detail::kHighestBreakingIndex, "");
        !st)
        return st.error();
    if (auto st = r->number("texels_per_wavelength", shore.texels_per_wavelength); !st) return st.error();
    if (shore.texels_per_wavelength != 0.0)
        if (auto st = check_range(*r, "texels_per_wavelength", shore.texels_per_wavelength,
                                  detail::kFewestTexelsPerWavelength, detail::kMostTexelsPerWavelength, " (or 0)");
            !st)
            return st.error();
    if (r->has("bake")) {
        if (r->has("resolution") || r->has("distance_resolution") || r->has("breaking_index") ||
            r->has("texels_per_wavelength") || r->has("diffraction"))
            return r->error("bake",
                            "a saved bake fixes the resolutions, breaking index, texels per wavelength and "
                            "diffraction: give either bake or those");
        std::string folder;
        if (auto st = r->string("bake", folder); !st) return st.error();
        if (folder.empty()) return r->error("bake", "expected a folder written by tidewater bake");
        shore.bake_folder = folder;
        if (shore.bake_folder.is_relative() && !base_dir.empty()) shore.bake_folder = base_dir / shore.bake_folder;
    }
    return shore;
}

bool looks_like_path(const std::string& name) {
    return name.find('/') != std::string::npos || name.find('\\') != std::string::npos ||
           (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0);
}

}  // namespace

namespace detail {

using nlohmann::json;

Result<WaterProfile> read_water_profile(const json& value, const std::string& source, const std::string& path,
                                        const std::filesystem::path& base_dir) {
    if (value.is_string()) return load_preset(value.get<std::string>(), base_dir);
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"preset", "waves", "spectrum", "ripples", "flow", "fold_policy", "time_offset", "name",
                                 "description", "optics"});
        !st)
        return st.error();
    WaterProfile profile;
    if (r->has("preset")) {
        std::string name;
        if (auto st = r->string("preset", name); !st) return st.error();
        auto preset = load_preset(name, base_dir);
        if (!preset) return preset.error();
        profile = std::move(preset).value();
    }
    if (auto st = read_wave_source(*r, profile, true); !st) return st.error();
    if (auto st = read_profile_settings(*r, profile); !st) return st.error();
    return profile;
}

Status read_pair(const ObjectReader& r, std::string_view key, glm::dvec2& out, bool required, double limit) {
    if (!r.has(key)) return required ? Status(r.error(key, "required [a, b] is missing")) : Status();
    const json& v = r.at(key);
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
        return r.error(key, "expected [a, b], two numbers");
    }
    const glm::dvec2 pair{v[0].get<double>(), v[1].get<double>()};
    for (double x : {pair.x, pair.y}) {
        if (!std::isfinite(x) || std::abs(x) > limit)
            return r.error(key, fmt::format("{} is out of range (allowed: |value| <= {})", x, limit));
    }
    out = pair;
    return {};
}

Status check_range(const ObjectReader& r, std::string_view key, double v, double lo, double hi, const char* unit) {
    if (v < lo || v > hi) return r.error(key, fmt::format("{} is out of range (allowed: {} to {}{})", v, lo, hi, unit));
    return {};
}

}  // namespace detail

std::vector<std::string> bundled_preset_names() {
    std::vector<std::string> names;
    for (const auto& e : embedded::presets::entries()) names.emplace_back(e.name);
    std::sort(names.begin(), names.end());
    return names;
}

Result<WaterProfile> parse_preset(std::string_view json_text, const std::string& source) {
    auto doc = detail::parse_json_text(json_text, source);
    if (!doc) return doc.error();
    auto r = ObjectReader::open(*doc, source, "");
    if (!r) return r.error();
    if (auto st = r->allow_only({"version", "name", "description", "waves", "spectrum", "ripples", "flow",
                                 "fold_policy", "time_offset", "optics"});
        !st)
        return st.error();
    if (auto st = read_version(*r); !st) return st.error();
    WaterProfile profile;
    if (auto st = read_wave_source(*r, profile, false); !st) return st.error();
    if (auto st = read_profile_settings(*r, profile); !st) return st.error();
    // Validate now so a bad preset is reported against its own file.
    auto body = WaterBody::create(profile, 0.0, source);
    if (!body) return body.error();
    return profile;
}

Result<WaterProfile> load_preset(const std::string& name_or_path, const std::filesystem::path& base_dir) {
    if (!looks_like_path(name_or_path)) {
        for (const auto& e : embedded::presets::entries()) {
            if (e.name == name_or_path) return parse_preset(e.text, fmt::format("<preset {}>", e.name));
        }
        std::string list;
        for (const auto& n : bundled_preset_names()) list += (list.empty() ? "" : ", ") + n;
        return Error{ErrorCode::not_found,
                     fmt::format("preset \"{}\" is not bundled (bundled: {}); give a path ending in .json for a file",
                                 name_or_path, list)};
    }
    std::filesystem::path path = name_or_path;
    if (path.is_relative() && !base_dir.empty()) path = base_dir / path;
    auto text = detail::read_text_file(path.string());
    if (!text) return text.error();
    return parse_preset(*text, path.string());
}

Result<Scene> parse_scene(std::string_view json_text, const std::string& source,
                          const std::filesystem::path& base_dir) {
    auto doc = detail::parse_json_text(json_text, source);
    if (!doc) return doc.error();
    auto r = ObjectReader::open(*doc, source, "");
    if (!r) return r.error();
    if (auto st = r->allow_only({"version", "name", "description", "water_level", "terrain", "ocean", "lakes", "rivers",
                                 "boats", "floats", "clip_volumes", "camera", "shore"});
        !st)
        return st.error();
    if (auto st = read_version(*r); !st) return st.error();
    Scene scene;
    scene.source = source;
    if (auto st = r->string("name", scene.name); !st) return st.error();
    if (!r->has("ocean") && !r->has("lakes") && !r->has("rivers"))
        return r->error("ocean",
                        "a scene needs water: give an ocean (a preset name, a file or an object), lakes or rivers");
    // The ocean's level: required with an ocean, meaningless without one.
    double level = 0.0;
    if (r->has("ocean") || r->has("water_level")) {
        if (!r->has("ocean")) return r->error("water_level", "is the ocean's level, and this scene has no \"ocean\"");
        if (auto st = r->number("water_level", level, true); !st) return st.error();
        if (std::abs(level) > kMaxAbsHeight) {
            return r->error("water_level",
                            fmt::format("{} is out of range (allowed: |water_level| <= 100000 m)", level));
        }
    }
    if (!r->has("terrain")) return r->error("terrain", "required terrain is missing");
    auto terrain = detail::read_terrain(*r, base_dir);
    if (!terrain) return terrain.error();
    scene.terrain = std::move(terrain).value();
    if (r->has("ocean")) {
        auto profile = detail::read_water_profile(r->at("ocean"), source, "/ocean", base_dir);
        if (!profile) return profile.error();
        auto body = WaterBody::create(*profile, level, r->context("ocean"), &scene.warnings);
        if (!body) return body.error();
        scene.ocean = std::move(body).value();
    } else {
        scene.has_ocean = false;
    }
    if (auto st = detail::read_lakes(*r, base_dir, scene.lakes, scene.warnings); !st) return st.error();
    if (auto st = detail::read_rivers(*r, base_dir, scene.rivers, scene.warnings); !st) return st.error();
    if (auto st = detail::read_boats(*r, scene.boats); !st) return st.error();
    if (auto st = detail::read_floats(*r, scene.floats); !st) return st.error();
    if (auto st = detail::read_clip_volumes(*r, base_dir, scene.clip_volumes); !st) return st.error();
    if (!scene.has_ocean && scene.lakes.empty() && scene.rivers.empty())
        return r->error("ocean",
                        "a scene needs water: give an ocean (a preset name, a file or an object), lakes or rivers");
    if (auto st = detail::check_body_names(*r, scene); !st) return st.error();
    // How the waves feel the shore; bake_scene makes the model.
    auto shore = read_shore(*r, base_dir);
    if (!shore) return shore.error();
    scene.shore = std::move(shore).value();
    if (r->has("camera")) {
        auto camera = read_camera(*r);
        if (!camera) return camera.error();
        scene.camera = *camera;
    }
    return scene;
}

std::string scene_label(const Scene& scene) {
    if (!scene.source.empty()) return scene.source;
    if (!scene.name.empty()) return fmt::format("scene \"{}\"", scene.name);
    return "the scene";
}

Result<Scene> load_scene(const std::filesystem::path& path) {
    auto text = detail::read_text_file(path.string());
    if (!text) return text.error();
    return parse_scene(*text, path.string(), path.parent_path());
}

Result<Scene> default_scene() {
    for (const auto& e : embedded::scenes::entries()) {
        if (e.name == "default") return parse_scene(e.text, "<default scene>", {});
    }
    return Error{ErrorCode::not_found, "the default scene is not bundled in this build"};
}

}  // namespace tidewater
