// Loading the scene named by --scene, or the bundled default scene.
#pragma once

#include <string>

#include "tidewater/scene.hpp"

namespace tidewater::cli {

inline Result<Scene> load_scene_option(const std::string& path, const SceneLoadOptions& options = {}) {
    return path.empty() ? default_scene(options) : load_scene(path, options);
}

}  // namespace tidewater::cli
