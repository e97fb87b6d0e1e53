// The scene named by --scene (or the bundled default scene), parsed and baked.
#pragma once

#include <memory>
#include <fmt/format.h>
#include <string>

#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::cli {

inline Result<Scene> parse_scene_option(const std::string& path) { return path.empty() ? default_scene() : load_scene(path); }

/// Parses and bakes (or loads the saved bake of) the scene, ready to draw and query.
inline Result<std::shared_ptr<const Scene>> load_scene_option(const std::string& path, const SceneBakeOptions& options = {}) {
    auto scene = parse_scene_option(path);
    if (!scene) return scene.error();
    if (!scene->has_ocean)
        return Error{ErrorCode::unsupported, fmt::format("{}: the scene has no ocean; the tools query and draw an ocean, and "
                                                         "scenes of lakes and rivers alone are not supported by them yet",
                                                         path.empty() ? "<default scene>" : path)};
    return bake_scene(*scene, options);
}

}  // namespace tidewater::cli
