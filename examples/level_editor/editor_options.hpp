// tidewater-editor's command line (see editor_main.cpp for what each option does).
#pragma once

#include <glm/vec2.hpp>
#include <optional>
#include <string>

namespace tidewater::editor {

struct Options {
    std::string scene, screenshot, script, shader_dir;
    int width = 1280, height = 720;
    long frames = -1, resize_at = -1;
    std::optional<glm::dvec2> probe;
    bool validation = true;
    bool memory_log = false;
    /// Bake a scene opened from its saved bake again in the background, keeping its
    /// marches, so that its first seabed stroke is re-baked where it reaches (off with
    /// --keep-saved-bake: for a world whose second bake would not fit in memory).
    bool ready_edits = true;
};

/// The options, or none when an argument is not understood.
std::optional<Options> parse(int argc, char** argv);

}  // namespace tidewater::editor
