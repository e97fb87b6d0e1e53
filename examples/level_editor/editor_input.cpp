// The viewport's mouse input: orbit, pan, zoom, the probe, markers and the terrain brush.
#include <cmath>

#include "editor.hpp"
#include "terrain_brush.hpp"

namespace tidewater::editor {

void Editor::viewport_input() {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_.window(), &x, &y);
    const double dx = x - last_drag_x_, dy = y - last_drag_y_;
    last_drag_x_ = x;
    last_drag_y_ = y;
    if (glfwGetMouseButton(window_.window(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) camera_.orbit(dx, dy);
    if (glfwGetMouseButton(window_.window(), GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS) camera_.pan(dx, dy);
    if (io.MouseWheel != 0.0f) camera_.zoom(io.MouseWheel);
    const VkExtent2D e = window_.extent();
    probe_ = probe_ray(*scene_, clock_.now(), camera_.position(), camera_.ray(x, y, e.width, e.height));
    if (brushing_) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && probe_) {
            const bool lower = ImGui::GetIO().KeyShift;
            paint({probe_->point.x, probe_->point.z}, (lower ? -1.0 : 1.0) * static_cast<double>(brush_height_));
        } else if (stroke_ && !bake_.running()) {
            // The stroke ended: the edited terrain is baked on a worker thread.
            Scene edited = *scene_;
            edited.terrain = *stroke_;
            stroke_.reset();
            bake_.start(std::move(edited), scene_);
        }
        return;
    }
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && probe_ && !probe_->on_land && !editing_rivers_) {
        FloatingBody marker = FloatingBody::four_point(6.0, 2.5);
        marker.position = {probe_->point.x, probe_->point.z};
        markers_.push_back(marker);
    }
}

void Editor::paint(glm::dvec2 at, double height) {
    // A stroke paints on its own copy; it is baked when the stroke ends.
    if (!stroke_) stroke_ = scene_->terrain.with_cuts({});
    stroke_ = brush_terrain(*stroke_, at, brush_radius_, height);
}

}  // namespace tidewater::editor
