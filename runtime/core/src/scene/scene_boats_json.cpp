// The scene's scripted boats: JSON -> SceneBoat. Schema: docs/scene-format.md.
#include <fmt/format.h>

#include "host_device.h"
#include "scene/scene_json_parts.hpp"

namespace tidewater::detail {

namespace {

using nlohmann::json;

Result<SceneBoat> read_boat(const json& value, const std::string& source, const std::string& path) {
    auto r = ObjectReader::open(value, source, path);
    if (!r) return r.error();
    if (auto st = r->allow_only({"name", "path", "speed", "length", "beam", "draft", "start"}); !st) return st.error();
    SceneBoat boat;
    if (auto st = r->string("name", boat.name, true); !st) return st.error();
    if (auto st = read_path(*r, boat.path); !st) return st.error();
    if (auto st = r->number("speed", boat.speed, true); !st) return st.error();
    if (auto st = check_range(*r, "speed", boat.speed, 0.1, 30.0, " m/s"); !st) return st.error();
    if (auto st = r->number("length", boat.hull.length, true); !st) return st.error();
    if (auto st = check_range(*r, "length", boat.hull.length, 1.0, 400.0, " m"); !st) return st.error();
    if (auto st = r->number("beam", boat.hull.beam, true); !st) return st.error();
    if (auto st = check_range(*r, "beam", boat.hull.beam, 0.3, 100.0, " m"); !st) return st.error();
    if (auto st = r->number("draft", boat.hull.draft, true); !st) return st.error();
    if (auto st = check_range(*r, "draft", boat.hull.draft, 0.05, 30.0, " m"); !st) return st.error();
    if (auto st = r->number("start", boat.start); !st) return st.error();
    if (auto st = check_range(*r, "start", boat.start, -1e6, 1e6, " s"); !st) return st.error();
    return boat;
}

}  // namespace

Status read_boats(const ObjectReader& scene, std::vector<SceneBoat>& boats) {
    boats.clear();
    if (!scene.has("boats")) return {};
    const json& list = scene.at("boats");
    if (!list.is_array())
        return scene.error("boats", fmt::format("expected an array of objects, found {}", json_type_name(list)));
    std::size_t points = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string at = fmt::format("{}/{}", scene.child_path("boats"), i);
        auto boat = read_boat(list[i], scene.source(), at);
        if (!boat) return boat.error();
        points += boat_wake_points(boat->hull, boat->speed);
        if (points > gpu::kMaxWakePoints)
            return scene.error(
                fmt::format("boats/{}", i),
                fmt::format("the boats' wakes would hold {} disturbance points, more than the {} a frame may hold "
                            "(a faster or shorter boat lays more: points are every length / 8 of track)",
                            points, gpu::kMaxWakePoints));
        boats.push_back(std::move(boat).value());
    }
    return {};
}

}  // namespace tidewater::detail
