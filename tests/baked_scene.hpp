// Tests' shortcut from a parsed scene to a baked one (bake_scene), as a value.
#pragma once

#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::test {

/// The scene baked; a parse or bake error passes through.
inline Result<Scene> baked(const Result<Scene>& parsed, const SceneBakeOptions& options = {}) {
    if (!parsed) return parsed.error();
    auto made = bake_scene(*parsed, options);
    if (!made) return made.error();
    return **made;
}

}  // namespace tidewater::test
