// The scene's "clip_volumes": JSON -> ClipVolume. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <glm/gtc/quaternion.hpp>

#include "scene/scene_json_parts.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

/// Within what the renderer's frame holds (host_device.h kMaxClipVolumes, with room for a
/// host's and the floats' own).
constexpr std::size_t kMaxSceneClipVolumes = 16;

Result<ClipVolume> read_clip_volume(const json& value, const std::string& source, const std::string& path) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"shape", "center", "half_extents", "radius", "half_length", "yaw", "pitch", "roll"});
        !st)
        return st.error();
    std::string shape;
    if (auto st = r->string("shape", shape, true); !st) return st.error();
    ClipVolume v;
    if (shape == "box") {
        v.shape = ClipVolume::Shape::box;
    } else if (shape == "sphere") {
        v.shape = ClipVolume::Shape::sphere;
    } else if (shape == "capsule") {
        v.shape = ClipVolume::Shape::capsule;
    } else {
        return r->error("shape", fmt::format("\"{}\" is not a shape (allowed: box, sphere, capsule)", shape));
    }
    if (!r->has("center")) return r->error("center", "required [x, y, z] is missing");
    if (auto st = read_numbers(*r, "center", 3, -1e7, 1e7, " m", &v.center.x); !st) return st.error();
    const bool box = v.shape == ClipVolume::Shape::box;
    const bool capsule = v.shape == ClipVolume::Shape::capsule;
    if (box != r->has("half_extents"))
        return r->error("half_extents", box ? "required [x, y, z] is missing" : "is for boxes");
    if (box == r->has("radius"))
        return r->error("radius", box ? "a box takes \"half_extents\"" : "required is missing");
    if (capsule != r->has("half_length"))
        return r->error("half_length", capsule ? "required is missing" : "is for capsules");
    if (auto st = read_numbers(*r, "half_extents", 3, 1e-3, 1e5, " m", &v.half_extents.x); !st) return st.error();
    if (auto st = r->number("radius", v.radius); !st) return st.error();
    if (auto st = r->number("half_length", v.half_length); !st) return st.error();
    // Turned by yaw about y, then pitch about the turned x, then roll about the turned z.
    double yaw = 0.0, pitch = 0.0, roll = 0.0;
    for (auto [key, angle] : {std::pair{"yaw", &yaw}, std::pair{"pitch", &pitch}, std::pair{"roll", &roll}}) {
        if (auto st = r->number(key, *angle); !st) return st.error();
        if (auto st = check_range(*r, key, *angle, -360.0, 360.0, " degrees"); !st) return st.error();
    }
    v.orientation = glm::angleAxis(glm::radians(yaw), glm::dvec3(0.0, 1.0, 0.0)) *
                    glm::angleAxis(glm::radians(pitch), glm::dvec3(1.0, 0.0, 0.0)) *
                    glm::angleAxis(glm::radians(roll), glm::dvec3(0.0, 0.0, 1.0));
    if (auto st = validate(v, r->context()); !st) return st.error();
    return v;
}

}  // namespace

Status read_clip_volumes(const ObjectReader& scene, std::vector<ClipVolume>& volumes) {
    if (!scene.has("clip_volumes")) return {};
    const json& list = scene.at("clip_volumes");
    if (!list.is_array())
        return scene.error("clip_volumes", fmt::format("expected an array of objects, found {}", json_type_name(list)));
    if (list.size() > kMaxSceneClipVolumes)
        return scene.error("clip_volumes", fmt::format("{} volumes; at most {}", list.size(), kMaxSceneClipVolumes));
    for (std::size_t i = 0; i < list.size(); ++i) {
        auto v = read_clip_volume(list[i], scene.source(), fmt::format("{}/{}", scene.child_path("clip_volumes"), i));
        if (!v) return v.error();
        volumes.push_back(*v);
    }
    return {};
}

}  // namespace tidewater::detail
