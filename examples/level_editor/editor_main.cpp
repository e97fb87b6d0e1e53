// tidewater-editor: a level-editor host of Tidewater on GLFW and Dear ImGui. The editor
// owns the instance, device and swapchain; Tidewater records each frame into the
// swapchain image, and ImGui draws its panels over it.
//
//   tidewater-editor [--scene S] [--size WxH] [--frames N --screenshot out.png]
//                    [--probe X,Y] [--script FILE] [--resize-at N] [--shader-dir DIR] [--no-validation]
//
// Panels: scene (open, save, errors), water (the ocean's preset, re-baked in the
// background), shore (breaking index, re-baked with progress), terrain (a brush), rivers
// and lakes (discharge, width, level; path points dragged in the viewport), time
// (pause, scale, scrub), view (debug views, GPU pass timings) and the probe.
// Viewport: right drag orbits, middle drag pans, the wheel zooms; a left click on the
// water drops a marker that bobs and tilts with hull_attitude.
// Hot reload (--shader-dir DIR, a copy of shaders/): a saved shader is compiled with
// the glslang library and swapped in without a device-wide wait; a failed compile shows
// its error (FILE:LINE) and the last good pipelines keep drawing. Each reload prints
// "shader reload: ok (N ms)" or "shader reload: FILE:LINE: message" on stderr.
// Scripted mode (--frames) draws N frames, writes the last one with its panels to
// --screenshot, prints the probe at pixel --probe, and exits (non-zero on any error or
// validation message).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <tidewater/render/renderer.hpp>
#include <tidewater/tidewater.hpp>

#include "editor_window.hpp"
#include "orbit_camera.hpp"
#include "shader_reload.hpp"
#include "surface_probe.hpp"
#include "terrain_brush.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::editor {

namespace {

struct Options {
    std::string scene, screenshot, script, shader_dir;
    int width = 1280, height = 720;
    long frames = -1, resize_at = -1;
    std::optional<glm::dvec2> probe;
    bool validation = true;
};

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (a == "--scene" && (v = next())) o.scene = v;
        else if (a == "--screenshot" && (v = next())) o.screenshot = v;
        else if (a == "--frames" && (v = next())) o.frames = std::atol(v);
        else if (a == "--resize-at" && (v = next())) o.resize_at = std::atol(v);
        else if (a == "--script" && (v = next())) o.script = v;
        else if (a == "--shader-dir" && (v = next())) o.shader_dir = v;
        else if (a == "--size" && (v = next())) {
            if (std::sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width < 320 || o.height < 240) return std::nullopt;
        } else if (a == "--probe" && (v = next())) {
            double x = 0, y = 0;
            if (std::sscanf(v, "%lf,%lf", &x, &y) != 2) return std::nullopt;
            o.probe = glm::dvec2(x, y);
        } else if (a == "--no-validation") o.validation = false;
        else return std::nullopt;
    }
    return o;
}

/// A bake running on a worker thread while the last good scene keeps drawing.
struct BackgroundBake {
    std::future<Result<std::shared_ptr<const Scene>>> job;
    std::atomic<double> fraction{0.0};
    std::mutex lock;
    std::string stage;

    bool running() const { return job.valid(); }
    void start(Scene edited, std::shared_ptr<const Scene> previous) {
        fraction = 0.0;
        job = std::async(std::launch::async, [this, edited = std::move(edited), previous = std::move(previous)] {
            SceneBakeOptions o;
            o.previous = previous;
            o.progress = [this](std::string_view s, double f) {
                fraction = f;
                const std::lock_guard<std::mutex> g(lock);
                stage = std::string(s);
            };
            return bake_scene(edited, o);
        });
    }
    /// The result once it is ready (the job is then over).
    std::optional<Result<std::shared_ptr<const Scene>>> ready() {
        if (!job.valid() || job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        return job.get();
    }
};

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
    std::optional<SceneFloaters> floaters_;      // the scene's boats and floats, riding the water
    std::vector<render::FloatDraw> float_draws_;  // this frame's
    void refloat();
    void float_bodies(render::FrameInfo& info);
    std::string scene_path_, message_;
    char path_field_[512] = {};
    OrbitCamera camera_;
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
    /// Script steps run at a given frame: "at N replace FILE|OLD|NEW", "at N screenshot PATH".
    struct Step {
        long frame = 0;
        std::string kind, argument;
    };
    std::vector<Step> steps_;
    bool force_reload_ = false;
    bool brushing_ = false;           // the Terrain panel's brush is on (left drag paints)
    float brush_radius_ = 60.0f, brush_height_ = 2.0f;
    std::optional<Terrain> stroke_;   // the terrain under the current stroke
    std::optional<std::pair<glm::dvec2, double>> scripted_brush_;  // where, and the ground there before
    void paint(glm::dvec2 at, double height);
    bool editing_rivers_ = false;          // the Rivers panel's point editing is on
    std::optional<std::pair<std::size_t, std::size_t>> dragged_;  // river, path point
    std::optional<Scene> body_edit_;       // rivers and lakes being edited, baked on release
    void bodies_panel();
    void drag_points();
    std::optional<ImVec2> project(glm::dvec3 p) const;
    Status run_step(const Step& step, std::string& screenshot);
};

Status Editor::load(const std::string& path) {
    auto parsed = path.empty() ? default_scene() : load_scene(path);
    if (!parsed) return parsed.error();
    auto baked = bake_scene(*parsed);
    if (!baked) return baked.error();
    scene_ = std::move(baked).value();
    floaters_.reset();
    refloat();
    scene_path_ = path;
    std::snprintf(path_field_, sizeof path_field_, "%s", path.c_str());
    breaking_index_ = static_cast<float>(scene_->shore.breaking_index);
    const auto presets = bundled_preset_names();
    const auto at = std::find(presets.begin(), presets.end(), scene_->ocean.profile().name);
    preset_ = at == presets.end() ? 0 : static_cast<int>(at - presets.begin());
    if (scene_->camera) camera_ = OrbitCamera::looking(scene_->camera->position, scene_->camera->target, scene_->camera->fov_y_deg);
    if (renderer_)
        if (auto st = renderer_->set_scene(*scene_); !st) return st;
    return {};
}

void Editor::swap_in(Result<std::shared_ptr<const Scene>> baked) {
    if (!baked) {
        message_ = baked.error().message;
        return;
    }
    // Between frames: the renderer waits for the frames in flight and uploads.
    if (auto st = renderer_->set_scene(**baked); !st) {
        message_ = st.error().message;
        return;
    }
    scene_ = std::move(baked).value();
    refloat();
    message_ = fmt::format("re-baked in {:.2f} s ({} river(s) and {} lake shore(s) reused)", scene_->bake->seconds,
                           scene_->bake->reused.rivers, scene_->bake->reused.lake_shores);
}

// The scene's boats and floats: carried on over an edited scene with the same ones, set
// afloat again otherwise (a failure is shown, and they are not drawn).
void Editor::refloat() {
    if (scene_->boats.empty() && scene_->floats.empty()) {
        floaters_.reset();
        return;
    }
    if (floaters_ && floaters_->set_scene(scene_)) return;
    auto made = SceneFloaters::create(scene_, clock_.now());
    if (!made) {
        message_ = made.error().message;
        floaters_.reset();
        return;
    }
    floaters_ = std::move(made).value();
}

// Advances the boats and floats to the clock (set afloat again when the clock went back
// or jumped a minute ahead) and hands them to the frame.
void Editor::float_bodies(render::FrameInfo& info) {
    if (!floaters_) return;
    const double now = clock_.now();
    if (now < floaters_->time() - 1e-6 || now > floaters_->time() + 60.0) {
        floaters_.reset();
        refloat();
        if (!floaters_) return;
    }
    if (auto st = floaters_->advance_to(now); !st) {
        message_ = st.error().message;
        floaters_.reset();
        return;
    }
    float_draws_ = render::float_draws(*floaters_);
    info.floats = float_draws_;
}

void Editor::choose_preset(const std::string& name) {
    auto profile = load_preset(name);
    auto body = profile ? WaterBody::create(*profile, scene_->water_level(), "ocean") : Result<WaterBody>(profile.error());
    if (!body) {
        message_ = body.error().message;
        return;
    }
    // A preset change keeps the surf: the shore model is baked again in the background.
    Scene edited = *scene_;
    edited.ocean = std::move(body).value();
    bake_.start(std::move(edited), scene_);
}

// A script for CI and pictures, one command a line:
//   camera PX PY PZ TX TY TZ [FOV]     view NAME     preset NAME     probe X Y     time T
//   brush X Z RADIUS HEIGHT     (a stroke of the terrain brush, re-baked in the background)
//   river NAME discharge Q      (as the Rivers panel's slider, re-baked in the background)
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
        auto bad = [&] { return Error{ErrorCode::parse_error, fmt::format("{}:{}: cannot read \"{}\"", path, number, line)}; };
        if (command == "camera") {
            glm::dvec3 p, t;
            double fov = camera_.fov_y_deg;
            if (!(words >> p.x >> p.y >> p.z >> t.x >> t.y >> t.z)) return bad();
            words >> fov;
            camera_ = OrbitCamera::looking(p, t, fov);
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
            const auto it = std::find_if(edited.rivers.begin(), edited.rivers.end(), [&](const SceneRiver& r) { return r.name == name; });
            if (it == edited.rivers.end()) return bad();
            it->discharge = value;
            bake_.start(std::move(edited), scene_);
        } else if (command == "at") {
            Step step;
            if (!(words >> step.frame >> step.kind) || (step.kind != "replace" && step.kind != "screenshot")) return bad();
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
        return Error{ErrorCode::parse_error, fmt::format("editor: replace needs FILE|OLD|NEW, got \"{}\"", step.argument)};
    const std::filesystem::path file = std::filesystem::path(shader_dir_) / step.argument.substr(0, bar);
    const std::string old_text = step.argument.substr(bar + 1, bar2 - bar - 1), new_text = step.argument.substr(bar2 + 1);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    const auto at = source.find(old_text);
    if (!in || at == std::string::npos) return Error{ErrorCode::not_found, fmt::format("editor: {}: \"{}\" not found", file.string(), old_text)};
    source.replace(at, old_text.size(), new_text);
    std::ofstream(file, std::ios::trunc) << source;
    force_reload_ = true;
    return {};
}

void Editor::paint(glm::dvec2 at, double height) {
    // A stroke paints on its own copy; it is baked when the stroke ends.
    if (!stroke_) stroke_ = scene_->terrain.with_cuts({});
    stroke_ = brush_terrain(*stroke_, at, brush_radius_, height);
}

std::optional<ImVec2> Editor::project(glm::dvec3 p) const {
    const VkExtent2D e = window_.extent();
    const render::Camera cam = camera_.camera();
    const glm::dvec3 forward = glm::normalize(cam.target - cam.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(0.5 * cam.fov_y_deg * 3.141592653589793 / 180.0);
    const glm::dvec3 d = p - cam.position;
    const double depth = glm::dot(d, forward);
    if (depth <= 0.1) return std::nullopt;
    const double x = glm::dot(d, right) / (depth * tan_half * e.width / e.height), y = glm::dot(d, up) / (depth * tan_half);
    return ImVec2(static_cast<float>((x + 1.0) * 0.5 * e.width), static_cast<float>((1.0 - y) * 0.5 * e.height));
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
        if (ImGui::SliderFloat(fmt::format("lake \"{}\" level (m)", edited.lakes[l].name).c_str(), &level, -50.0f, 500.0f, "%.2f")) {
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
        const glm::dvec3 mast = centre + 4.0 * glm::normalize(glm::dvec3(std::sin(attitude->pitch), 1.0, std::sin(attitude->roll)));
        const auto a = project(centre), b = project(mast);
        if (!a || !b) continue;
        draw->AddCircleFilled(*a, 5.0f, IM_COL32(255, 140, 0, 255));
        draw->AddLine(*a, *b, IM_COL32(255, 140, 0, 255), 2.0f);
    }
}

Status Editor::start(const Options& options) {
    if (auto st = window_.create(options.width, options.height, options.validation); !st) return st;
    render::RendererInitInfo init;
    init.device = window_.context();
    init.color_format = window_.color_format();
    init.depth_format = EditorWindow::kDepthFormat;
    init.frames_in_flight = EditorWindow::kFramesInFlight;
    init.wireframe = init.device.enabled_features.fillModeNonSolid;
    auto renderer = render::Renderer::create(init);
    if (!renderer) return renderer.error();
    renderer_ = std::move(renderer).value();
    if (auto st = load(options.scene); !st) return st;
    if (auto st = renderer_->resize(window_.extent()); !st) return st;
    if (!options.shader_dir.empty()) {
        if (!std::filesystem::is_directory(options.shader_dir))
            return Error{ErrorCode::io_error, fmt::format("editor: --shader-dir {}: not a folder", options.shader_dir)};
        shader_dir_ = options.shader_dir;
        shaders_ = std::make_unique<ShaderReload>(options.shader_dir);
        shaders_->changed();  // the first look records the files
    }

    // Dear ImGui over the same device, in the editor's own render pass.
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window_.window(), true);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 16;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = sizes;
    const render::DeviceContext ctx = window_.context();
    if (vkCreateDescriptorPool(ctx.device, &pool, nullptr, &imgui_pool_) != VK_SUCCESS)
        return Error{ErrorCode::device_error, "editor: cannot create ImGui's descriptor pool"};
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance;
    info.PhysicalDevice = ctx.physical_device;
    info.Device = ctx.device;
    info.QueueFamily = ctx.queue_family;
    info.Queue = ctx.queue;
    info.DescriptorPool = imgui_pool_;
    info.MinImageCount = 2;
    info.ImageCount = std::max(2u, window_.image_count());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    if (!ImGui_ImplVulkan_Init(&info, window_.ui_pass())) return Error{ErrorCode::device_error, "editor: ImGui's Vulkan backend failed"};
    // The font texture, uploaded once through a one-off command buffer.
    VkCommandPool upload_pool = VK_NULL_HANDLE;
    VkCommandPoolCreateInfo cp{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cp.queueFamilyIndex = ctx.queue_family;
    vkCreateCommandPool(ctx.device, &cp, nullptr, &upload_pool);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = upload_pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vkAllocateCommandBuffers(ctx.device, &ai, &cmd);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    ImGui_ImplVulkan_CreateFontsTexture(cmd);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    vkQueueSubmit(ctx.queue, 1, &submit, VK_NULL_HANDLE);
    vkQueueWaitIdle(ctx.queue);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    vkDestroyCommandPool(ctx.device, upload_pool, nullptr);
    return {};
}

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
            const std::string dir = std::string(path_field_).empty() ? "tidewater-bake" : std::string(path_field_) + ".bake";
            auto st = save_scene_bake(dir, *scene_);
            message_ = st ? fmt::format("saved the bake to {}/", dir) : st.error().message;
        }
    }
    if (ImGui::CollapsingHeader("Water", ImGuiTreeNodeFlags_DefaultOpen)) {
        const auto names = bundled_preset_names();
        std::vector<const char*> items;
        for (const auto& n : names) items.push_back(n.c_str());
        if (ImGui::Combo("ocean preset", &preset_, items.data(), static_cast<int>(items.size())) && !bake_.running())
            choose_preset(names[static_cast<std::size_t>(preset_)]);
        ImGui::Text("%zu waves, Hs %.2f m", scene_->ocean.waves().size(), scene_->ocean.waves().significant_wave_height());
    }
    if (ImGui::CollapsingHeader("Shore", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::SliderFloat("breaking index", &breaking_index_, 0.3f, 1.2f, "%.2f");
        if (ImGui::Button("Re-bake shore") && !bake_.running()) {
            Scene edited = *scene_;
            edited.shore.bake_folder.clear();
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
        ImGui::Text("GPU: terrain %.2f ms, copy %.2f ms, water %.2f ms", timings_.sky_and_terrain_ms, timings_.scene_copy_ms,
                    timings_.water_ms);
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
    if (shaders_ && ImGui::CollapsingHeader("Shaders", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (shaders_->error().empty()) ImGui::TextWrapped("%s", shader_line_.empty() ? "watching for changes" : shader_line_.c_str());
        else ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", shaders_->error().c_str());
    }
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    ImGui::End();
}

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

int Editor::run(const Options& options) {
    if (auto st = start(options); !st) {
        std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
        return 1;
    }
    if (!options.script.empty())
        if (auto st = run_script(options.script); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            return 1;
        }
    if (options.probe) script_probe_ = options.probe;
    bool ok = true;
    auto last = std::chrono::steady_clock::now();
    double frame_seconds = 0.0;
    long timed_frames = 0;
    for (long i = 0; !glfwWindowShouldClose(window_.window()) && (options.frames < 0 || i < options.frames); ++i) {
        glfwPollEvents();
        if (i == options.resize_at) glfwSetWindowSize(window_.window(), options.width * 3 / 4, options.height * 3 / 4);
        // In scripted mode a re-bake completes before the frames go on (the picture is of it).
        if (options.frames >= 0 && bake_.running()) bake_.job.wait();
        if (auto done = bake_.ready()) swap_in(std::move(*done));
        const auto frame_start = std::chrono::steady_clock::now();
        std::string step_screenshot;
        for (const Step& step : steps_)
            if (step.frame == i)
                if (auto st = run_step(step, step_screenshot); !st) {
                    std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
                    ok = false;
                }
        if (shaders_ && (shaders_->changed() || force_reload_)) {
            // A saved shader: compiled and swapped in before this frame records.
            force_reload_ = false;
            shader_line_ = shaders_->reload(*renderer_);
            std::fprintf(stderr, "%s\n", shader_line_.c_str());
        }
        const auto now = std::chrono::steady_clock::now();
        clock_.advance(options.frames < 0 ? std::chrono::duration<double>(now - last).count() : 1.0 / 60.0);
        last = now;
        EditorWindow::Frame frame;
        auto begun = window_.begin_frame(frame, [&](VkExtent2D extent) { return renderer_->resize(extent); });
        if (!begun) {
            std::fprintf(stderr, "tidewater-editor: %s\n", begun.error().message.c_str());
            ok = false;
            break;
        }
        if (!*begun) continue;  // the swapchain was rebuilt
        // The slot's previous frame has finished (begin_frame waited for it): its GPU times.
        if (frame.index >= EditorWindow::kFramesInFlight)
            if (auto t = renderer_->timings(frame.index - EditorWindow::kFramesInFlight); t) timings_ = *t;
        ImGui_ImplVulkan_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        viewport_input();
        if (script_probe_) {
            const VkExtent2D e = window_.extent();
            probe_ = probe_ray(*scene_, clock_.now(), camera_.position(), camera_.ray(script_probe_->x, script_probe_->y, e.width, e.height));
        }
        panels();
        drag_points();
        draw_markers();
        ImGui::Render();
        render::FrameInfo info;
        info.camera = camera_.camera();
        info.time = clock_.now();
        info.frame_index = frame.index;
        info.view = render::all_debug_views()[static_cast<std::size_t>(view_)];
        float_bodies(info);
        const render::FrameTargets targets{frame.color, frame.color_view, frame.depth, frame.depth_view, window_.extent()};
        if (auto st = renderer_->record_frame(frame.cmd, info, targets); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            ok = false;
        }
        VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        rp.renderPass = window_.ui_pass();
        rp.framebuffer = frame.framebuffer;
        rp.renderArea = {{0, 0}, window_.extent()};
        vkCmdBeginRenderPass(frame.cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
        ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), frame.cmd);
        vkCmdEndRenderPass(frame.cmd);
        const bool last_frame = options.frames > 0 && i + 1 == options.frames;
        if (last_frame && !options.screenshot.empty()) step_screenshot = options.screenshot;
        if (auto st = window_.end_frame(frame, step_screenshot); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            ok = false;
        }
        if (!step_screenshot.empty()) std::printf("wrote %s\n", step_screenshot.c_str());
        if (i >= 2 && !last_frame) {  // past the first frames' pipeline warm-up
            frame_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count();
            ++timed_frames;
        }
    }
    if (timed_frames > 0) std::printf("frame time: %.1f ms mean over %ld frames\n", 1000.0 * frame_seconds / static_cast<double>(timed_frames), timed_frames);
    if (scripted_brush_)
        std::printf("terrain at the brush (%.1f, %.1f): %.3f m, was %.3f m\n", scripted_brush_->first.x, scripted_brush_->first.y,
                    scene_->terrain.height_at(scripted_brush_->first), scripted_brush_->second);
    std::printf("window %ux%u, ocean \"%s\" with%s a shore model\n", window_.extent().width, window_.extent().height,
                scene_->ocean.profile().name.c_str(), scene_->ocean.shore() ? "" : "out");
    if (!message_.empty()) std::printf("%s\n", message_.c_str());
    if (script_probe_ && probe_) {
        const SurfacePoint direct = query_world_point(*scene_, clock_.now(), {probe_->point.x, probe_->point.z}).surface;
        std::printf("probe: (%.3f, %.3f) height %.6f m, query_surface %.6f m, body \"%s\"%s\n", probe_->point.x, probe_->point.z,
                    probe_->point.y, direct.height, std::string(body_name(*scene_, probe_->water.body)).c_str(),
                    probe_->on_land ? " (land)" : "");
        std::printf("terrain at the probe: %.3f m\n", scene_->terrain.height_at({probe_->point.x, probe_->point.z}));
        std::printf("gpu: terrain %.3f ms, copy %.3f ms, water %.3f ms, total %.3f ms\n", timings_.sky_and_terrain_ms,
                    timings_.scene_copy_ms, timings_.water_ms, timings_.total_ms);
    }
    if (bake_.running()) bake_.job.wait();
    vkDeviceWaitIdle(window_.context().device);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(window_.context().device, imgui_pool_, nullptr);
    renderer_.reset();
    const int messages = window_.validation_messages();
    window_.destroy();
    if (messages > 0) {
        std::fprintf(stderr, "tidewater-editor: %d validation message(s)\n", messages);
        ok = false;
    }
    return ok ? 0 : 1;
}

}  // namespace

}  // namespace tidewater::editor

int main(int argc, char** argv) {
    const auto options = tidewater::editor::parse(argc, argv);
    if (!options) {
        std::fprintf(stderr, "usage: tidewater-editor [--scene S] [--size WxH] [--frames N --screenshot out.png] [--probe X,Y] "
                             "[--script FILE] [--resize-at N] [--shader-dir DIR] [--no-validation]\n");
        return 2;
    }
    tidewater::editor::Editor editor;
    return editor.run(*options);
}
