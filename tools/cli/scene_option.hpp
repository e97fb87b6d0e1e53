// Loading the scene named by --scene, or the bundled default scene.
#pragma once

#include <string>

#include "tidewater/scene.hpp"

namespace tidewater::cli {

inline Result<Scene> load_scene_option(const std::string& path) {
    return path.empty() ? default_scene() : load_scene(path);
}

}  // namespace tidewater::cli
