// The scene named by --scene (or the bundled default scene), parsed and baked.
#pragma once

#include <fmt/format.h>

#include <memory>
#include <string>

#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::cli {

inline Result<Scene> parse_scene_option(const std::string& path) {
    return path.empty() ? default_scene() : load_scene(path);
}

/// Whether the verb can work without an ocean (queries and drift can; drawing cannot yet).
enum class OceanNeed { optional, required };

/// Parses and bakes (or loads the saved bake of) the scene, ready to draw and query.
inline Result<std::shared_ptr<const Scene>> load_scene_option(const std::string& path,
                                                              OceanNeed ocean = OceanNeed::required,
                                                              const SceneBakeOptions& options = {}) {
    auto scene = parse_scene_option(path);
    if (!scene) return scene.error();
    if (ocean == OceanNeed::required && !scene->has_ocean)
        return Error{ErrorCode::unsupported,
                     fmt::format("{}: the scene has no ocean; drawing and inspecting scenes of lakes "
                                 "and rivers alone is not supported yet (query and drift are)",
                                 path.empty() ? "<default scene>" : path)};
    return bake_scene(*scene, options);
}

}  // namespace tidewater::cli
