// tidewater render: frames of a scene as PNG, headless, with per-pass GPU times.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "atomic_file.hpp"
#include "scene_option.hpp"
#include "tidewater/image_io.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/standalone.hpp"
#include "time_range.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct RenderArgs {
    std::string scene;
    double time = 0.0;
    std::string size = "1280x720";
    std::string out;
    int frames = 1;
    double fps = 30.0;
    std::string out_dir;
    std::string view = "shaded";
    std::string stats;
    std::vector<double> camera, target;
    double fov = 0.0;
    bool validate = false;
};

Result<VkExtent2D> parse_size(const std::string& text) {
    const auto x = text.find('x');
    unsigned w = 0, h = 0;
    if (x != std::string::npos) {
        const auto a = std::from_chars(text.data(), text.data() + x, w);
        const auto b = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        if (a.ec == std::errc() && a.ptr == text.data() + x && b.ec == std::errc() && b.ptr == text.data() + text.size() &&
            w >= 16 && h >= 16 && w <= 8192 && h <= 8192)
            return VkExtent2D{w, h};
    }
    return Error{ErrorCode::invalid_argument, fmt::format("--size: \"{}\" is not WxH with 16 <= W, H <= 8192", text)};
}

/// The scene's camera, or one that frames the terrain from offshore.
render::Camera default_camera(const Scene& scene) {
    render::Camera cam;
    if (scene.camera) {
        cam.position = scene.camera->position;
        cam.target = scene.camera->target;
        cam.fov_y_deg = scene.camera->fov_y_deg;
        return cam;
    }
    const glm::dvec2 c = scene.terrain.extent_center();
    const double h = std::min(scene.terrain.extent_half_size(), 600.0);
    cam.target = {c.x, scene.water_level, c.y};
    cam.position = {c.x - 0.5 * h, scene.water_level + 0.12 * h + 8.0, c.y + 0.8 * h};
    return cam;
}

int run_render(const RenderArgs& a) {
    constexpr const char* verb = "render";
    auto extent = parse_size(a.size);
    if (!extent) return fail(verb, extent.error().message);
    if (auto st = check_time(a.time, "--time"); !st) return fail(verb, st.error().message);
    const auto view = render::parse_debug_view(a.view);
    if (!view) return fail(verb, fmt::format("--view: \"{}\" is not a view (shaded, height, normals, jacobian, depth, lod, wireframe)", a.view));
    if (a.frames < 1 || a.frames > 100000) return fail(verb, "--frames: must be in 1..100000");
    if (!(a.fps > 0.0 && a.fps <= 1000.0)) return fail(verb, "--fps: must be in (0, 1000]");
    if (a.frames == 1 && a.out.empty() && a.out_dir.empty()) return fail(verb, "give --out FILE.png (or --frames N --out-dir D)");
    if (a.frames > 1 && a.out_dir.empty()) return fail(verb, "--frames > 1 needs --out-dir");
    if (check_time(a.time + (a.frames - 1) / a.fps, "--time").ok() == false) return fail(verb, "--time: the sequence ends out of range");
    auto scene = load_scene_option(a.scene);
    if (!scene) return fail(verb, scene.error().message);

    render::FrameInfo frame;
    frame.camera = default_camera(*scene);
    if (!a.camera.empty()) frame.camera.position = {a.camera[0], a.camera[1], a.camera[2]};
    if (!a.target.empty()) frame.camera.target = {a.target[0], a.target[1], a.target[2]};
    if (a.fov != 0.0) frame.camera.fov_y_deg = a.fov;
    frame.view = *view;

    render::StandaloneOptions options;
    options.validation = a.validate;
    auto device = render::StandaloneDevice::create(options);
    if (!device) return fail(verb, device.error().message);
    render::RendererInitInfo init;
    init.device = (*device)->context();
    init.color_format = render::OffscreenTarget::kColorFormat;
    init.depth_format = render::OffscreenTarget::kDepthFormat;
    auto renderer = render::Renderer::create(init);
    if (!renderer) return fail(verb, renderer.error().message);
    if (auto st = (*renderer)->set_scene(*scene); !st) return fail(verb, st.error().message);
    auto target = render::OffscreenTarget::create((*device)->context(), extent->width, extent->height);
    if (!target) return fail(verb, target.error().message);
    if (!a.out_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(a.out_dir, ec);
        if (ec) return fail(verb, fmt::format("{}: cannot create folder: {}", a.out_dir, ec.message()));
    }

    nlohmann::json frame_stats = nlohmann::json::array();
    std::vector<std::string> written;
    for (int i = 0; i < a.frames; ++i) {
        frame.time = a.time + i / a.fps;
        frame.frame_index = static_cast<std::uint64_t>(i);
        auto image = (*target)->render(**renderer, frame);
        if (!image) return fail(verb, image.error().message);
        const std::string path = a.frames == 1 && !a.out.empty()
                                     ? a.out
                                     : (std::filesystem::path(a.out_dir) / fmt::format("frame_{:04}.png", i)).string();
        if (auto st = write_png_rgba8(path, image->width, image->height, image->pixels); !st) return fail(verb, st.error().message);
        written.push_back(path);
        if (auto t = (*renderer)->timings(frame.frame_index); t) {
            frame_stats.push_back({{"frame", i}, {"time_s", frame.time}, {"sky_and_terrain_ms", t->sky_and_terrain_ms},
                                   {"scene_copy_ms", t->scene_copy_ms}, {"water_ms", t->water_ms}, {"total_ms", t->total_ms}});
        }
    }
    if ((*device)->validation_messages() > 0) {
        return fail(verb, fmt::format("{} Vulkan validation message(s); see above", (*device)->validation_messages()));
    }
    if (!a.stats.empty()) {
        const render::RendererStats s = (*renderer)->stats();
        nlohmann::json j = {{"device", (*device)->device_name()},
                            {"size", {extent->width, extent->height}},
                            {"view", a.view},
                            {"frames", frame_stats},
                            {"counts", {{"terrain_vertices", s.terrain_vertices}, {"terrain_triangles", s.terrain_triangles},
                                        {"water_patches", s.water_patches}, {"waves", s.waves}}},
                            {"units", "milliseconds of GPU time from timestamp queries"}};
        AtomicFile file(a.stats);
        if (auto st = file.write_and_commit(j.dump(2) + "\n"); !st) return fail(verb, st.error().message);
    }
    std::printf("rendered %zu frame(s) of \"%s\" at %ux%u on %s: %s%s\n", written.size(), scene->name.c_str(), extent->width,
                extent->height, (*device)->device_name().c_str(), written.front().c_str(), written.size() > 1 ? " ..." : "");
    return 0;
}

}  // namespace

Verb add_render_verb(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to PNG (headless Vulkan)");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--time", args->time, "Clock time of the first frame, s")->capture_default_str();
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--out", args->out, "Output PNG of a single frame");
    cmd->add_option("--frames", args->frames, "Number of frames")->capture_default_str();
    cmd->add_option("--fps", args->fps, "Frames per second of a sequence")->capture_default_str();
    cmd->add_option("--out-dir", args->out_dir, "Folder for frame_NNNN.png");
    cmd->add_option("--view", args->view, "shaded, height, normals, jacobian, depth, lod or wireframe")->capture_default_str();
    cmd->add_option("--stats", args->stats, "Write per-pass GPU times, the device and counts as JSON");
    cmd->add_option("--camera", args->camera, "Camera position x y z, m")->expected(3);
    cmd->add_option("--target", args->target, "Camera target x y z, m")->expected(3);
    cmd->add_option("--fov", args->fov, "Vertical field of view, degrees");
    cmd->add_flag("--validate", args->validate, "Enable the Khronos validation layer; any message fails the run");
    return {cmd, [args] { return run_render(*args); }};
}

}  // namespace tidewater::cli
