#include "render_pipelines.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <vector>

#include "descriptor_sets.hpp"
#include "embedded_shaders.hpp"
#include "host_device.h"
#include "vk_util.hpp"

namespace tidewater::render::detail {

namespace {

Result<OwnedShaderModule> make_module(const Device& ctx, std::string_view name, const ShaderLookup& shaders) {
    std::span<const std::uint32_t> spirv = shaders ? shaders(name) : std::span<const std::uint32_t>();
    if (spirv.empty()) spirv = embedded_spirv(name);
    if (spirv.empty()) return Error{ErrorCode::not_found, fmt::format("shader {} is not embedded in this build", name)};
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    OwnedShaderModule module;
    TW_VK_TRY(make_owned(ctx, module, [&](VkShaderModule* out) {
        return ctx.vk().CreateShaderModule(ctx.device, &info, ctx.allocator, out);
    }));
    return module;
}

}  // namespace

WaterShading WaterShading::from(const QualitySettings& q) {
    WaterShading w;
    w.foam_lags = static_cast<std::uint32_t>(q.foam_lags);
    w.reflection_facets = static_cast<std::uint32_t>(q.reflection_facets);
    w.reflection_steps = q.reflection_march_steps;
    w.reflection_step_growth = static_cast<float>(render::reflection_step_growth(q.reflection_march_steps));
    w.scene_reflection = q.scene_reflection ? VK_TRUE : VK_FALSE;
    w.caustics = q.caustics ? VK_TRUE : VK_FALSE;
    w.waves_capped = q.waves_drawn > 0 ? VK_TRUE : VK_FALSE;
    return w;
}

Result<QualitySettings> drawn_quality(const RendererInitInfo& init, const Device& ctx) {
    auto quality = quality_settings(init.quality, init.quality_overrides);
    if (!quality) return Error{quality.error().code, "renderer: " + quality.error().message};
    const bool asked = init.shade_water_per_sample || init.quality_overrides.water_per_sample.value_or(false);
    const bool multisampled = init.samples != VK_SAMPLE_COUNT_1_BIT;
    const bool sample_shading = ctx.enabled_features.sampleRateShading == VK_TRUE;
    if (asked && !multisampled)
        return Error{ErrorCode::invalid_argument,
                     "renderer: shade_water_per_sample needs a multisampled target (samples 2, 4 or 8), as does "
                     "quality_overrides.water_per_sample"};
    if (asked && !sample_shading)
        return Error{ErrorCode::unsupported,
                     "renderer: the device feature sampleRateShading is not enabled (shade_water_per_sample, "
                     "quality_overrides.water_per_sample): enable it in vkCreateDevice and say so in DeviceContext"};
    quality->water_per_sample = asked || (quality->water_per_sample && multisampled && sample_shading);
    return quality;
}

DrawOptions draw_options_for(const RendererInitInfo& init, const QualitySettings& quality) {
    return {init.color_format,        init.depth_format, init.samples,
            quality.water_per_sample, init.wireframe,    WaterShading::from(quality)};
}

Result<VkPipeline> create_pipeline(const Device& ctx, const PipelineDesc& d) {
    struct Stage {
        std::string_view name;
        VkShaderStageFlagBits stage;
    };
    std::vector<Stage> wanted{{d.vertex, VK_SHADER_STAGE_VERTEX_BIT}};
    if (!d.tess_control.empty()) {
        wanted.push_back({d.tess_control, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT});
        wanted.push_back({d.tess_eval, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT});
    }
    wanted.push_back({d.fragment, VK_SHADER_STAGE_FRAGMENT_BIT});
    std::vector<OwnedShaderModule> modules;  // destroyed once the pipeline is made
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    // Every stage gets the water's constants; a stage without them ignores them.
    const VkSpecializationMapEntry water_entries[] = {
        {gpu::kSpecFoamLags, offsetof(WaterShading, foam_lags), sizeof(std::uint32_t)},
        {gpu::kSpecReflectionFacets, offsetof(WaterShading, reflection_facets), sizeof(std::uint32_t)},
        {gpu::kSpecReflectionSteps, offsetof(WaterShading, reflection_steps), sizeof(std::int32_t)},
        {gpu::kSpecReflectionStepGrowth, offsetof(WaterShading, reflection_step_growth), sizeof(float)},
        {gpu::kSpecCaustics, offsetof(WaterShading, caustics), sizeof(std::uint32_t)},
        {gpu::kSpecSceneReflection, offsetof(WaterShading, scene_reflection), sizeof(std::uint32_t)},
        {gpu::kSpecWavesCapped, offsetof(WaterShading, waves_capped), sizeof(std::uint32_t)}};
    VkSpecializationInfo water_specialization{static_cast<std::uint32_t>(std::size(water_entries)), water_entries,
                                              sizeof(WaterShading), d.water};
    for (const Stage& s : wanted) {
        auto module = make_module(ctx, s.name, d.shaders);
        if (!module) return module.error();
        modules.push_back(std::move(module).value());
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = s.stage;
        info.module = modules.back().get();
        info.pName = "main";
        if (d.water) info.pSpecializationInfo = &water_specialization;
        stages.push_back(info);
    }

    const VkVertexInputBindingDescription mesh_binding{0, 24, VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription mesh_attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                                  {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12}};
    const VkVertexInputBindingDescription patch_bindings[2] = {
        {0, sizeof(float) * 2, VK_VERTEX_INPUT_RATE_VERTEX},
        {1, sizeof(gpu::GpuTerrainNode), VK_VERTEX_INPUT_RATE_INSTANCE}};
    const VkVertexInputAttributeDescription patch_attributes[3] = {
        {0, 0, VK_FORMAT_R32G32_SFLOAT, 0},
        {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::GpuTerrainNode, rect)},
        {2, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::GpuTerrainNode, morph)}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (d.vertices == PipelineDesc::Vertices::mesh) {
        vertex_input.vertexBindingDescriptionCount = 1;
        vertex_input.pVertexBindingDescriptions = &mesh_binding;
        vertex_input.vertexAttributeDescriptionCount = 2;
        vertex_input.pVertexAttributeDescriptions = mesh_attributes;
    } else if (d.vertices == PipelineDesc::Vertices::terrain_patch) {
        vertex_input.vertexBindingDescriptionCount = 2;
        vertex_input.pVertexBindingDescriptions = patch_bindings;
        vertex_input.vertexAttributeDescriptionCount = 3;
        vertex_input.pVertexAttributeDescriptions = patch_attributes;
    }
    const bool tessellated = !d.tess_control.empty();
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineTessellationStateCreateInfo tess{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
    tess.patchControlPoints = 4;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = d.polygon_mode;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = d.samples;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = d.depth_test ? VK_TRUE : VK_FALSE;
    depth.depthWriteEnable = d.depth_write ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reversed-Z
    VkPipelineColorBlendAttachmentState blend{};
    blend.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blending.attachmentCount = 1;
    blending.pAttachments = &blend;
    const VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamic_states;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &d.color_format;
    rendering.depthAttachmentFormat = d.depth_format;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = static_cast<std::uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &assembly;
    info.pTessellationState = tessellated ? &tess : nullptr;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blending;
    info.pDynamicState = &dynamic;
    info.layout = d.layout;
    // Statistics are captured at build time, where the host enabled them.
    if (ctx.pipeline_executable_info) info.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult r =
        ctx.vk().CreateGraphicsPipelines(ctx.device, ctx.pipeline_cache, 1, &info, ctx.allocator, &pipeline);
    if (r != VK_SUCCESS) return vk_error(r, "vkCreateGraphicsPipelines");
    return pipeline;
}

namespace {

Status create_layouts(const Device& ctx, FramePipelines& p) {
    TW_VK_TRY(make_set_layout(ctx, kFrameSetRows, VK_SHADER_STAGE_ALL_GRAPHICS, p.set_layout));
    const VkDescriptorSetLayout set_layout = p.set_layout.get();
    const VkPushConstantRange push{VK_SHADER_STAGE_ALL_GRAPHICS, 0, gpu::kPushConstantBytes};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    TW_VK_TRY(make_owned(ctx, p.layout, [&](VkPipelineLayout* out) {
        return ctx.vk().CreatePipelineLayout(ctx.device, &layout_info, ctx.allocator, out);
    }));
    return {};
}

Status create_samplers(const Device& ctx, FramePipelines& p) {
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = VK_FILTER_LINEAR;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.maxLod = 0.0f;
    TW_VK_TRY(make_owned(ctx, p.linear,
                         [&](VkSampler* out) { return ctx.vk().CreateSampler(ctx.device, &s, ctx.allocator, out); }));
    s.magFilter = s.minFilter = VK_FILTER_NEAREST;
    TW_VK_TRY(make_owned(ctx, p.nearest,
                         [&](VkSampler* out) { return ctx.vk().CreateSampler(ctx.device, &s, ctx.allocator, out); }));
    s.magFilter = s.minFilter = VK_FILTER_LINEAR;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    TW_VK_TRY(make_owned(ctx, p.linear_repeat,
                         [&](VkSampler* out) { return ctx.vk().CreateSampler(ctx.device, &s, ctx.allocator, out); }));
    return {};
}

}  // namespace

Result<FramePipelines> FramePipelines::create(const Device& ctx, const DrawOptions& options) {
    FramePipelines p;
    if (auto st = create_layouts(ctx, p); !st) return st.error();
    if (auto st = create_samplers(ctx, p); !st) return st.error();
    auto draws = p.make_draws(ctx, options, nullptr);
    if (!draws) return draws.error();
    p.draws = std::move(draws).value();
    return p;
}

Result<DrawPipelines> FramePipelines::make_draws(const Device& ctx, const DrawOptions& options,
                                                 const ShaderLookup& shaders) const {
    DrawPipelines p;
    PipelineDesc base;
    base.layout = layout.get();
    base.color_format = options.color_format;
    base.depth_format = options.depth_format;
    base.samples = options.samples;
    base.shaders = shaders;
    auto make = [&](OwnedPipeline& out, const PipelineDesc& d) -> Status {
        auto made = create_pipeline(ctx, d);
        if (!made) return made.error();
        out = OwnedPipeline(ctx, *made);
        return {};
    };
    PipelineDesc sky = base;
    sky.vertex = "sky.vert";
    sky.fragment = "sky.frag";
    sky.depth_write = false;
    if (auto st = make(p.sky, sky); !st) return st.error();
    PipelineDesc host_light = sky;  // full screen, over the copy of the host's colour and depth
    host_light.fragment = "host_light.frag";
    host_light.depth_test = false;
    host_light.depth_format = VK_FORMAT_UNDEFINED;  // drawn without the depth attachment, reading its copy
    host_light.water = &options.water;              // its caustics
    if (auto st = make(p.host_light, host_light); !st) return st.error();
    PipelineDesc terrain = base;
    terrain.vertex = "terrain.vert";
    terrain.fragment = "terrain.frag";
    terrain.vertices = PipelineDesc::Vertices::terrain_patch;
    terrain.water = &options.water;  // its caustics
    if (auto st = make(p.terrain, terrain); !st) return st.error();
    PipelineDesc floats = base;  // hull meshes, one paint per body
    floats.vertex = "mesh.vert";
    floats.fragment = "float.frag";
    floats.vertices = PipelineDesc::Vertices::mesh;
    floats.water = &options.water;  // its caustics
    if (auto st = make(p.floats, floats); !st) return st.error();
    PipelineDesc water = base;
    water.vertex = "water.vert";
    water.tess_control = "water.tesc";
    water.tess_eval = "water.tese";
    water.fragment = options.water_per_sample ? "water_per_sample.frag" : "water.frag";
    water.water = &options.water;
    if (auto st = make(p.water, water); !st) return st.error();
    if (options.wireframe) {
        terrain.polygon_mode = water.polygon_mode = VK_POLYGON_MODE_LINE;
        if (auto st = make(p.terrain_wire, terrain); !st) return st.error();
        if (auto st = make(p.water_wire, water); !st) return st.error();
    }
    return p;
}

}  // namespace tidewater::render::detail
