// The scene's lakes and rivers: JSON -> SceneLake / SceneRiver. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "scene/scene_json_parts.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

constexpr double kMaxCoordinate = 1e7;  // m, as for camera and terrain centres
constexpr std::size_t kMaxPathPoints = 4096;

Status read_name(const ObjectReader& r, std::string& name) {
    if (auto st = r.string("name", name, true); !st) return st;
    if (name.empty()) return r.error("name", "must not be empty");
    return {};
}

Result<WaterBody> read_body(const ObjectReader& r, const char* default_preset, double level,
                            const std::filesystem::path& base_dir, std::vector<std::string>& warnings) {
    const json preset = r.has("preset") ? r.at("preset") : json(default_preset);
    auto profile = read_water_profile(preset, r.source(), r.child_path("preset"), base_dir);
    if (!profile) return profile.error();
    return WaterBody::create(*profile, level, r.context("preset"), &warnings);
}

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

/// Whether segments ab and cd share a point.
bool segments_meet(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto on = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 x, double side) {
        return side == 0.0 && std::min(p.x, q.x) <= x.x && x.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= x.y &&
               x.y <= std::max(p.y, q.y);
    };
    return on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4);
}

Status check_simple(const ObjectReader& r, const std::vector<glm::dvec2>& path) {
    const std::size_t n = path.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        for (std::size_t j = i + 2; j + 1 < n; ++j) {
            if (segments_meet(path[i], path[i + 1], path[j], path[j + 1]))
                return r.error("path",
                               fmt::format("crosses itself: segment {}-{} meets segment {}-{}", i, i + 1, j, j + 1));
        }
    }
    return {};
}

Status read_width(const ObjectReader& r, std::size_t points, std::vector<double>& width) {
    if (!r.has("width")) return r.error("width", "required width (m, one number or one per path point) is missing");
    const json& v = r.at("width");
    std::vector<double> values;
    if (v.is_number()) {
        values.assign(points, v.get<double>());
    } else if (v.is_array()) {
        if (v.size() != points)
            return r.error("width", fmt::format("{} widths for {} path points (give one number or one per point)",
                                                v.size(), points));
        for (const json& w : v) {
            if (!w.is_number()) return r.error("width", fmt::format("expected numbers, found {}", json_type_name(w)));
            values.push_back(w.get<double>());
        }
    } else {
        return r.error("width", fmt::format("expected a number or an array of numbers, found {}", json_type_name(v)));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!(values[i] >= 0.5 && values[i] <= 10000.0))
            return r.error(v.is_array() ? fmt::format("width/{}", i) : std::string("width"),
                           fmt::format("{} is out of range (allowed: 0.5 to 10000 m)", values[i]));
    }
    width = std::move(values);
    return {};
}

Result<SceneLake> read_lake(const json& value, const std::string& source, const std::string& path,
                            const std::filesystem::path& base_dir, std::vector<std::string>& warnings) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"name", "level", "at", "preset"}); !st) return st.error();
    SceneLake lake;
    if (auto st = read_name(*r, lake.name); !st) return st.error();
    double level = 0.0;
    if (auto st = r->number("level", level, true); !st) return st.error();
    if (auto st = check_range(*r, "level", level, -1e5, 1e5, " m"); !st) return st.error();
    if (auto st = read_pair(*r, "at", lake.at, true, kMaxCoordinate); !st) return st.error();
    auto body = read_body(*r, "lake_rippled", level, base_dir, warnings);
    if (!body) return body.error();
    lake.body = std::move(body).value();
    return lake;
}

Result<SceneRiver> read_river(const json& value, const std::string& source, const std::string& path,
                              const std::filesystem::path& base_dir, std::vector<std::string>& warnings) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"name", "path", "width", "discharge", "manning", "preset", "carve"}); !st)
        return st.error();
    SceneRiver river;
    if (auto st = read_name(*r, river.name); !st) return st.error();
    if (auto st = read_path(*r, river.path); !st) return st.error();
    if (auto st = check_simple(*r, river.path); !st) return st.error();
    if (auto st = read_width(*r, river.path.size(), river.width); !st) return st.error();
    if (auto st = r->number("discharge", river.discharge, true); !st) return st.error();
    if (auto st = check_range(*r, "discharge", river.discharge, 1e-3, 1e6, " m^3/s"); !st) return st.error();
    if (auto st = r->number("manning", river.manning); !st) return st.error();
    if (auto st = check_range(*r, "manning", river.manning, 0.005, 0.3, " s/m^(1/3)"); !st) return st.error();
    if (r->has("carve")) {
        if (!r->at("carve").is_boolean()) return r->error("carve", "expected true or false");
        river.carve = r->at("carve").get<bool>();
    }
    auto body = read_body(*r, "river_flowing", 0.0, base_dir, warnings);
    if (!body) return body.error();
    river.body = std::move(body).value();
    return river;
}

template <typename Body, typename ReadOne>
Status read_list(const ObjectReader& scene, const char* key, const std::filesystem::path& base_dir,
                 std::vector<Body>& out, std::vector<std::string>& warnings, ReadOne read_one) {
    out.clear();
    if (!scene.has(key)) return {};
    const json& list = scene.at(key);
    if (!list.is_array())
        return scene.error(key, fmt::format("expected an array of objects, found {}", json_type_name(list)));
    if (list.size() > 255) return scene.error(key, fmt::format("{} given, at most 255 allowed", list.size()));
    for (std::size_t i = 0; i < list.size(); ++i) {
        auto body =
            read_one(list[i], scene.source(), fmt::format("{}/{}", scene.child_path(key), i), base_dir, warnings);
        if (!body) return body.error();
        out.push_back(std::move(body).value());
    }
    return {};
}

}  // namespace

/// Points (x, z) at `key`: at least two, finite, consecutive points apart.
Status read_path(const ObjectReader& r, std::vector<glm::dvec2>& path) {
    if (!r.has("path")) return r.error("path", "required [[x, z], ...] is missing");
    const json& list = r.at("path");
    if (!list.is_array()) return r.error("path", fmt::format("expected [[x, z], ...], found {}", json_type_name(list)));
    if (list.size() < 2 || list.size() > kMaxPathPoints)
        return r.error("path", fmt::format("{} points given (allowed: 2 to {})", list.size(), kMaxPathPoints));
    path.clear();
    for (std::size_t i = 0; i < list.size(); ++i) {
        const json& v = list[i];
        const std::string at = fmt::format("path/{}", i);
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
            return r.error(at, "expected [x, z], two numbers");
        const glm::dvec2 p{v[0].get<double>(), v[1].get<double>()};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kMaxCoordinate ||
            std::abs(p.y) > kMaxCoordinate)
            return r.error(at, fmt::format("[{}, {}] is out of range (allowed: |value| <= 1e7 m)", p.x, p.y));
        if (!path.empty() && std::hypot(p.x - path.back().x, p.y - path.back().y) < 1e-3)
            return r.error(at, "repeats the point before it (points must be at least 1 mm apart)");
        path.push_back(p);
    }
    return {};
}

Status read_lakes(const ObjectReader& scene, const std::filesystem::path& base_dir, std::vector<SceneLake>& lakes,
                  std::vector<std::string>& warnings) {
    return read_list(scene, "lakes", base_dir, lakes, warnings, read_lake);
}

Status read_rivers(const ObjectReader& scene, const std::filesystem::path& base_dir, std::vector<SceneRiver>& rivers,
                   std::vector<std::string>& warnings) {
    return read_list(scene, "rivers", base_dir, rivers, warnings, read_river);
}

Status check_body_names(const ObjectReader& scene, const Scene& parsed) {
    std::set<std::string> seen;
    if (parsed.has_ocean) seen.insert("ocean");
    auto check = [&](const std::string& name, const char* key, std::size_t i) -> Status {
        const std::string at = fmt::format("{}/{}/name", key, i);
        if (name == "ocean") return scene.error(at, "\"ocean\" names the ocean; choose another name");
        if (!seen.insert(name).second) return scene.error(at, fmt::format("\"{}\" names another body already", name));
        return {};
    };
    for (std::size_t i = 0; i < parsed.lakes.size(); ++i)
        if (auto st = check(parsed.lakes[i].name, "lakes", i); !st) return st;
    for (std::size_t i = 0; i < parsed.rivers.size(); ++i)
        if (auto st = check(parsed.rivers[i].name, "rivers", i); !st) return st;
    return {};
}

}  // namespace tidewater::detail
