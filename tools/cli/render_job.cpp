#include "render_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "tidewater/detail/atomic_sibling.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/image_write.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/standalone.hpp"
#include "tidewater/scene_floaters.hpp"

namespace tidewater::cli {

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
    cam.target = {c.x, scene.water_level(), c.y};
    cam.position = {c.x - 0.5 * h, scene.water_level() + 0.12 * h + 8.0, c.y + 0.8 * h};
    return cam;
}

Result<RenderResult> run_render_job(const Scene& scene, const RenderJob& job) {
    render::FrameInfo frame;
    frame.camera = job.camera.value_or(default_camera(scene));
    frame.view = job.view;
    if (job.sun_direction) frame.sun_direction = *job.sun_direction;
    frame.sky_turbidity = job.sky_turbidity;
    render::StandaloneOptions options;
    options.validation = job.validate;
    auto device = render::StandaloneDevice::create(options);
    if (!device) return device.error();
    render::RendererInitInfo init;
    init.device = (*device)->context();
    init.color_format = render::OffscreenTarget::kColorFormat;
    init.depth_format = render::OffscreenTarget::kDepthFormat;
    init.wireframe = init.device.enabled_features.fillModeNonSolid;  // the wireframe view where the device has it
    init.samples = job.samples;
    init.shade_water_per_sample = job.water_per_sample;
    init.gpu_memory_budget = job.gpu_memory_budget;
    init.quality = job.quality;
    init.quality_overrides = job.quality_overrides;
    auto renderer = render::Renderer::create(init);
    if (!renderer) return renderer.error();
    if (auto st = (*renderer)->set_scene(scene); !st) return st.error();
    auto target =
        render::OffscreenTarget::create((*device)->context(), job.extent.width, job.extent.height, job.samples);
    if (!target) return target.error();
    if (!job.output_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(job.output_dir, ec);
        if (ec)
            return Error{ErrorCode::io_error,
                         fmt::format("{}: cannot create folder: {}", job.output_dir, ec.message())};
    }
    // The scene's boats and floats riding the water, drawn at each frame's time.
    std::optional<SceneFloaters> floaters;
    if (!scene.boats.empty() || !scene.floats.empty()) {
        auto made = SceneFloaters::create(std::make_shared<const Scene>(scene), job.start_time);
        if (!made) return made.error();
        floaters = std::move(made).value();
    }
    // Split screen: the main view draws the left half, a second view the right half.
    std::vector<render::ViewFrame> views(1);
    if (job.split_camera) {
        auto right = (*renderer)->add_view({job.extent.width - job.extent.width / 2, job.extent.height});
        if (!right) return right.error();
        views.push_back({*right, {}, {}});
        views[0].targets.extent = {job.extent.width / 2, job.extent.height};
        views[1].targets.extent = {job.extent.width - job.extent.width / 2, job.extent.height};
        views[1].targets.offset = {static_cast<std::int32_t>(job.extent.width / 2), 0};
    } else {
        views[0].targets.extent = job.extent;
    }
    std::vector<render::FloatDraw> float_draws;
    RenderResult result;
    result.device = (*device)->device_name();
    nlohmann::json frames = nlohmann::json::array();
    for (int i = 0; i < job.frames; ++i) {
        frame.time = job.start_time + i / job.fps;
        frame.frame_index = static_cast<std::uint64_t>(i);
        if (floaters) {
            if (auto st = floaters->advance_to(frame.time); !st) return st.error();
            float_draws = render::float_draws(*floaters);
            frame.floats = float_draws;
        }
        views[0].frame = frame;
        if (job.split_camera) {
            views[1].frame = frame;
            views[1].frame.camera = *job.split_camera;
        }
        auto image = (*target)->render_views(**renderer, views);
        if (!image) return image.error();
        // Validation messages fail the job before anything is written for this frame.
        if ((*device)->validation_messages() > 0)
            return Error{ErrorCode::device_error,
                         fmt::format("{} Vulkan validation message(s); see above", (*device)->validation_messages())};
        const std::string path =
            job.frames == 1 && !job.single_output.empty()
                ? job.single_output
                : (std::filesystem::path(job.output_dir) / fmt::format("frame_{:04}.png", i)).string();
        detail::sweep_stale_siblings(path);  // what a killed render of this frame left
        if (auto st = detail::write_png_rgba8(path, image->width, image->height, image->pixels); !st) return st.error();
        result.files.push_back(path);
        if (auto t = (*renderer)->timings(frame.frame_index); t) {
            frames.push_back({{"frame", i},
                              {"time_s", frame.time},
                              {"sky_and_terrain_ms", t->sky_and_terrain_ms},
                              {"scene_copy_ms", t->scene_copy_ms},
                              {"water_ms", t->water_ms},
                              {"total_ms", t->total_ms}});
            if (t->invocations_counted) {
                auto counts = [&](const render::PassInvocations& c) {
                    nlohmann::json j{{"vertex", c.vertex},
                                     {"tessellation_patches", c.tessellation_patches},
                                     {"tessellation_evaluation", c.tessellation_evaluation},
                                     {"primitives", c.primitives},
                                     {"fragment", c.fragment}};
                    if (t->samples_counted) j["samples_passed"] = c.samples_passed;
                    return j;
                };
                frames.back()["invocations"] = {{"opaque", counts(t->opaque_invocations)},
                                                {"water", counts(t->water_invocations)}};
            }
            // Split screen: the second view's passes, timed apart from the first's.
            if (views.size() > 1)
                if (auto second = (*renderer)->timings(frame.frame_index, views[1].view); second)
                    frames.back()["second_view"] = {{"sky_and_terrain_ms", second->sky_and_terrain_ms},
                                                    {"scene_copy_ms", second->scene_copy_ms},
                                                    {"water_ms", second->water_ms},
                                                    {"total_ms", second->total_ms}};
        }
    }
    const render::RendererStats s = (*renderer)->stats();
    result.stats = {{"device", result.device},
                    {"size", {job.extent.width, job.extent.height}},
                    {"views", views.size()},
                    {"view", std::string(render::to_string(job.view))},
                    {"quality",
                     {{"tier", std::string(render::quality_name(job.quality))},
                      {"water_pixels_per_vertex", (*renderer)->quality().water_pixels_per_vertex},
                      {"water_max_foreshortening", (*renderer)->quality().water_max_foreshortening},
                      {"foam_lags", (*renderer)->quality().foam_lags},
                      {"reflection_facets", (*renderer)->quality().reflection_facets},
                      {"reflection_march_steps", (*renderer)->quality().reflection_march_steps},
                      {"far_field_ring_patches", (*renderer)->quality().far_field_ring_patches},
                      {"waves_drawn", (*renderer)->quality().waves_drawn},
                      {"scene_reflection", (*renderer)->quality().scene_reflection},
                      {"water_per_sample", (*renderer)->quality().water_per_sample},
                      {"caustics", (*renderer)->quality().caustics}}},
                    {"frames", frames},
                    {"counts",
                     {{"terrain_vertices", s.terrain_vertices},
                      {"terrain_triangles", s.terrain_triangles},
                      {"terrain_bytes", s.terrain_bytes},
                      {"shore_bytes", s.shore_bytes},
                      {"shore_stride", s.shore_stride},
                      {"shore_streamed_tiles", s.shore_streamed_tiles},
                      {"shore_streamable_tiles", s.shore_streamable_tiles},
                      {"water_patches", s.water_patches},
                      {"waves", s.waves}}},
                    {"units", "milliseconds of GPU time from timestamp queries"}};
    // The driver's statistics of every pipeline stage, where the device has them.
    if (auto stages = (*renderer)->pipeline_statistics(); stages) {
        for (const auto& st : *stages) {
            nlohmann::json stage{{"pipeline", st.pipeline}, {"stage", st.stage}};
            for (const auto& v : st.statistics) stage["statistics"][v.name] = v.value;
            result.stats["pipelines"].push_back(stage);
        }
    } else {
        result.stats["pipelines_unavailable"] = stages.error().message;
    }
    return result;
}

}  // namespace tidewater::cli
