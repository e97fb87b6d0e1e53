#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

#include "editor.hpp"
#include "editor_script_parse.hpp"
#include "terrain_brush.hpp"
#include "tidewater/detail/overloaded.hpp"

namespace tidewater::editor {

namespace {

using detail::Overloaded;

std::string read_script(const std::string& path, Status& status) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        status = Error{ErrorCode::io_error, fmt::format("{}: cannot open the script", path)};
        return {};
    }
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

// A script for CI, pictures and soaks (editor_script_parse.hpp): parsed whole; the lines
// without a frame run now, the others before their frame (run_command from the frame loop).
Status Editor::run_script(const std::string& path) {
    Status read;
    const std::string text = read_script(path, read);
    if (!read) return read;
    auto commands = parse_script(text, path);
    if (!commands) return commands.error();
    script_path_ = path;
    std::string no_screenshot;
    for (const ScriptLine& line : *commands) {
        if (line.frame >= 0) {
            scheduled_.push_back(line);
        } else if (auto ran = run_command(line, no_screenshot); !ran) {
            return ran;
        }
    }
    return {};
}

Status Editor::run_command(const ScriptLine& line, std::string& screenshot) {
    const std::string where = fmt::format("{}:{}", script_path_, line.number);
    // A script's commands run in order, each on what the edits before it made, as a panel
    // waits for its bar: a re-bake still running is finished and swapped in first.
    if (bake_.running()) swap_in(bake_.job.get());
    return std::visit(
        Overloaded{
            [&](const ScriptCamera& c) -> Status {
                OrbitCamera& camera = c.second ? second_camera_ : camera_;
                const double fov = c.fov_y_deg > 0.0 ? c.fov_y_deg : camera_.fov_y_deg;
                camera = OrbitCamera::looking(c.position, c.target, fov);
                if (c.second) second_camera_set_ = two_viewports_ = true;
                return {};
            },
            [&](const ScriptViewports& v) -> Status {
                two_viewports_ = v.count == 2;
                return {};
            },
            [&](const ScriptView& v) -> Status {
                const auto view = render::parse_debug_view(v.name);
                if (!view) return Error{ErrorCode::invalid_argument, fmt::format("{}: no view \"{}\"", where, v.name)};
                const auto all = render::all_debug_views();
                view_ = static_cast<int>(std::find(all.begin(), all.end(), *view) - all.begin());
                return {};
            },
            [&](const ScriptPreset& p) -> Status {
                const auto names = bundled_preset_names();
                const auto at = std::find(names.begin(), names.end(), p.name);
                if (at == names.end())
                    return Error{ErrorCode::invalid_argument,
                                 fmt::format("{}: no bundled preset \"{}\"", where, p.name)};
                preset_ = static_cast<int>(at - names.begin());
                choose_preset(p.name);
                return {};
            },
            [&](const ScriptProbe& p) -> Status {
                script_probe_ = p.at;
                return {};
            },
            [&](const ScriptBrush& b) -> Status {
                brush_radius_ = static_cast<float>(b.radius);
                scripted_brush_ = std::make_pair(b.at, scene_->terrain.height_at(b.at));
                paint(b.at, b.height);
                Scene edited = *scene_;
                edited.terrain = *stroke_;
                stroke_.reset();
                bake_.start(std::move(edited), scene_);
                return {};
            },
            [&](const ScriptRiver& r) -> Status {
                Scene edited = *scene_;
                const auto it = std::find_if(edited.rivers.begin(), edited.rivers.end(),
                                             [&](const SceneRiver& river) { return river.name == r.name; });
                if (it == edited.rivers.end())
                    return Error{ErrorCode::invalid_argument,
                                 fmt::format("{}: the scene has no river \"{}\"", where, r.name)};
                it->discharge = r.discharge;
                bake_.start(std::move(edited), scene_);
                return {};
            },
            [&](const ScriptClip& c) -> Status {
                place_clip(c.at, c.radius);
                return {};
            },
            [&](const ScriptStep& s) -> Status { return run_step(s, screenshot); },
            [&](const ScriptTime& t) -> Status {
                clock_.set_time(t.seconds);
                return {};
            },
        },
        line.command);
}

Status Editor::run_step(const ScriptStep& step, std::string& screenshot) {
    if (step.kind == "screenshot") {
        screenshot = step.argument;
        return {};
    }
    // replace FILE|OLD|NEW in the watched shader folder, as an engineer's save would.
    if (!shaders_) return Error{ErrorCode::invalid_argument, "editor: a replace step needs --shader-dir"};
    const auto bar = step.argument.find('|'), bar2 = step.argument.find('|', bar == std::string::npos ? 0 : bar + 1);
    if (bar == std::string::npos || bar2 == std::string::npos)
        return Error{ErrorCode::parse_error,
                     fmt::format("editor: replace needs FILE|OLD|NEW, got \"{}\"", step.argument)};
    const std::filesystem::path file = std::filesystem::path(shader_dir_) / step.argument.substr(0, bar);
    const std::string old_text = step.argument.substr(bar + 1, bar2 - bar - 1),
                      new_text = step.argument.substr(bar2 + 1);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    const auto at = source.find(old_text);
    if (!in || at == std::string::npos)
        return Error{ErrorCode::not_found, fmt::format("editor: {}: \"{}\" not found", file.string(), old_text)};
    source.replace(at, old_text.size(), new_text);
    std::ofstream(file, std::ios::trunc) << source;
    force_reload_ = true;
    return {};
}

}  // namespace tidewater::editor
