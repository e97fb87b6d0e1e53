// The viewports: one, or two side by side (each a renderer view of its own), and the mouse
// input over them: orbit, pan, zoom, the probe, markers and the terrain brush.
#include <algorithm>
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
    // The viewport under the cursor: its camera moves, and the probe's ray is through it.
    const VkRect2D right = viewport_rect(1, window_.extent());
    const bool over_right = second_view_ && x >= right.offset.x;
    OrbitCamera& camera = over_right ? second_camera_ : camera_;
    const VkRect2D rect = over_right ? right : viewport_rect(0, window_.extent());
    if (glfwGetMouseButton(window_.window(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) camera.orbit(dx, dy);
    if (glfwGetMouseButton(window_.window(), GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS) camera.pan(dx, dy);
    if (io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);
    probe_ = probe_ray(*scene_, clock_.now(), camera.position(),
                       camera.ray(x - rect.offset.x, y - rect.offset.y, rect.extent.width, rect.extent.height));
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

VkRect2D Editor::viewport_rect(int which, VkExtent2D window) const {
    if (!two_viewports_) return {{0, 0}, window};
    const std::uint32_t left = std::max(window.width / 2, 1u);
    if (which == 0) return {{0, 0}, {left, window.height}};
    return {{static_cast<std::int32_t>(left), 0}, {std::max(window.width - left, 1u), window.height}};
}

Status Editor::lay_out_views(VkExtent2D window) {
    if (two_viewports_ && !second_view_) {
        if (!second_camera_set_) {
            // The second viewport starts a quarter turn round the first one's target.
            second_camera_ = camera_;
            second_camera_.yaw += 0.5 * 3.141592653589793;
            second_camera_set_ = true;
        }
        auto added = renderer_->add_view(viewport_rect(1, window).extent);
        if (!added) return added.error();
        second_view_ = *added;
    } else if (!two_viewports_ && second_view_) {
        if (auto st = renderer_->remove_view(*second_view_); !st) return st;
        second_view_.reset();
    }
    // No wait in either: the renderer keeps what frames in flight read until they are done.
    if (auto st = renderer_->resize(viewport_rect(0, window).extent); !st) return st;
    if (second_view_) return renderer_->resize(viewport_rect(1, window).extent, *second_view_);
    return {};
}

void Editor::paint(glm::dvec2 at, double height) {
    // A stroke paints on its own copy; it is baked when the stroke ends.
    if (!stroke_) stroke_ = scene_->terrain.with_cuts({});
    stroke_ = brush_terrain(*stroke_, at, brush_radius_, height);
}

}  // namespace tidewater::editor
