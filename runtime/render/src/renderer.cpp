#include "tidewater/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fmt/format.h>
#include <vector>

#include "frame_constants.hpp"
#include "gpu_memory.hpp"
#include "render_pipelines.hpp"
#include "shore_upload.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/shore_waves.hpp"
#include "terrain_mesh.hpp"
#include "vk_util.hpp"

namespace tidewater::render {

using detail::GpuBuffer;
using detail::GpuImage;
using detail::transition;

namespace {

constexpr std::array<DebugView, 9> kViews = {DebugView::shaded, DebugView::height, DebugView::normals,
                                             DebugView::jacobian, DebugView::depth, DebugView::lod,
                                             DebugView::wireframe, DebugView::shore, DebugView::breaking};
constexpr std::array<std::string_view, 9> kViewNames = {"shaded", "height", "normals", "jacobian", "depth",
                                                        "lod", "wireframe", "shore", "breaking"};
constexpr std::uint32_t kBindings = 7;  // see shaders/frame.glsl
constexpr std::uint32_t kTerrainCells = 384;
constexpr std::uint32_t kHeightTextureSize = 1024;
constexpr std::uint32_t kTimestampsPerFrame = 4;

}  // namespace

std::string_view to_string(DebugView view) { return kViewNames[static_cast<std::size_t>(view)]; }

std::optional<DebugView> parse_debug_view(std::string_view name) {
    for (std::size_t i = 0; i < kViews.size(); ++i)
        if (kViewNames[i] == name) return kViews[i];
    return std::nullopt;
}

std::span<const DebugView> all_debug_views() { return kViews; }

struct Renderer::Impl {
    RendererInitInfo info;
    const DeviceContext& ctx() const { return info.device; }

    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline sky = VK_NULL_HANDLE, terrain = VK_NULL_HANDLE, terrain_wire = VK_NULL_HANDLE;
    VkPipeline water = VK_NULL_HANDLE, water_wire = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkSampler linear = VK_NULL_HANDLE, nearest = VK_NULL_HANDLE;
    VkCommandPool upload_pool = VK_NULL_HANDLE;
    VkQueryPool timestamps = VK_NULL_HANDLE;
    double timestamp_period_ns = 1.0;

    struct Slot {
        GpuBuffer frame, waves;
        VkDescriptorSet set = VK_NULL_HANDLE;
        std::uint64_t recorded_frame = ~0ull;
    };
    std::vector<Slot> slots;

    // Scene data.
    bool has_scene = false;
    WaterBody ocean;
    detail::TerrainPlacement placement;
    double water_half_size = 3000.0;
    GpuBuffer terrain_vertices, terrain_indices;
    std::uint32_t terrain_index_count = 0;
    std::uint64_t terrain_vertex_count = 0;
    GpuImage height_texture;
    GpuImage dummy_color, dummy_depth;  // bound where no scene copy exists
    GpuImage copy_color, copy_depth;    // the opaque scene, for refraction and reflection
    GpuBuffer shore_waves, shore_shared;  // the shore fields (placeholders without a shore)
    const ShoreWaves* uploaded_shore = nullptr;
    std::shared_ptr<const ShoreWaves> shore_alive;
    VkExtent2D copy_extent{};
    std::uint64_t last_patches = 0;

    ~Impl() {
        const VkDevice dev = ctx().device;
        if (!dev) return;
        vkDeviceWaitIdle(dev);
        for (Slot& s : slots) {
            s.frame.reset();
            s.waves.reset();
        }
        terrain_vertices.reset();
        terrain_indices.reset();
        shore_waves.reset();
        shore_shared.reset();
        height_texture.reset();
        dummy_color.reset();
        dummy_depth.reset();
        copy_color.reset();
        copy_depth.reset();
        const VkAllocationCallbacks* a = ctx().allocator;
        for (VkPipeline p : {sky, terrain, terrain_wire, water, water_wire})
            if (p) vkDestroyPipeline(dev, p, a);
        if (layout) vkDestroyPipelineLayout(dev, layout, a);
        if (set_layout) vkDestroyDescriptorSetLayout(dev, set_layout, a);
        if (pool) vkDestroyDescriptorPool(dev, pool, a);
        if (linear) vkDestroySampler(dev, linear, a);
        if (nearest) vkDestroySampler(dev, nearest, a);
        if (upload_pool) vkDestroyCommandPool(dev, upload_pool, a);
        if (timestamps) vkDestroyQueryPool(dev, timestamps, a);
    }

    void log(const std::string& message) const {
        if (info.log) info.log(message);
    }
    Status upload_shore(const std::shared_ptr<const ShoreWaves>& shore);
    Status create_layouts();
    Status create_pipelines();
    Status create_slots();
    Status create_samplers_and_dummies();
    Status upload_image(GpuImage& image, const void* data, VkDeviceSize bytes, VkImageAspectFlags aspect);
    Status ensure_copy_targets(VkExtent2D extent);
    void write_descriptors(Slot& slot, bool with_scene_copy);
    Status prepare_slot(const FrameInfo& frame, VkExtent2D extent, bool scene_copy, Slot*& slot, detail::FramePlan& plan);
    void draw_opaque(VkCommandBuffer cmd, const Slot& slot, const detail::FramePlan& plan, VkExtent2D extent, DebugView view);
    void draw_water(VkCommandBuffer cmd, const Slot& slot, const detail::FramePlan& plan, VkExtent2D extent, DebugView view);
};

Status Renderer::Impl::create_layouts() {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_ALL_GRAPHICS;
    const VkDescriptorSetLayoutBinding bindings[kBindings] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr}};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = kBindings;
    set_info.pBindings = bindings;
    TW_VK_TRY(vkCreateDescriptorSetLayout(ctx().device, &set_info, ctx().allocator, &set_layout));
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, 16};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    TW_VK_TRY(vkCreatePipelineLayout(ctx().device, &layout_info, ctx().allocator, &layout));
    return {};
}

Status Renderer::Impl::create_pipelines() {
    detail::PipelineDesc base;
    base.layout = layout;
    base.color_format = info.color_format;
    base.depth_format = info.depth_format;
    auto make = [&](VkPipeline& out, detail::PipelineDesc d) -> Status {
        auto p = detail::create_pipeline(ctx(), d);
        if (!p) return p.error();
        out = *p;
        return {};
    };
    detail::PipelineDesc sky_desc = base;
    sky_desc.vertex = "sky.vert";
    sky_desc.fragment = "sky.frag";
    sky_desc.depth_write = false;
    if (auto st = make(sky, sky_desc); !st) return st;
    detail::PipelineDesc terrain_desc = base;
    terrain_desc.vertex = "terrain.vert";
    terrain_desc.fragment = "terrain.frag";
    terrain_desc.terrain_vertices = true;
    if (auto st = make(terrain, terrain_desc); !st) return st;
    detail::PipelineDesc water_desc = base;
    water_desc.vertex = "water.vert";
    water_desc.tess_control = "water.tesc";
    water_desc.tess_eval = "water.tese";
    water_desc.fragment = "water.frag";
    if (auto st = make(water, water_desc); !st) return st;
    if (info.wireframe) {
        terrain_desc.polygon_mode = VK_POLYGON_MODE_LINE;
        water_desc.polygon_mode = VK_POLYGON_MODE_LINE;
        if (auto st = make(terrain_wire, terrain_desc); !st) return st;
        if (auto st = make(water_wire, water_desc); !st) return st;
    }
    return {};
}

Status Renderer::Impl::create_slots() {
    VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, info.frames_in_flight},
                                     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * info.frames_in_flight},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * info.frames_in_flight}};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = info.frames_in_flight;
    pool_info.poolSizeCount = 3;
    pool_info.pPoolSizes = sizes;
    TW_VK_TRY(vkCreateDescriptorPool(ctx().device, &pool_info, ctx().allocator, &pool));
    slots.resize(info.frames_in_flight);
    for (Slot& s : slots) {
        auto frame = GpuBuffer::create(ctx(), sizeof(gpu::GpuFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        if (!frame) return frame.error();
        s.frame = std::move(frame).value();
        auto waves = GpuBuffer::create(ctx(), sizeof(gpu::GpuWave) * kMaxWaves, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!waves) return waves.error();
        s.waves = std::move(waves).value();
        VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        alloc.descriptorPool = pool;
        alloc.descriptorSetCount = 1;
        alloc.pSetLayouts = &set_layout;
        TW_VK_TRY(vkAllocateDescriptorSets(ctx().device, &alloc, &s.set));
    }
    std::uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx().physical_device, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx().physical_device, &family_count, families.data());
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(ctx().physical_device, &props);
    if (ctx().queue_family < family_count && families[ctx().queue_family].timestampValidBits > 0) {
        timestamp_period_ns = static_cast<double>(props.limits.timestampPeriod);
        VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        q.queryType = VK_QUERY_TYPE_TIMESTAMP;
        q.queryCount = kTimestampsPerFrame * info.frames_in_flight;
        TW_VK_TRY(vkCreateQueryPool(ctx().device, &q, ctx().allocator, &timestamps));
    }
    return {};
}

Status Renderer::Impl::upload_image(GpuImage& image, const void* data, VkDeviceSize bytes, VkImageAspectFlags aspect) {
    auto staging = GpuBuffer::create(ctx(), bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    if (!staging) return staging.error();
    std::memcpy(staging->mapped(), data, bytes);
    return detail::submit_and_wait(ctx(), upload_pool, [&](VkCommandBuffer cmd) {
        transition(cmd, image.handle(), aspect, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {image.extent().width, image.extent().height, 1};
        vkCmdCopyBufferToImage(cmd, staging->handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(cmd, image.handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
                   VK_ACCESS_SHADER_READ_BIT);
    });
}

Status Renderer::Impl::create_samplers_and_dummies() {
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = VK_FILTER_LINEAR;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.maxLod = 0.0f;
    TW_VK_TRY(vkCreateSampler(ctx().device, &s, ctx().allocator, &linear));
    s.magFilter = s.minFilter = VK_FILTER_NEAREST;
    TW_VK_TRY(vkCreateSampler(ctx().device, &s, ctx().allocator, &nearest));
    VkCommandPoolCreateInfo cp{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cp.queueFamilyIndex = ctx().queue_family;
    cp.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    TW_VK_TRY(vkCreateCommandPool(ctx().device, &cp, ctx().allocator, &upload_pool));
    auto color = GpuImage::create(ctx(), {1, 1}, info.color_format, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT);
    if (!color) return color.error();
    dummy_color = std::move(color).value();
    auto depth = GpuImage::create(ctx(), {1, 1}, info.depth_format, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  VK_IMAGE_ASPECT_DEPTH_BIT);
    if (!depth) return depth.error();
    dummy_depth = std::move(depth).value();
    const std::uint32_t black = 0;
    const float zero_depth = 0.0f;
    if (auto st = upload_image(dummy_color, &black, 4, VK_IMAGE_ASPECT_COLOR_BIT); !st) return st;
    return upload_image(dummy_depth, &zero_depth, 4, VK_IMAGE_ASPECT_DEPTH_BIT);
}

Status Renderer::Impl::ensure_copy_targets(VkExtent2D extent) {
    if (copy_color.handle() && copy_extent.width == extent.width && copy_extent.height == extent.height) return {};
    if (extent.width == 0 || extent.height == 0 || extent.width > 16384 || extent.height > 16384)
        return Error{ErrorCode::invalid_argument, fmt::format("renderer: extent {}x{} is out of range (1 to 16384)", extent.width, extent.height)};
    log(fmt::format("tidewater: refraction copies resized to {}x{}", extent.width, extent.height));
    // The copies may be in use by frames in flight: a resize waits for the device.
    vkDeviceWaitIdle(ctx().device);
    copy_color.reset();
    copy_depth.reset();
    auto color = GpuImage::create(ctx(), extent, info.color_format, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT);
    if (!color) return color.error();
    copy_color = std::move(color).value();
    auto depth = GpuImage::create(ctx(), extent, info.depth_format, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  VK_IMAGE_ASPECT_DEPTH_BIT);
    if (!depth) return depth.error();
    copy_depth = std::move(depth).value();
    copy_extent = extent;
    // Give the new images a defined layout before any frame samples them.
    return detail::submit_and_wait(ctx(), upload_pool, [&](VkCommandBuffer cmd) {
        transition(cmd, copy_color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
        transition(cmd, copy_depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
}

void Renderer::Impl::write_descriptors(Slot& slot, bool with_scene_copy) {
    VkDescriptorBufferInfo frame_info{slot.frame.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo wave_info{slot.waves.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo height{linear, height_texture.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo color{linear, (with_scene_copy ? copy_color : dummy_color).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo depth{nearest, (with_scene_copy ? copy_depth : dummy_depth).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo shore_wave_info{shore_waves.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo shore_shared_info{shore_shared.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet w[kBindings];
    for (std::uint32_t i = 0; i < kBindings; ++i) {
        w[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w[i].dstSet = slot.set;
        w[i].dstBinding = i;
        w[i].descriptorCount = 1;
    }
    w[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    w[0].pBufferInfo = &frame_info;
    w[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w[1].pBufferInfo = &wave_info;
    w[2].descriptorType = w[3].descriptorType = w[4].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w[2].pImageInfo = &height;
    w[3].pImageInfo = &color;
    w[4].pImageInfo = &depth;
    w[5].descriptorType = w[6].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w[5].pBufferInfo = &shore_wave_info;
    w[6].pBufferInfo = &shore_shared_info;
    vkUpdateDescriptorSets(ctx().device, kBindings, w, 0, nullptr);
}

Status Renderer::Impl::prepare_slot(const FrameInfo& frame, VkExtent2D extent, bool scene_copy, Slot*& slot,
                                    detail::FramePlan& plan) {
    if (!has_scene) return Error{ErrorCode::invalid_argument, "renderer: no scene; call set_scene first"};
    if (extent.width == 0 || extent.height == 0 || extent.width > 16384 || extent.height > 16384)
        return Error{ErrorCode::invalid_argument, fmt::format("renderer: extent {}x{} is out of range (1 to 16384)", extent.width, extent.height)};
    if (auto st = detail::validate_camera(frame.camera); !st) return st;
    if (!std::isfinite(frame.time) || std::abs(frame.time) > 1e9)
        return Error{ErrorCode::invalid_argument, fmt::format("renderer: time {} is out of range (finite, |t| <= 1e9 s)", frame.time)};
    if (frame.view == DebugView::wireframe && !water_wire)
        return Error{ErrorCode::unsupported, "renderer: the wireframe view needs fillModeNonSolid (RendererInitInfo::wireframe)"};
    slot = &slots[frame.frame_index % slots.size()];
    slot->recorded_frame = frame.frame_index;
    plan = detail::plan_frame(frame, extent, ocean, placement, water_half_size, scene_copy);
    if (uploaded_shore) {
        const glm::dvec2 rel = uploaded_shore->corner() - plan.origin;
        plan.frame.shore_rect = glm::vec4(static_cast<float>(rel.x), static_cast<float>(rel.y),
                                          static_cast<float>(uploaded_shore->texel()), static_cast<float>(uploaded_shore->resolution()));
    }
    std::memcpy(slot->frame.mapped(), &plan.frame, sizeof(plan.frame));
    if (!plan.waves.empty()) std::memcpy(slot->waves.mapped(), plan.waves.data(), sizeof(gpu::GpuWave) * plan.waves.size());
    write_descriptors(*slot, scene_copy);
    return {};
}

void Renderer::Impl::draw_opaque(VkCommandBuffer cmd, const Slot& slot, const detail::FramePlan& plan, VkExtent2D extent,
                                 DebugView view) {
    detail::set_viewport(cmd, extent);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &slot.set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, 16, &plan.terrain_mesh_offset);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, view == DebugView::wireframe ? terrain_wire : terrain);
    const VkDeviceSize offset = 0;
    const VkBuffer vb = terrain_vertices.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
    vkCmdBindIndexBuffer(cmd, terrain_indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, terrain_index_count, 1, 0, 0, 0);
    // The sky last: it only fills pixels nothing else covered (depth still at the far plane).
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, sky);
    vkCmdDraw(cmd, 3, 1, 0, 0);
}

void Renderer::Impl::draw_water(VkCommandBuffer cmd, const Slot& slot, const detail::FramePlan& plan, VkExtent2D extent,
                                DebugView view) {
    detail::set_viewport(cmd, extent);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &slot.set, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, view == DebugView::wireframe ? water_wire : water);
    const std::uint32_t patches = plan.patches_per_side * plan.patches_per_side;
    vkCmdDraw(cmd, 4, patches, 0, 0);
    last_patches = patches;
}

Status Renderer::Impl::upload_shore(const std::shared_ptr<const ShoreWaves>& shore) {
    const ShoreWaves* wanted = shore && !shore->trivial() ? shore.get() : nullptr;
    if (shore_waves.handle() && wanted == uploaded_shore) return {};
    vkDeviceWaitIdle(ctx().device);  // frames in flight may read the old fields
    const detail::PackedShore packed = detail::pack_shore(wanted);
    for (auto [buffer, data] : {std::pair{&shore_waves, &packed.per_wave}, std::pair{&shore_shared, &packed.shared}}) {
        auto fresh = GpuBuffer::create(ctx(), data->size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!fresh) return fresh.error();
        std::memcpy(fresh->mapped(), data->data(), data->size() * sizeof(glm::vec4));
        *buffer = std::move(fresh).value();
    }
    uploaded_shore = wanted;
    shore_alive = wanted ? shore : nullptr;
    return {};
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(const RendererInitInfo& info) {
    const DeviceContext& c = info.device;
    if (!c.instance || !c.physical_device || !c.device || !c.queue)
        return Error{ErrorCode::invalid_argument, "renderer: RendererInitInfo.device needs instance, physical device, device and queue"};
    if (info.frames_in_flight < 1 || info.frames_in_flight > 4)
        return Error{ErrorCode::invalid_argument, fmt::format("renderer: frames_in_flight {} is out of range (1 to 4)", info.frames_in_flight)};
    if (info.samples != VK_SAMPLE_COUNT_1_BIT)
        return Error{ErrorCode::unsupported, fmt::format("renderer: sample count {} is not supported yet (use 1)", static_cast<int>(info.samples))};
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(c.physical_device, &features);
    if (!features.tessellationShader) return Error{ErrorCode::unsupported, "renderer: the device has no tessellationShader feature"};
    auto check_format = [&](VkFormat f, VkFormatFeatureFlags need, const char* what) -> Status {
        VkFormatProperties p;
        vkGetPhysicalDeviceFormatProperties(c.physical_device, f, &p);
        if ((p.optimalTilingFeatures & need) != need)
            return Error{ErrorCode::unsupported, fmt::format("renderer: {} format {} lacks the needed features on this device", what, static_cast<int>(f))};
        return {};
    };
    if (auto st = check_format(info.color_format, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                                      VK_FORMAT_FEATURE_TRANSFER_DST_BIT, "colour"); !st) return st.error();
    if (auto st = check_format(info.depth_format, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                                      VK_FORMAT_FEATURE_TRANSFER_DST_BIT, "depth"); !st) return st.error();
    if (auto st = check_format(VK_FORMAT_R32_SFLOAT, VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "height texture (R32_SFLOAT)"); !st)
        return st.error();
    auto impl = std::make_unique<Impl>();
    impl->info = info;
    impl->info.wireframe = info.wireframe && features.fillModeNonSolid;
    if (info.wireframe && !features.fillModeNonSolid) impl->log("tidewater: no fillModeNonSolid: the wireframe view is off");
    for (auto step : {&Impl::create_layouts, &Impl::create_pipelines, &Impl::create_slots, &Impl::create_samplers_and_dummies}) {
        if (auto st = ((*impl).*step)(); !st) return st.error();
    }
    return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

Status Renderer::set_scene(const Scene& scene) {
    Impl& m = *impl_;
    vkDeviceWaitIdle(m.ctx().device);  // the old terrain may be in use by frames in flight
    const detail::TerrainMesh mesh = detail::build_terrain_mesh(scene.terrain, kTerrainCells);
    const VkDeviceSize vbytes = mesh.vertices.size() * sizeof(float), ibytes = mesh.indices.size() * sizeof(std::uint32_t);
    auto vb = GpuBuffer::create(m.ctx(), vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!vb) return vb.error();
    auto ib = GpuBuffer::create(m.ctx(), ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!ib) return ib.error();
    std::memcpy(vb->mapped(), mesh.vertices.data(), vbytes);
    std::memcpy(ib->mapped(), mesh.indices.data(), ibytes);
    auto height = GpuImage::create(m.ctx(), {kHeightTextureSize, kHeightTextureSize}, VK_FORMAT_R32_SFLOAT,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!height) return height.error();
    const std::vector<float> heights = detail::sample_height_texture(scene.terrain, kHeightTextureSize);
    if (auto st = m.upload_image(*height, heights.data(), heights.size() * sizeof(float), VK_IMAGE_ASPECT_COLOR_BIT); !st) return st;

    m.terrain_vertices = std::move(vb).value();
    m.terrain_indices = std::move(ib).value();
    m.terrain_index_count = static_cast<std::uint32_t>(mesh.indices.size());
    m.terrain_vertex_count = mesh.vertices.size() / 6;
    m.height_texture = std::move(height).value();
    const double half = scene.terrain.extent_half_size();
    m.placement.mesh_origin = mesh.origin;
    m.placement.height_rect_corner = scene.terrain.extent_center() - glm::dvec2(half);
    m.placement.height_rect_size = 2.0 * half;
    m.water_half_size = std::max(3000.0, half);
    m.ocean = scene.ocean;
    if (auto st = m.upload_shore(scene.ocean.shore()); !st) return st;
    m.has_scene = true;
    m.log(fmt::format("tidewater: scene \"{}\" uploaded: {} terrain vertices, {} waves", scene.name, m.terrain_vertex_count,
                      scene.ocean.waves().size()));
    return {};
}

Status Renderer::resize(VkExtent2D extent) { return impl_->ensure_copy_targets(extent); }

Status Renderer::set_water(const WaterBody& water) {
    if (!impl_->has_scene) return Error{ErrorCode::invalid_argument, "renderer: set_scene before set_water"};
    if (water.waves().size() > kMaxWaves) return Error{ErrorCode::invalid_argument, "renderer: too many waves"};
    // Wave data is written per frame into the in-flight slot; only a new shore model is uploaded.
    if (auto st = impl_->upload_shore(water.shore()); !st) return st;
    impl_->ocean = water;
    return {};
}

Status Renderer::record_frame(VkCommandBuffer cmd, const FrameInfo& frame, const FrameTargets& t) {
    Impl& m = *impl_;
    if (!cmd || !t.color_image || !t.color_view || !t.depth_image || !t.depth_view)
        return Error{ErrorCode::invalid_argument, "renderer: record_frame needs a command buffer and the colour and depth images and views"};
    if (auto st = m.ensure_copy_targets(t.extent); !st) return st;
    Impl::Slot* slot = nullptr;
    detail::FramePlan plan;
    if (auto st = m.prepare_slot(frame, t.extent, true, slot, plan); !st) return st;
    const std::uint32_t q0 = static_cast<std::uint32_t>(slot - m.slots.data()) * kTimestampsPerFrame;
    if (m.timestamps) {
        vkCmdResetQueryPool(cmd, m.timestamps, q0, kTimestampsPerFrame);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, m.timestamps, q0);
    }

    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = t.color_view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = t.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingAttachmentInfo depth = color;
    depth.imageView = t.depth_view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.clearValue.depthStencil = {0.0f, 0};  // reversed-Z: far
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, t.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;

    vkCmdBeginRendering(cmd, &rendering);
    m.draw_opaque(cmd, *slot, plan, t.extent, frame.view);
    vkCmdEndRendering(cmd);
    if (m.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m.timestamps, q0 + 1);

    // Copy the opaque scene for refraction and reflection.
    const auto color_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const auto depth_stage = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    transition(cmd, t.color_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               color_stage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    transition(cmd, t.depth_image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               depth_stage, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    for (GpuImage* img : {&m.copy_color, &m.copy_depth}) {
        const VkImageAspectFlags aspect = img == &m.copy_color ? VK_IMAGE_ASPECT_COLOR_BIT : VK_IMAGE_ASPECT_DEPTH_BIT;
        transition(cmd, img->handle(), aspect, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_WRITE_BIT);
        VkImageCopy region{};
        region.srcSubresource = {aspect, 0, 0, 1};
        region.dstSubresource = {aspect, 0, 0, 1};
        region.extent = {t.extent.width, t.extent.height, 1};
        vkCmdCopyImage(cmd, aspect == VK_IMAGE_ASPECT_COLOR_BIT ? t.color_image : t.depth_image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       img->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(cmd, img->handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                   VK_ACCESS_SHADER_READ_BIT);
    }
    transition(cmd, t.color_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, color_stage,
               VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    transition(cmd, t.depth_image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, depth_stage,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    if (m.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, m.timestamps, q0 + 2);

    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    vkCmdBeginRendering(cmd, &rendering);
    m.draw_water(cmd, *slot, plan, t.extent, frame.view);
    vkCmdEndRendering(cmd);
    if (m.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m.timestamps, q0 + 3);
    return {};
}

Status Renderer::record_in_pass(VkCommandBuffer cmd, const FrameInfo& frame, VkExtent2D extent) {
    Impl& m = *impl_;
    if (!cmd) return Error{ErrorCode::invalid_argument, "renderer: record_in_pass needs a command buffer"};
    Impl::Slot* slot = nullptr;
    detail::FramePlan plan;
    if (auto st = m.prepare_slot(frame, extent, false, slot, plan); !st) return st;
    m.draw_opaque(cmd, *slot, plan, extent, frame.view);
    m.draw_water(cmd, *slot, plan, extent, frame.view);
    return {};
}

Result<PassTimings> Renderer::timings(std::uint64_t frame_index) {
    Impl& m = *impl_;
    if (!m.timestamps) return Error{ErrorCode::unsupported, "renderer: this queue has no timestamps"};
    const std::size_t s = frame_index % m.slots.size();
    if (m.slots[s].recorded_frame != frame_index)
        return Error{ErrorCode::not_found, fmt::format("renderer: frame {} is not the last recorded in its slot", frame_index)};
    std::uint64_t ticks[kTimestampsPerFrame];
    const VkResult r = vkGetQueryPoolResults(m.ctx().device, m.timestamps, static_cast<std::uint32_t>(s) * kTimestampsPerFrame,
                                             kTimestampsPerFrame, sizeof(ticks), ticks, sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT);
    if (r != VK_SUCCESS) return detail::vk_error(r, "vkGetQueryPoolResults");
    auto ms = [&](std::uint64_t a, std::uint64_t b) { return static_cast<double>(b - a) * m.timestamp_period_ns * 1e-6; };
    PassTimings p;
    p.sky_and_terrain_ms = ms(ticks[0], ticks[1]);
    p.scene_copy_ms = ms(ticks[1], ticks[2]);
    p.water_ms = ms(ticks[2], ticks[3]);
    p.total_ms = ms(ticks[0], ticks[3]);
    return p;
}

RendererStats Renderer::stats() const {
    RendererStats s;
    s.terrain_vertices = impl_->terrain_vertex_count;
    s.terrain_triangles = impl_->terrain_index_count / 3;
    s.water_patches = impl_->last_patches;
    s.waves = static_cast<std::uint32_t>(impl_->ocean.waves().size());
    return s;
}

}  // namespace tidewater::render
