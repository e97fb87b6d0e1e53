// The editor's script, parsed apart from the editor that runs it (editor_script.cpp), so
// that a bad line is refused with its file and line before anything runs, and so that the
// parser can be fuzzed without a window. One command a line; blank lines and lines
// starting with # are skipped:
//   camera PX PY PZ TX TY TZ [FOV]     view NAME     preset NAME     probe X Z     time T
//   brush X Z RADIUS HEIGHT     (a stroke of the terrain brush, re-baked in the background)
//   river NAME discharge Q      (as the Rivers panel's slider, re-baked in the background)
//   clip X Y Z RADIUS           (a clip sphere, as the Clip volumes panel places one)
//   viewports 1|2               (one viewport, or two side by side, as the View panel's box)
//   second PX PY PZ TX TY TZ [FOV]  (the right viewport's camera; two viewports from then on)
//   at N replace FILE|OLD|NEW   (a shader in --shader-dir, at frame N: a hot reload follows)
//   at N screenshot PATH        (the frame N, panels included)
//   at N COMMAND                (any command above, run before frame N is drawn; a re-bake
//                                it starts is swapped in before the next frame)
// Lengths in metres, angles in degrees, times in seconds, discharge in m^3/s. Names
// (views, presets, rivers) are checked when the command runs.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater::editor {

struct ScriptCamera {
    bool second = false;  ///< the right viewport's camera
    glm::dvec3 position{0.0}, target{0.0};
    double fov_y_deg = 0.0;  ///< 0: keep the camera's
};
struct ScriptViewports {
    int count = 1;
};
struct ScriptView {
    std::string name;
};
struct ScriptPreset {
    std::string name;
};
struct ScriptProbe {
    glm::dvec2 at{0.0};
};
struct ScriptBrush {
    glm::dvec2 at{0.0};
    double radius = 0.0, height = 0.0;
};
struct ScriptRiver {
    std::string name;
    double discharge = 0.0;
};
struct ScriptClip {
    glm::dvec3 at{0.0};
    double radius = 0.0;
};
struct ScriptStep {
    std::string kind, argument;  ///< "replace" FILE|OLD|NEW, or "screenshot" PATH
};
struct ScriptTime {
    double seconds = 0.0;
};
using ScriptCommand = std::variant<ScriptCamera, ScriptViewports, ScriptView, ScriptPreset, ScriptProbe, ScriptBrush,
                                   ScriptRiver, ScriptClip, ScriptStep, ScriptTime>;

/// A command, the line it is on (from 1) and the frame before which it runs (-1: at the
/// start; a ScriptStep always has one).
struct ScriptLine {
    int number = 0;
    long frame = -1;
    ScriptCommand command;
};

/// Bounds of a script's values: coordinates within a million metres, a field of view of
/// 1 to 170 degrees, a time within a day.
inline constexpr double kScriptMaxCoordinate = 1e6;

/// The commands of a script's text; `source` names it in errors ("FILE:LINE: ...").
Result<std::vector<ScriptLine>> parse_script(std::string_view text, const std::string& source);

}  // namespace tidewater::editor
