// A profile's "optics": a Jerlov water type, an extinction, and optionally a colour.
#include <fmt/format.h>

#include "scene_json_parts.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

Status read_channels(const ObjectReader& r, std::string_view key, glm::dvec3& out) {
    const json& v = r.at(key);
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
        return r.error(key, "expected [red, green, blue], three numbers");
    out = glm::dvec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    return {};
}

}  // namespace

Status read_optics(const ObjectReader& parent, std::optional<WaterOptics>& out) {
    auto r = ObjectReader::open(parent.at("optics"), parent.source(), parent.child_path("optics"));
    if (!r) return r.error();
    if (auto st = r->allow_only({"water_type", "extinction", "color"}); !st) return st;
    if (r->has("water_type") == r->has("extinction"))
        return r->error("water_type", "give exactly one of water_type and extinction");
    WaterOptics optics;
    if (r->has("water_type")) {
        std::string name;
        if (auto st = r->string("water_type", name); !st) return st;
        const auto type = jerlov_type_named(name);
        if (!type) {
            std::string list;
            for (const auto& n : jerlov_type_names()) list += (list.empty() ? "\"" : ", \"") + n + "\"";
            return r->error("water_type", fmt::format("\"{}\" is not a Jerlov water type (allowed: {})", name, list));
        }
        optics = jerlov_optics(*type);
    } else {
        if (auto st = read_channels(*r, "extinction", optics.extinction); !st) return st;
        optics.color = glm::dvec3(kDeepWaterBrightness);  // replaced below once the extinction is checked
    }
    if (r->has("color"))
        if (auto st = read_channels(*r, "color", optics.color); !st) return st;
    if (auto st = validate(optics, r->context()); !st) return st;
    if (r->has("extinction") && !r->has("color")) optics.color = deep_water_color(optics.extinction);
    out = optics;
    return {};
}

}  // namespace tidewater::detail
