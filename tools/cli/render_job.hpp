// Rendering a scene to PNG files on a standalone device: shared by the
// render and demo verbs.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tidewater/render/renderer.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::cli {

struct RenderJob {
    VkExtent2D extent{1280, 720};
    double start_time = 0.0;  ///< s
    int frames = 1;
    double fps = 30.0;
    render::DebugView view = render::DebugView::shaded;
    std::optional<render::Camera> camera;  ///< Default: the scene's camera or an offshore view.
    /// Split screen: the image's right half is a second view of the same frame from this
    /// camera, the left half the first camera's.
    std::optional<render::Camera> split_camera;
    std::string single_output;  ///< PNG path when frames == 1; else frame_NNNN.png in output_dir.
    std::string output_dir;
    bool validate = false;
    std::optional<glm::dvec3> sun_direction;                ///< Toward the sun; default FrameInfo's.
    double sky_turbidity = 2.5;                             ///< Preetham sky, in [1.7, 10].
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  ///< Multisampling (antialiased edges).
    bool water_per_sample = false;                          ///< RendererInitInfo::shade_water_per_sample (samples > 1).
    std::uint64_t gpu_memory_budget = render::RendererInitInfo{}.gpu_memory_budget;  ///< bytes
    render::Quality quality = render::Quality::high;
    render::QualityOverrides quality_overrides;
};

struct RenderResult {
    std::vector<std::string> files;
    std::string device;
    nlohmann::json stats;  ///< Device, size, per-frame pass times, counts.
};

/// The scene's camera, or one that frames the terrain from offshore.
render::Camera default_camera(const Scene& scene);

Result<RenderResult> run_render_job(const Scene& scene, const RenderJob& job);

}  // namespace tidewater::cli
