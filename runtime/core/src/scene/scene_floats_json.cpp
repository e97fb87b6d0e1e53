// The scene's floats (barrels, boxes, buoys): JSON -> SceneFloat. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include <cmath>

#include "scene/scene_json_parts.hpp"
#include "tidewater/buoyancy.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxFloats = 256;

Result<SceneFloat> read_float(const json& value, const std::string& source, const std::string& path) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"name", "shape", "at", "radius", "height", "size", "mass", "color"}); !st)
        return st.error();
    SceneFloat f;
    if (auto st = r->string("name", f.name); !st) return st.error();
    std::string shape = "barrel";
    if (auto st = r->string("shape", shape); !st) return st.error();
    if (shape == "barrel")
        f.shape = SceneFloat::Shape::barrel;
    else if (shape == "box")
        f.shape = SceneFloat::Shape::box;
    else if (shape == "sphere")
        f.shape = SceneFloat::Shape::sphere;
    else if (shape == "open_box")
        f.shape = SceneFloat::Shape::open_box;
    else
        return r->error("shape", fmt::format("\"{}\" is not a shape (allowed: barrel, box, sphere, open_box)", shape));
    if (auto st = read_pair(*r, "at", f.at, true, 1e6); !st) return st.error();
    const bool boxed = f.shape == SceneFloat::Shape::box || f.shape == SceneFloat::Shape::open_box;
    const bool round = !boxed;
    if (round && r->has("size")) return r->error("size", fmt::format("is for boxes; a {} takes \"radius\"", shape));
    if (!round && (r->has("radius") || r->has("height")))
        return r->error(r->has("radius") ? "radius" : "height", "a box takes \"size\": [x, y, z]");
    if (f.shape == SceneFloat::Shape::sphere && r->has("height"))
        return r->error("height", "a sphere takes only \"radius\"");
    double radius = 0.5 * f.size.x, height = f.size.y;
    if (auto st = r->number("radius", radius); !st) return st.error();
    if (auto st = check_range(*r, "radius", radius, 0.05, 20.0, " m"); !st) return st.error();
    if (auto st = r->number("height", height); !st) return st.error();
    if (auto st = check_range(*r, "height", height, 0.05, 40.0, " m"); !st) return st.error();
    if (round)
        f.size = f.shape == SceneFloat::Shape::sphere ? glm::dvec3(2.0 * radius)
                                                      : glm::dvec3(2.0 * radius, height, 2.0 * radius);
    if (auto st = read_numbers(*r, "size", 3, 0.05, 40.0, " m", &f.size.x); !st) return st.error();
    if (auto st = r->number("mass", f.mass, true); !st) return st.error();
    if (auto st = check_range(*r, "mass", f.mass, 0.1, 1e7, " kg"); !st) return st.error();
    double color[3] = {static_cast<double>(f.color.r), static_cast<double>(f.color.g), static_cast<double>(f.color.b)};
    if (auto st = read_numbers(*r, "color", 3, 0.0, 1.0, "", color); !st) return st.error();
    f.color = glm::vec3(static_cast<float>(color[0]), static_cast<float>(color[1]), static_cast<float>(color[2]));
    const double volume = boxed                                  ? f.size.x * f.size.y * f.size.z
                          : f.shape == SceneFloat::Shape::sphere ? kPi / 6.0 * f.size.x * f.size.x * f.size.x
                                                                 : 0.25 * kPi * f.size.x * f.size.x * f.size.y;
    if (f.mass >= kWaterDensity * volume)
        return r->error("mass", fmt::format("{} kg would sink: the {} displaces at most {:.1f} kg of water", f.mass,
                                            shape, kWaterDensity * volume));
    return f;
}

}  // namespace

Status read_numbers(const ObjectReader& r, std::string_view key, int n, double lo, double hi, const char* unit,
                    double* out) {
    if (!r.has(key)) return {};
    const json& v = r.at(key);
    if (!v.is_array() || v.size() != static_cast<std::size_t>(n))
        return r.error(key, fmt::format("expected an array of {} numbers, found {}", n, json_type_name(v)));
    for (int i = 0; i < n; ++i) {
        if (!v[static_cast<std::size_t>(i)].is_number())
            return r.error(key, fmt::format("item {} must be a number, found {}", i,
                                            json_type_name(v[static_cast<std::size_t>(i)])));
        const double x = v[static_cast<std::size_t>(i)].get<double>();
        if (!std::isfinite(x) || x < lo || x > hi)
            return r.error(key, fmt::format("item {} = {} is out of range [{}, {}]{}", i, x, lo, hi, unit));
        out[i] = x;
    }
    return {};
}

Status read_floats(const ObjectReader& scene, std::vector<SceneFloat>& floats) {
    floats.clear();
    if (!scene.has("floats")) return {};
    const json& list = scene.at("floats");
    if (!list.is_array())
        return scene.error("floats", fmt::format("expected an array of objects, found {}", json_type_name(list)));
    if (list.size() > kMaxFloats)
        return scene.error("floats", fmt::format("{} floats; at most {}", list.size(), kMaxFloats));
    for (std::size_t i = 0; i < list.size(); ++i) {
        auto f = read_float(list[i], scene.source(), fmt::format("{}/{}", scene.child_path("floats"), i));
        if (!f) return f.error();
        if (f->name.empty()) f->name = fmt::format("float {}", i);
        floats.push_back(std::move(f).value());
    }
    return {};
}

}  // namespace tidewater::detail
