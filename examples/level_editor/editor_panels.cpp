// The editor's ImGui panels and the overlays drawn over the frame (river points,
// markers).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "editor.hpp"

namespace tidewater::editor {

void Editor::panels() {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Tidewater");
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("%s: %zu lake(s), %zu river(s)", scene_->name.c_str(), scene_->lakes.size(), scene_->rivers.size());
        ImGui::InputText("file", path_field_, sizeof path_field_);
        if (ImGui::Button("Open")) {
            auto st = load(path_field_);
            message_ = st ? fmt::format("opened {}", path_field_) : st.error().message;
        }
        ImGui::SameLine();
        if (ImGui::Button("Save bake") && !bake_.running()) {
            const std::string dir =
                std::string(path_field_).empty() ? "tidewater-bake" : std::string(path_field_) + ".bake";
            auto st = save_scene_bake(dir, *scene_);
            message_ = st ? fmt::format("saved the bake to {}/", dir) : st.error().message;
        }
    }
    if (ImGui::CollapsingHeader("Water", ImGuiTreeNodeFlags_DefaultOpen)) {
        const auto names = bundled_preset_names();
        std::vector<const char*> items;
        for (const auto& n : names) items.push_back(n.c_str());
        if (ImGui::Combo("ocean preset", &preset_, items.data(), static_cast<int>(items.size())) && !bake_.running() &&
            preset_ >= 0)
            choose_preset(names[static_cast<std::size_t>(preset_)]);
        if (preset_ < 0) ImGui::TextUnformatted("the scene's own waves (pick a preset to replace them)");
        ImGui::Text("%zu waves, Hs %.2f m", scene_->ocean.waves().size(),
                    scene_->ocean.waves().significant_wave_height());
    }
    if (ImGui::CollapsingHeader("Shore", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::SliderFloat("breaking index", &breaking_index_, 0.3f, 1.2f, "%.2f");
        if (ImGui::Button("Re-bake shore") && !bake_.running()) {
            Scene edited = *scene_;
            edited.shore.breaking_index = breaking_index_;
            bake_.start(std::move(edited), scene_);
        }
        if (bake_.running()) {
            std::string stage;
            {
                const std::lock_guard<std::mutex> g(bake_.lock);
                stage = bake_.stage;
            }
            ImGui::ProgressBar(static_cast<float>(bake_.fraction.load()), ImVec2(-1, 0), stage.c_str());
        }
    }
    if (ImGui::CollapsingHeader("Terrain")) {
        ImGui::Checkbox("brush (left drag: raise, with shift: lower)", &brushing_);
        ImGui::SliderFloat("radius (m)", &brush_radius_, 5.0f, 400.0f, "%.0f");
        ImGui::SliderFloat("height per frame (m)", &brush_height_, 0.1f, 10.0f, "%.1f");
        if (stroke_) ImGui::TextUnformatted("painting: baked when the stroke ends");
    }
    bodies_panel();
    if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
        bool paused = clock_.paused();
        if (ImGui::Checkbox("pause", &paused)) paused ? clock_.pause() : clock_.resume();
        if (ImGui::SliderFloat("scale", &time_scale_, 0.0f, 4.0f, "%.2f")) clock_.set_scale(time_scale_);
        float t = static_cast<float>(clock_.now());
        if (ImGui::SliderFloat("time (s)", &t, 0.0f, std::max(600.0f, t))) clock_.set_time(t);
    }
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        const auto views = render::all_debug_views();
        std::vector<std::string> names;
        for (const auto v : views) names.emplace_back(render::to_string(v));
        std::vector<const char*> items;
        for (const auto& n : names) items.push_back(n.c_str());
        ImGui::Combo("debug view", &view_, items.data(), static_cast<int>(items.size()));
        ImGui::Checkbox("two viewports", &two_viewports_);
        ImGui::Text("GPU: terrain %.2f ms, copy %.2f ms, water %.2f ms", timings_.sky_and_terrain_ms,
                    timings_.scene_copy_ms, timings_.water_ms);
        if (second_view_)
            ImGui::Text("right: terrain %.2f ms, copy %.2f ms, water %.2f ms", second_timings_.sky_and_terrain_ms,
                        second_timings_.scene_copy_ms, second_timings_.water_ms);
    }
    if (ImGui::CollapsingHeader("Probe", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (probe_) {
            const SurfacePoint& s = probe_->water.surface;
            ImGui::Text("at (%.1f, %.1f): %s", probe_->point.x, probe_->point.z,
                        probe_->on_land ? "land" : std::string(body_name(*scene_, probe_->water.body)).c_str());
            ImGui::Text("height %.3f m, depth %.2f m, foam %.2f", s.height, s.depth, s.foam);
            ImGui::Text("velocity (%.2f, %.2f, %.2f) m/s", s.velocity.x, s.velocity.y, s.velocity.z);
        } else {
            ImGui::TextUnformatted("move the cursor over the water");
        }
    }
    clip_panel();
    if (shaders_ && ImGui::CollapsingHeader("Shaders", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (shaders_->error().empty())
            ImGui::TextWrapped("%s", shader_line_.empty() ? "watching for changes" : shader_line_.c_str());
        else
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", shaders_->error().c_str());
    }
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    ImGui::End();
}

// Clip volumes: spheres placed on the water at the probe, where the water is removed.
void Editor::clip_panel() {
    if (!ImGui::CollapsingHeader("Clip volumes")) return;
    ImGui::SliderFloat("radius (m)", &clip_radius_, 0.5f, 50.0f);
    if (probe_ && !probe_->on_land) {
        if (ImGui::Button("place a sphere at the probe")) place_clip(probe_->point, clip_radius_);
    } else {
        ImGui::TextUnformatted("put the probe on the water to place one");
    }
    for (std::size_t i = 0; i < clip_volumes_.size(); ++i) {
        const ClipVolume& v = clip_volumes_[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("sphere (%.0f, %.0f, %.0f) r %.1f m", v.center.x, v.center.y, v.center.z, v.radius);
        ImGui::SameLine();
        const bool remove = ImGui::SmallButton("remove");
        ImGui::PopID();
        if (remove) {
            clip_volumes_.erase(clip_volumes_.begin() + static_cast<std::ptrdiff_t>(i));
            break;
        }
    }
}

void Editor::bodies_panel() {
    if (scene_->rivers.empty() && scene_->lakes.empty()) return;
    if (!ImGui::CollapsingHeader("Rivers and lakes")) return;
    ImGui::Checkbox("drag river points (left drag)", &editing_rivers_);
    bool changed = false;
    Scene edited = body_edit_ ? *body_edit_ : *scene_;
    for (std::size_t r = 0; r < edited.rivers.size(); ++r) {
        SceneRiver& river = edited.rivers[r];
        ImGui::PushID(static_cast<int>(r));
        float q = static_cast<float>(river.discharge), w = static_cast<float>(river.width.front());
        ImGui::Text("river \"%s\"", river.name.c_str());
        if (ImGui::SliderFloat("discharge (m3/s)", &q, 0.1f, 500.0f, "%.1f", ImGuiSliderFlags_Logarithmic)) {
            river.discharge = q;
            changed = true;
        }
        if (ImGui::SliderFloat("source width (m)", &w, 2.0f, 200.0f, "%.1f")) {
            river.width.front() = w;
            changed = true;
        }
        ImGui::PopID();
    }
    for (std::size_t l = 0; l < edited.lakes.size(); ++l) {
        ImGui::PushID(1000 + static_cast<int>(l));
        float level = static_cast<float>(edited.lakes[l].body.level());
        if (ImGui::SliderFloat(fmt::format("lake \"{}\" level (m)", edited.lakes[l].name).c_str(), &level, -50.0f,
                               500.0f, "%.2f")) {
            auto body = WaterBody::create(edited.lakes[l].body.profile(), level, edited.lakes[l].name);
            if (body) {
                edited.lakes[l].body = std::move(body).value();
                changed = true;
            }
        }
        ImGui::PopID();
    }
    if (changed) body_edit_ = std::move(edited);
    if (body_edit_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left) && !bake_.running()) {
        // Released: bake the edited rivers and lakes (the rest is reused).
        bake_.start(std::move(*body_edit_), scene_);
        body_edit_.reset();
    }
}

void Editor::drag_points() {
    // The rivers' path points, drawn over the frame; with editing on, a left drag moves one.
    const Scene& shown = body_edit_ ? *body_edit_ : *scene_;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    std::optional<std::pair<std::size_t, std::size_t>> nearest;
    float best = 12.0f;
    for (std::size_t r = 0; r < shown.rivers.size(); ++r)
        for (std::size_t k = 0; k < shown.rivers[r].path.size(); ++k) {
            const glm::dvec2 p = shown.rivers[r].path[k];
            const auto q = project({p.x, shown.terrain.height_at(p) + 1.0, p.y});
            if (!q) continue;
            draw->AddCircle(*q, 5.0f, IM_COL32(80, 220, 255, 255), 12, 2.0f);
            const float d = std::hypot(q->x - mouse.x, q->y - mouse.y);
            if (d < best) best = d, nearest = std::make_pair(r, k);
        }
    if (!editing_rivers_ || ImGui::GetIO().WantCaptureMouse) return;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) dragged_ = nearest;
    if (dragged_ && ImGui::IsMouseDown(ImGuiMouseButton_Left) && probe_) {
        if (!body_edit_) body_edit_ = *scene_;
        body_edit_->rivers[dragged_->first].path[dragged_->second] = {probe_->point.x, probe_->point.z};
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragged_.reset();
}

void Editor::draw_markers() {
    // Each marker bobs and tilts with hull_attitude, drawn as a cross over the frame.
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    for (const FloatingBody& m : markers_) {
        auto attitude = hull_attitude(*scene_, m, clock_.now());
        if (!attitude) continue;
        const glm::dvec3 centre{m.position.x, attitude->heave, m.position.y};
        // The mast tilts with pitch and roll.
        const glm::dvec3 mast =
            centre + 4.0 * glm::normalize(glm::dvec3(std::sin(attitude->pitch), 1.0, std::sin(attitude->roll)));
        const auto a = project(centre), b = project(mast);
        if (!a || !b) continue;
        draw->AddCircleFilled(*a, 5.0f, IM_COL32(255, 140, 0, 255));
        draw->AddLine(*a, *b, IM_COL32(255, 140, 0, 255), 2.0f);
    }
}

std::optional<ImVec2> Editor::project(glm::dvec3 p) const {
    const VkExtent2D e = viewport_rect(0, window_.extent()).extent;  // the left or only viewport's
    const render::Camera cam = camera_.camera();
    const glm::dvec3 forward = glm::normalize(cam.target - cam.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(0.5 * cam.fov_y_deg * 3.141592653589793 / 180.0);
    const glm::dvec3 d = p - cam.position;
    const double depth = glm::dot(d, forward);
    if (depth <= 0.1) return std::nullopt;
    const double x = glm::dot(d, right) / (depth * tan_half * e.width / e.height),
                 y = glm::dot(d, up) / (depth * tan_half);
    if (std::abs(x) > 1.0) return std::nullopt;  // not over another viewport
    return ImVec2(static_cast<float>((x + 1.0) * 0.5 * e.width), static_cast<float>((1.0 - y) * 0.5 * e.height));
}

}  // namespace tidewater::editor
