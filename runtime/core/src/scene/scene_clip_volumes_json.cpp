// The scene's "clip_volumes": JSON -> ClipVolume. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <vector>

#include "scene/scene_json_parts.hpp"
#include "tidewater/detail/distance_texture_png.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

/// Within what the renderer's frame holds (host_device.h kMaxClipVolumes, with room for a
/// host's and the floats' own).
constexpr std::size_t kMaxSceneClipVolumes = 16;
/// The scene's convex volumes' planes, at most: half the frame's (host_device.h kMaxClipPlanes).
constexpr std::size_t kMaxSceneClipPlanes = 48;
/// A convex volume's mesh, at most (it has at most ClipVolume::kMaxPlanes faces).
constexpr std::size_t kMaxConvexVertices = 256, kMaxConvexTriangles = 512;
/// The scene's distance textures' samples, at most: half the frame's (host_device.h
/// kMaxClipTextureSamples).
constexpr std::size_t kMaxSceneTextureSamples = std::size_t{1} << 21;

/// "vertices": [[x, y, z], ...] and "triangles": [[i, j, k], ...] of a convex volume's mesh.
Result<ClipVolume> read_convex(const ObjectReader& r, glm::dvec3 center) {
    for (const char* key : {"vertices", "triangles"})
        if (!r.has(key)) return r.error(key, "required for a convex volume is missing");
    const json& vertices = r.at("vertices");
    const json& triangles = r.at("triangles");
    if (!vertices.is_array() || vertices.empty() || vertices.size() > kMaxConvexVertices)
        return r.error("vertices", fmt::format("expected an array of 4 to {} [x, y, z] points", kMaxConvexVertices));
    if (!triangles.is_array() || triangles.empty() || triangles.size() > kMaxConvexTriangles)
        return r.error("triangles",
                       fmt::format("expected an array of 4 to {} [i, j, k] triangles", kMaxConvexTriangles));
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const json& p = vertices[i];
        glm::dvec3 v;
        for (int c = 0; c < 3; ++c) {
            if (!p.is_array() || p.size() != 3 || !p[static_cast<std::size_t>(c)].is_number())
                return r.error(fmt::format("vertices/{}", i), "expected [x, y, z] in metres");
            v[c] = p[static_cast<std::size_t>(c)].get<double>();
            if (!std::isfinite(v[c]) || std::abs(v[c]) > 1e5)
                return r.error(fmt::format("vertices/{}", i),
                               fmt::format("{} is out of range (|value| <= 1e5 m)", v[c]));
        }
        points.push_back(v);
    }
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const json& t = triangles[i];
        std::array<std::uint32_t, 3> face{};
        for (std::size_t c = 0; c < 3; ++c) {
            if (!t.is_array() || t.size() != 3 || !t[c].is_number_integer() || t[c].get<std::int64_t>() < 0 ||
                t[c].get<std::int64_t>() >= static_cast<std::int64_t>(points.size()))
                return r.error(fmt::format("triangles/{}", i),
                               fmt::format("expected [i, j, k], indices of \"vertices\" (0 to {})", points.size() - 1));
            face[c] = static_cast<std::uint32_t>(t[c].get<std::int64_t>());
        }
        faces.push_back(face);
    }
    auto made = ClipVolume::convex_mesh(center, points, faces);
    if (!made) return r.error("triangles", made.error().message);
    return made;
}

/// "file" (a 16-bit PNG of "slices" slices), "range" (m): a distance texture's samples.
Result<std::shared_ptr<const DistanceTexture>> read_texture(const ObjectReader& r,
                                                            const std::filesystem::path& base_dir) {
    std::string file;
    if (auto st = r.string("file", file, true); !st) return st.error();
    std::int64_t slices = 0;
    if (auto st = r.integer("slices", slices, DistanceTexture::kMinSide, DistanceTexture::kMaxSide, true); !st)
        return st.error();
    if (!r.has("range")) return r.error("range", "required (the distance at 0 and 65535, m) is missing");
    double range = 0.0;
    if (auto st = r.number("range", range); !st) return st.error();
    if (auto st = check_range(r, "range", range, 1e-3, 1e5, " m"); !st) return st.error();
    std::filesystem::path path = file;
    if (path.is_relative() && !base_dir.empty()) path = base_dir / path;
    auto texture = read_distance_texture_png(path, static_cast<std::uint32_t>(slices), range);
    if (!texture) return r.error("file", texture.error().message);
    return texture;
}

Result<ClipVolume> read_clip_volume(const json& value, const std::string& source, const std::string& path,
                                    const std::filesystem::path& base_dir) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"shape", "center", "half_extents", "radius", "half_length", "vertices", "triangles",
                                 "file", "slices", "range", "yaw", "pitch", "roll"});
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
    } else if (shape == "convex") {
        v.shape = ClipVolume::Shape::convex;
    } else if (shape == "distance_texture") {
        v.shape = ClipVolume::Shape::distance_texture;
    } else {
        return r->error("shape", fmt::format("\"{}\" is not a shape (allowed: box, sphere, capsule, convex, "
                                             "distance_texture)",
                                             shape));
    }
    if (!r->has("center")) return r->error("center", "required [x, y, z] is missing");
    if (auto st = read_numbers(*r, "center", 3, -1e7, 1e7, " m", &v.center.x); !st) return st.error();
    const bool convex = v.shape == ClipVolume::Shape::convex;
    for (const char* key : {"vertices", "triangles"})
        if (!convex && r->has(key)) return r->error(key, "is for convex volumes");
    if (convex) {
        for (const char* key : {"half_extents", "radius", "half_length"})
            if (r->has(key)) return r->error(key, "a convex volume takes \"vertices\" and \"triangles\"");
        auto made = read_convex(*r, v.center);
        if (!made) return made.error();
        v = std::move(made).value();
    }
    const bool textured = v.shape == ClipVolume::Shape::distance_texture;
    for (const char* key : {"file", "slices", "range"})
        if (!textured && r->has(key)) return r->error(key, "is for distance textures");
    if (textured) {
        auto texture = read_texture(*r, base_dir);
        if (!texture) return texture.error();
        v.texture = std::move(texture).value();
    }
    // A distance texture spans a box: it takes what a box does.
    const bool box = v.shape == ClipVolume::Shape::box || textured;
    const bool capsule = v.shape == ClipVolume::Shape::capsule;
    if (!convex && box != r->has("half_extents"))
        return r->error("half_extents", box ? "required [x, y, z] is missing" : "is for boxes");
    if (!convex && box == r->has("radius"))
        return r->error("radius", box ? "a box takes \"half_extents\"" : "required is missing");
    if (!convex && capsule != r->has("half_length"))
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

Status read_clip_volumes(const ObjectReader& scene, const std::filesystem::path& base_dir,
                         std::vector<ClipVolume>& volumes) {
    if (!scene.has("clip_volumes")) return {};
    const json& list = scene.at("clip_volumes");
    if (!list.is_array())
        return scene.error("clip_volumes", fmt::format("expected an array of objects, found {}", json_type_name(list)));
    if (list.size() > kMaxSceneClipVolumes)
        return scene.error("clip_volumes", fmt::format("{} volumes; at most {}", list.size(), kMaxSceneClipVolumes));
    std::size_t planes = 0, samples = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
        auto v = read_clip_volume(list[i], scene.source(), fmt::format("{}/{}", scene.child_path("clip_volumes"), i),
                                  base_dir);
        if (!v) return v.error();
        planes += v->planes.size();
        samples += v->texture ? v->texture->distances().size() : 0;
        if (samples > kMaxSceneTextureSamples)
            return scene.error("clip_volumes", fmt::format("the distance textures have {} samples in all; at most {}",
                                                           samples, kMaxSceneTextureSamples));
        if (planes > kMaxSceneClipPlanes)
            return scene.error("clip_volumes", fmt::format("the convex volumes have {} faces in all; at most {}",
                                                           planes, kMaxSceneClipPlanes));
        volumes.push_back(*v);
    }
    return {};
}

}  // namespace tidewater::detail
