// The scene named by --scene (or the bundled default scene), parsed and baked.
#pragma once

#include <memory>
#include <string>

#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::cli {

inline Result<Scene> parse_scene_option(const std::string& path) { return path.empty() ? default_scene() : load_scene(path); }

/// Parses and bakes (or loads the saved bake of) the scene, ready to draw and query.
inline Result<std::shared_ptr<const Scene>> load_scene_option(const std::string& path, const SceneBakeOptions& options = {}) {
    auto scene = parse_scene_option(path);
    if (!scene) return scene.error();
    return bake_scene(*scene, options);
}

}  // namespace tidewater::cli
