#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "editor.hpp"
#include "terrain_brush.hpp"

namespace tidewater::editor {

// A script for CI and pictures, one command a line:
//   camera PX PY PZ TX TY TZ [FOV]     view NAME     preset NAME     probe X Y     time T
//   brush X Z RADIUS HEIGHT     (a stroke of the terrain brush, re-baked in the background)
//   river NAME discharge Q      (as the Rivers panel's slider, re-baked in the background)
//   clip X Y Z RADIUS           (a clip sphere, as the Clip volumes panel places one)
//   viewports 1|2               (one viewport, or two side by side, as the View panel's box)
//   second PX PY PZ TX TY TZ [FOV]  (the right viewport's camera; two viewports from then on)
//   at N replace FILE|OLD|NEW   (a shader in --shader-dir, at frame N: a hot reload follows)
//   at N screenshot PATH        (the frame N, panels included)
Status Editor::run_script(const std::string& path) {
    std::ifstream in(path);
    if (!in) return Error{ErrorCode::io_error, fmt::format("{}: cannot open the script", path)};
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string command;
        if (!(words >> command) || command[0] == '#') continue;
        auto bad = [&] {
            return Error{ErrorCode::parse_error, fmt::format("{}:{}: cannot read \"{}\"", path, number, line)};
        };
        if (command == "camera") {
            glm::dvec3 p, t;
            double fov = camera_.fov_y_deg;
            if (!(words >> p.x >> p.y >> p.z >> t.x >> t.y >> t.z)) return bad();
            words >> fov;
            camera_ = OrbitCamera::looking(p, t, fov);
        } else if (command == "viewports") {
            int count = 0;
            if (!(words >> count) || (count != 1 && count != 2)) return bad();
            two_viewports_ = count == 2;
        } else if (command == "second") {
            glm::dvec3 p, t;
            double fov = camera_.fov_y_deg;
            if (!(words >> p.x >> p.y >> p.z >> t.x >> t.y >> t.z)) return bad();
            words >> fov;
            second_camera_ = OrbitCamera::looking(p, t, fov);
            second_camera_set_ = true;
            two_viewports_ = true;
        } else if (command == "view") {
            std::string name;
            words >> name;
            const auto view = render::parse_debug_view(name);
            if (!view) return bad();
            const auto all = render::all_debug_views();
            view_ = static_cast<int>(std::find(all.begin(), all.end(), *view) - all.begin());
        } else if (command == "preset") {
            std::string name;
            words >> name;
            const auto names = bundled_preset_names();
            const auto at = std::find(names.begin(), names.end(), name);
            if (at == names.end()) return bad();
            preset_ = static_cast<int>(at - names.begin());
            choose_preset(name);
        } else if (command == "probe") {
            glm::dvec2 px;
            if (!(words >> px.x >> px.y)) return bad();
            script_probe_ = px;
        } else if (command == "brush") {
            glm::dvec2 at;
            double radius = 0.0, height = 0.0;
            if (!(words >> at.x >> at.y >> radius >> height) || !(radius > 0.0)) return bad();
            brush_radius_ = static_cast<float>(radius);
            scripted_brush_ = std::make_pair(at, scene_->terrain.height_at(at));
            paint(at, height);
            Scene edited = *scene_;
            edited.terrain = *stroke_;
            stroke_.reset();
            bake_.start(std::move(edited), scene_);
        } else if (command == "river") {
            std::string name, field;
            double value = 0.0;
            if (!(words >> name >> field >> value) || field != "discharge" || !(value > 0.0)) return bad();
            Scene edited = *scene_;
            const auto it = std::find_if(edited.rivers.begin(), edited.rivers.end(),
                                         [&](const SceneRiver& r) { return r.name == name; });
            if (it == edited.rivers.end()) return bad();
            it->discharge = value;
            bake_.start(std::move(edited), scene_);
        } else if (command == "clip") {
            glm::dvec3 at;
            double radius = 0.0;
            if (!(words >> at.x >> at.y >> at.z >> radius)) return bad();
            place_clip(at, radius);
        } else if (command == "at") {
            Step step;
            if (!(words >> step.frame >> step.kind) || (step.kind != "replace" && step.kind != "screenshot"))
                return bad();
            std::getline(words >> std::ws, step.argument);
            if (step.argument.empty()) return bad();
            steps_.push_back(step);
        } else if (command == "time") {
            double t = 0.0;
            if (!(words >> t)) return bad();
            clock_.set_time(t);
        } else {
            return bad();
        }
    }
    return {};
}

Status Editor::run_step(const Step& step, std::string& screenshot) {
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
