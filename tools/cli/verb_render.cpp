// tidewater render: frames of a scene as PNG, headless, with per-pass GPU times.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "atomic_file.hpp"
#include "extent_option.hpp"
#include "render_job.hpp"
#include "scene_option.hpp"
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
    std::vector<double> camera, target, split_camera;
    double fov = 0.0;
    std::vector<double> sun;
    double turbidity = 2.5;
    int samples = 1;
    bool water_per_sample = false;
    double gpu_memory_mib = 1024.0;
    std::string quality = "high";
    std::optional<double> water_pixels_per_vertex, water_max_foreshortening;
    std::optional<int> foam_lags, reflection_facets, reflection_march_steps, far_field_ring_patches, waves_drawn;
    std::optional<bool> scene_reflection, caustics;
    bool validate = false;
};

/// The debug views' names, "shaded, height, ...", from the renderer's own list.
std::string view_names() {
    std::string names;
    for (const auto view : render::all_debug_views())
        names += (names.empty() ? "" : ", ") + std::string(render::to_string(view));
    return names;
}

int run_render(const RenderArgs& a) {
    constexpr const char* verb = "render";
    auto extent = parse_extent(a.size, "--size");
    if (!extent) return fail(verb, extent.error().message);
    if (auto st = check_time(a.time, "--time"); !st) return fail(verb, st.error().message);
    const auto view = render::parse_debug_view(a.view);
    if (!view) return fail(verb, fmt::format("--view: \"{}\" is not a view ({})", a.view, view_names()));
    if (a.frames < 1 || a.frames > 100000) return fail(verb, "--frames: must be in 1..100000");
    if (!(a.fps > 0.0 && a.fps <= 1000.0)) return fail(verb, "--fps: must be in (0, 1000]");
    if (a.frames == 1 && a.out.empty() && a.out_dir.empty())
        return fail(verb, "give --out FILE.png (or --frames N --out-dir D)");
    if (a.frames > 1 && a.out_dir.empty()) return fail(verb, "--frames > 1 needs --out-dir");
    if (check_time(a.time + (a.frames - 1) / a.fps, "--time").ok() == false)
        return fail(verb, "--time: the sequence ends out of range");
    RenderJob job;
    job.extent = *extent;
    job.start_time = a.time;
    job.frames = a.frames;
    job.fps = a.fps;
    job.view = *view;
    job.validate = a.validate;
    job.single_output = a.frames == 1 ? a.out : std::string();
    job.output_dir = a.out_dir;
    if (!a.sun.empty()) {
        const glm::dvec3 sun{a.sun[0], a.sun[1], a.sun[2]};
        if (!std::isfinite(sun.x) || !std::isfinite(sun.y) || !std::isfinite(sun.z) || glm::length(sun) < 1e-9)
            return fail(verb, "--sun: the direction must be finite and non-zero");
        job.sun_direction = sun;
    }
    if (!(a.turbidity >= 1.7 && a.turbidity <= 10.0))
        return fail(verb, fmt::format("--turbidity: {} is out of range (1.7 to 10)", a.turbidity));
    job.sky_turbidity = a.turbidity;
    if (a.samples != 1 && a.samples != 2 && a.samples != 4 && a.samples != 8)
        return fail(verb, fmt::format("--samples: {} is not 1, 2, 4 or 8", a.samples));
    job.samples = static_cast<VkSampleCountFlagBits>(a.samples);
    if (a.water_per_sample && a.samples == 1) return fail(verb, "--water-per-sample: needs --samples 2, 4 or 8");
    job.water_per_sample = a.water_per_sample;
    if (!(a.gpu_memory_mib >= 16.0 && a.gpu_memory_mib <= 1048576.0))
        return fail(verb, fmt::format("--gpu-memory: {} MiB is out of range (16 to 1048576)", a.gpu_memory_mib));
    job.gpu_memory_budget = static_cast<std::uint64_t>(a.gpu_memory_mib * 1048576.0);
    const auto quality = render::quality_from_name(a.quality);
    if (!quality)
        return fail(verb, fmt::format("--quality: \"{}\" is not a tier (low, medium, high, ultra)", a.quality));
    job.quality = *quality;
    // One override at a time, so that a refusal names the flag that gave it.
    std::string refused;
    auto override_with = [&](auto& field, const auto& value, const char* flag) {
        if (!refused.empty()) return;
        field = value;
        if (auto st = render::quality_settings(job.quality, job.quality_overrides); !st)
            refused = fmt::format("{}: {}", flag, st.error().message);
    };
    render::QualityOverrides& o = job.quality_overrides;
    override_with(o.water_pixels_per_vertex, a.water_pixels_per_vertex, "--water-pixels-per-vertex");
    override_with(o.water_max_foreshortening, a.water_max_foreshortening, "--water-max-foreshortening");
    override_with(o.foam_lags, a.foam_lags, "--foam-lags");
    override_with(o.reflection_facets, a.reflection_facets, "--reflection-facets");
    override_with(o.reflection_march_steps, a.reflection_march_steps, "--reflection-march-steps");
    override_with(o.far_field_ring_patches, a.far_field_ring_patches, "--far-field-ring-patches");
    override_with(o.waves_drawn, a.waves_drawn, "--waves-drawn");
    override_with(o.scene_reflection, a.scene_reflection, "--scene-reflection");
    override_with(o.caustics, a.caustics, "--caustics");
    if (!refused.empty()) return fail(verb, refused);
    if (!a.split_camera.empty()) {
        for (double v : a.split_camera)
            if (!std::isfinite(v)) return fail(verb, "--split-camera: the six numbers must be finite");
        if (glm::length(glm::dvec3(a.split_camera[3] - a.split_camera[0], a.split_camera[4] - a.split_camera[1],
                                   a.split_camera[5] - a.split_camera[2])) < 1e-6)
            return fail(verb, "--split-camera: the position and the target must differ");
        if (extent->width < 32) return fail(verb, "--split-camera: the image needs at least 32 pixels across");
    }
    // Check the stats path before the bake and minutes of rendering.
    std::unique_ptr<AtomicFile> stats_file;
    if (!a.stats.empty()) {
        stats_file = std::make_unique<AtomicFile>(a.stats);
        if (!stats_file->status()) return fail(verb, stats_file->status().error().message);
    }
    // Every option checked: the scene's bake, which can take minutes, comes last.
    auto loaded = load_scene_option(a.scene);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();
    if (!a.camera.empty() || !a.target.empty() || a.fov != 0.0) {
        render::Camera cam = default_camera(*scene);
        if (!a.camera.empty()) cam.position = {a.camera[0], a.camera[1], a.camera[2]};
        if (!a.target.empty()) cam.target = {a.target[0], a.target[1], a.target[2]};
        if (a.fov != 0.0) cam.fov_y_deg = a.fov;
        job.camera = cam;
    }
    if (!a.split_camera.empty()) {
        render::Camera second = job.camera.value_or(default_camera(*scene));
        second.position = {a.split_camera[0], a.split_camera[1], a.split_camera[2]};
        second.target = {a.split_camera[3], a.split_camera[4], a.split_camera[5]};
        job.split_camera = second;
    }
    auto result = run_render_job(*scene, job);
    if (!result) return fail(verb, result.error().message);
    if (stats_file) {
        if (auto st = stats_file->write_and_commit(result->stats.dump(2) + "\n"); !st)
            return fail(verb, st.error().message);
    }
    std::printf("rendered %zu frame(s) of \"%s\" at %ux%u on %s: %s%s\n", result->files.size(), scene->name.c_str(),
                extent->width, extent->height, result->device.c_str(), result->files.front().c_str(),
                result->files.size() > 1 ? " ..." : "");
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
    cmd->add_option("--view", args->view, view_names())->capture_default_str();
    cmd->add_option("--stats", args->stats, "Write per-pass GPU times, the device and counts as JSON");
    cmd->add_option("--camera", args->camera, "Camera position x y z, m")->expected(3);
    cmd->add_option("--target", args->target, "Camera target x y z, m")->expected(3);
    cmd->add_option("--split-camera", args->split_camera,
                    "Split screen: the right half is a second view from x y z toward tx ty tz (m), "
                    "the left half the camera's")
        ->expected(6);
    cmd->add_option("--fov", args->fov, "Vertical field of view, degrees");
    cmd->add_option("--sun", args->sun, "Direction toward the sun x y z (y up)")->expected(3);
    cmd->add_option("--gpu-memory", args->gpu_memory_mib,
                    "Device memory the scene's data may take, MiB (16 or more): over it the terrain and the "
                    "shore fields are drawn coarser, the shore's tiles near the camera streamed in full")
        ->capture_default_str();
    cmd->add_option("--quality", args->quality, "Quality tier: low, medium, high or ultra (for stills)")
        ->capture_default_str();
    cmd->add_option("--water-pixels-per-vertex", args->water_pixels_per_vertex,
                    "Override the tier's spacing of the water's vertices on screen, pixels (1 to 32)");
    cmd->add_option("--water-max-foreshortening", args->water_max_foreshortening,
                    "Override how many times further apart the water's vertices may be along the view than across "
                    "it (1 to 100)");
    cmd->add_option("--foam-lags", args->foam_lags,
                    "Override how many of the crest foam's 0.5 s lags the water shows (0 to 4): how long whitecaps "
                    "linger");
    cmd->add_option("--reflection-facets", args->reflection_facets,
                    "Override the facets a pixel of water reflects over (4, or 1 at their mean slope)");
    cmd->add_option("--reflection-march-steps", args->reflection_march_steps,
                    "Override the steps of the march that finds the terrain a reflection meets (4 to 64)");
    cmd->add_option("--far-field-ring-patches", args->far_field_ring_patches,
                    "Override the patches per side of each ring of coarser water out to the horizon (even, 8 to 64)");
    cmd->add_option("--waves-drawn", args->waves_drawn,
                    "Override how many of each body's waves (its largest) the water draws one by one; the others "
                    "as roughness (0: all, else 1 to 1024)");
    cmd->add_option("--scene-reflection", args->scene_reflection,
                    "Override whether the water reflects the terrain and floats, not only the sky (true or false)");
    cmd->add_option("--caustics", args->caustics,
                    "Override whether the ground under shallow water shows caustics (true or false)");
    cmd->add_option("--samples", args->samples, "Samples per pixel (1, 2, 4 or 8): multisampling antialiases the edges")
        ->capture_default_str();
    cmd->add_flag(
        "--water-per-sample", args->water_per_sample,
        "Shade the water at every sample, its waves drawn for a sample's footprint: a grazing far field converges "
        "to the supersampled picture (about --samples times the water's cost)");
    cmd->add_option("--turbidity", args->turbidity,
                    "Air turbidity of the Preetham sky: 2 very clear, 3 clear, 6 hazy (1.7 to 10)")
        ->capture_default_str();
    cmd->add_flag("--validate", args->validate, "Enable the Khronos validation layer; any message fails the run");
    return {cmd, [args] { return run_render(*args); }};
}

}  // namespace tidewater::cli
