// The renderer's pipelines (private): its descriptor set and pipeline layouts, the
// sky, terrain and water pipelines (dynamic rendering, SPIR-V from the embedded
// shaders) and its samplers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string_view>

#include "tidewater/render/quality.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/result.hpp"
#include "vk_handle.hpp"

namespace tidewater::render::detail {

/// SPIR-V of a shader by source name ("water.frag"); empty: the embedded one.
using ShaderLookup = std::function<std::span<const std::uint32_t>(std::string_view name)>;

/// What the quality tier chooses for the water's and the terrain's shaders: their
/// specialization constants (gpu::kSpec*, water_quality.glsl). The defaults are the
/// shaders' own (`ultra`'s).
struct WaterShading {
    std::uint32_t foam_lags = 4;
    std::uint32_t reflection_facets = 4;
    std::int32_t reflection_steps = 24;
    float reflection_step_growth = 1.25f;
    std::uint32_t scene_reflection = 1;  ///< VkBool32
    std::uint32_t caustics = 1;          ///< VkBool32 (terrain.frag)
    std::uint32_t waves_capped = 0;      ///< VkBool32: QualitySettings::waves_drawn > 0

    static WaterShading from(const QualitySettings& q);
};

struct PipelineDesc {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;       // the targets' (multisampling)
    std::string_view vertex, tess_control, tess_eval, fragment;  // embedded shader names; tess ones optional
    /// mesh: position + normal, 24-byte stride (floating bodies); terrain_patch: the patch's
    /// grid vertices (vec2) and, per instance, a GpuTerrainNode.
    enum class Vertices { none, mesh, terrain_patch } vertices = Vertices::none;
    bool depth_write = true;
    bool depth_test = true;  ///< false: every fragment passes (a full-screen pass over a depth copy)
    VkPolygonMode polygon_mode = VK_POLYGON_MODE_FILL;
    ShaderLookup shaders;                 ///< overrides of the embedded SPIR-V (hot reload); null: none
    const WaterShading* water = nullptr;  ///< the water shaders' specialization; null: their defaults
};

Result<VkPipeline> create_pipeline(const Device& ctx, const PipelineDesc& desc);

/// The graphics pipelines of a frame, over the frame's layouts. Wireframe pipelines exist
/// only when asked for (they need fillModeNonSolid).
struct DrawPipelines {
    OwnedPipeline sky, terrain, terrain_wire, floats, water, water_wire;
    OwnedPipeline host_light;  ///< the host's geometry under the water (host_light.frag)
};

/// What the draw pipelines are made for: the targets' formats and samples, and the water's shading.
struct DrawOptions {
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    /// The water's fragment shader is water_per_sample.frag (shaded at every sample;
    /// RendererInitInfo::shade_water_per_sample).
    bool water_per_sample = false;
    bool wireframe = false;
    WaterShading water;
};

/// The quality a renderer draws at on its device: the tier's settings with the host's
/// overrides, the water shaded per sample where the host asked for it (refused where the
/// targets are single-sampled or sampleRateShading is off) or where the tier wishes it and
/// both allow it.
Result<QualitySettings> drawn_quality(const RendererInitInfo& init, const Device& ctx);
/// The draw pipelines' options for `init` at `quality` (drawn_quality).
DrawOptions draw_options_for(const RendererInitInfo& init, const QualitySettings& quality);

/// Everything a frame's draws bind, made once per renderer: the layout of set
/// gpu::kFrameSet (kFrameSetRows) and the push constants of host_device.h.
struct FramePipelines {
    OwnedSetLayout set_layout;
    OwnedPipelineLayout layout;
    DrawPipelines draws;
    OwnedSampler linear, nearest;
    OwnedSampler linear_repeat;  ///< for tables that tile (the foam's noise)

    static Result<FramePipelines> create(const Device& ctx, const DrawOptions& options);
    /// The draw pipelines over this object's layouts, from the embedded SPIR-V or `shaders`.
    Result<DrawPipelines> make_draws(const Device& ctx, const DrawOptions& options, const ShaderLookup& shaders) const;
};

}  // namespace tidewater::render::detail
