// The editor's state and the jobs of its parts, each defined in a file of its own:
// editor_main.cpp (start-up and the frame loop), editor_scene.cpp (loading, baked scenes
// swapped in, floating bodies, presets, clip volumes), editor_script.cpp (the script runner),
// editor_panels.cpp (the ImGui panels and overlays), editor_input.cpp (the viewports
// laid out, their input and the terrain brush).
#pragma once

#include <imgui.h>

#include <memory>
#include <optional>
#include <string>
#include <tidewater/render/renderer.hpp>
#include <tidewater/tidewater.hpp>
#include <utility>
#include <vector>

#include "bake_worker.hpp"
#include "editor_options.hpp"
#include "editor_script_parse.hpp"
#include "editor_window.hpp"
#include "orbit_camera.hpp"
#include "shader_reload.hpp"
#include "surface_probe.hpp"

namespace tidewater::editor {

/// The editor: its window, renderer, scene and panels. One per process; every member
/// function runs on the main thread (the bake worker reports through BackgroundBake).
class Editor {
  public:
    int run(const Options& options);

  private:
    Status start(const Options& options);
    Status load(const std::string& path);
    void panels();
    void viewport_input();
    void swap_in(Result<std::shared_ptr<const Scene>> baked);
    Status run_script(const std::string& path);
    void choose_preset(const std::string& name);
    void draw_markers();

    EditorWindow window_;
    std::unique_ptr<render::Renderer> renderer_;
    VkDescriptorPool imgui_pool_ = VK_NULL_HANDLE;
    std::shared_ptr<const Scene> scene_;
    std::optional<SceneFloaters> floaters_;       // the scene's boats and floats, riding the water
    std::vector<render::FloatDraw> float_draws_;  // this frame's
    void refloat();
    void float_bodies(render::FrameInfo& info);
    std::string scene_path_, message_;
    char path_field_[512] = {};
    OrbitCamera camera_;  // the viewport's, or the left one's with two viewports
    // Two viewports side by side (the View panel; "viewports 2" or "second ..." in a script):
    // the left one is camera_'s through the renderer's main view, the right one
    // second_camera_'s through a view of its own; the mouse drives the one it is over.
    bool two_viewports_ = false;
    OrbitCamera second_camera_;
    bool second_camera_set_ = false;
    std::optional<render::ViewId> second_view_;
    render::PassTimings second_timings_{};
    /// Adds or removes the second view as the layout asks and sizes the views for `window`.
    Status lay_out_views(VkExtent2D window);
    /// Viewport `which` (0: the left or only one, 1: the right one) of a `window`-sized frame.
    VkRect2D viewport_rect(int which, VkExtent2D window) const;
    Clock clock_;
    float time_scale_ = 1.0f;
    int view_ = 0, preset_ = 0;
    float breaking_index_ = 0.78f;
    BackgroundBake bake_;
    std::optional<ProbeHit> probe_;
    std::vector<FloatingBody> markers_;  // dropped with a left click; they ride the water
    render::PassTimings timings_{};
    double last_drag_x_ = 0.0, last_drag_y_ = 0.0;
    std::optional<glm::dvec2> script_probe_;
    std::unique_ptr<ShaderReload> shaders_;
    std::string shader_dir_;
    std::string shader_line_;
    /// The script's lines that run at a given frame ("at N ..."), and the script's path.
    std::vector<ScriptLine> scheduled_;
    std::string script_path_;
    /// After the first re-bake swapped in, and how many were: the soak's memory report.
    struct MemoryMark {
        std::uint64_t resident_bytes = 0, device_bytes = 0, heap_bytes = 0;
    };
    std::optional<MemoryMark> after_first_rebake_;
    int rebakes_ = 0;
    bool memory_log_ = false;  // --memory-log: the memory after each re-bake
    bool ready_edits_ = true;  // not --keep-saved-bake: a saved bake opened is baked again for local edits
    MemoryMark memory_now() const;
    bool force_reload_ = false;
    bool brushing_ = false;  // the Terrain panel's brush is on (left drag paints)
    float brush_radius_ = 60.0f, brush_height_ = 2.0f;
    std::optional<Terrain> stroke_;                                // the terrain under the current stroke
    std::optional<std::pair<glm::dvec2, double>> scripted_brush_;  // where, and the ground there before
    void paint(glm::dvec2 at, double height);
    bool editing_rivers_ = false;                                 // the Rivers panel's point editing is on
    std::optional<std::pair<std::size_t, std::size_t>> dragged_;  // river, path point
    std::optional<Scene> body_edit_;                              // rivers and lakes being edited, baked on release
    void bodies_panel();
    std::vector<ClipVolume> clip_volumes_;  // placed in the Clip volumes panel: no water inside
    float clip_radius_ = 6.0f;
    void clip_panel();
    void place_clip(glm::dvec3 at, double radius);
    void drag_points();
    std::optional<ImVec2> project(glm::dvec3 p) const;
    /// One script line, as the panel it stands for would; a screenshot step names the file
    /// the frame is written to.
    Status run_command(const ScriptLine& line, std::string& screenshot);
    Status run_step(const ScriptStep& step, std::string& screenshot);
};

}  // namespace tidewater::editor
