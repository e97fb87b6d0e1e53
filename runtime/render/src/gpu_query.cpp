#include "tidewater/render/gpu_query.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>

#include "embedded_shaders.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "gpu_memory.hpp"
#include "phase_cells.hpp"
#include "scene_uploads.hpp"
#include "vk_handle.hpp"
#include "vk_util.hpp"

namespace tidewater::render {

using detail::GpuBuffer;

namespace {
constexpr std::uint32_t kBindings = 7;  // see shaders/query.comp
}  // namespace

struct GpuQuery::Impl {
    DeviceContext ctx;
    detail::OwnedSetLayout set_layout;
    detail::OwnedPipelineLayout pipeline_layout;
    detail::OwnedPipeline pipeline;
    detail::OwnedDescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;  // freed with the pool
    detail::OwnedCommandPool commands;
    GpuBuffer waves, phases, points, results, cell_origins;
    detail::ShoreBuffers shore;  // the same upload the renderer uses

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        // Every member destroys its own handles; none may be in use by the GPU then.
        if (ctx.device) vkDeviceWaitIdle(ctx.device);
    }

    /// Grows `buffer` to hold at least `bytes`; reports whether it was replaced.
    Result<bool> ensure(GpuBuffer& buffer, VkDeviceSize bytes) {
        if (buffer.handle() && buffer.size() >= bytes) return false;
        auto fresh = GpuBuffer::create(ctx, std::max<VkDeviceSize>(bytes, 256), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!fresh) return fresh.error();
        buffer = std::move(fresh).value();
        return true;
    }

    void bind_buffers() {
        VkDescriptorBufferInfo infos[kBindings] = {
            {waves.handle(), 0, VK_WHOLE_SIZE},     {phases.handle(), 0, VK_WHOLE_SIZE},
            {points.handle(), 0, VK_WHOLE_SIZE},    {results.handle(), 0, VK_WHOLE_SIZE},
            {shore.per_wave(), 0, VK_WHOLE_SIZE},   {shore.shared(), 0, VK_WHOLE_SIZE},
            {cell_origins.handle(), 0, VK_WHOLE_SIZE}};
        VkWriteDescriptorSet writes[kBindings];
        for (std::uint32_t i = 0; i < kBindings; ++i) {
            writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[i].dstSet = set;
            writes[i].dstBinding = i;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = &infos[i];
        }
        vkUpdateDescriptorSets(ctx.device, kBindings, writes, 0, nullptr);
    }

};

GpuQuery::GpuQuery(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuQuery::~GpuQuery() = default;

Result<std::unique_ptr<GpuQuery>> GpuQuery::create(const DeviceContext& context) {
    if (!context.device || !context.queue || !context.physical_device) {
        return Error{ErrorCode::invalid_argument, "GpuQuery: the DeviceContext has no device, physical device or queue"};
    }
    auto impl = std::make_unique<Impl>();
    impl->ctx = context;
    const DeviceContext& ctx = impl->ctx;

    VkDescriptorSetLayoutBinding bindings[kBindings];
    for (std::uint32_t i = 0; i < kBindings; ++i) {
        bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    }
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = kBindings;
    set_info.pBindings = bindings;
    TW_VK_TRY(detail::make_owned(ctx.device, ctx.allocator, impl->set_layout, [&](VkDescriptorSetLayout* out) {
        return vkCreateDescriptorSetLayout(ctx.device, &set_info, ctx.allocator, out);
    }));
    const VkDescriptorSetLayout set_layout = impl->set_layout.get();

    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::GpuQueryParams)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    TW_VK_TRY(detail::make_owned(ctx.device, ctx.allocator, impl->pipeline_layout, [&](VkPipelineLayout* out) {
        return vkCreatePipelineLayout(ctx.device, &layout_info, ctx.allocator, out);
    }));

    const auto spirv = detail::embedded_spirv("query.comp");
    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = spirv.size_bytes();
    module_info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    TW_VK_TRY(vkCreateShaderModule(ctx.device, &module_info, ctx.allocator, &module));
    VkComputePipelineCreateInfo pipe{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipe.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipe.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipe.stage.module = module;
    pipe.stage.pName = "main";
    pipe.layout = impl->pipeline_layout.get();
    const VkResult made = detail::make_owned(ctx.device, ctx.allocator, impl->pipeline, [&](VkPipeline* out) {
        return vkCreateComputePipelines(ctx.device, ctx.pipeline_cache, 1, &pipe, ctx.allocator, out);
    });
    vkDestroyShaderModule(ctx.device, module, ctx.allocator);
    if (made != VK_SUCCESS) return detail::vk_error(made, "vkCreateComputePipelines(query.comp)");

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindings};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    TW_VK_TRY(detail::make_owned(ctx.device, ctx.allocator, impl->pool, [&](VkDescriptorPool* out) {
        return vkCreateDescriptorPool(ctx.device, &pool_info, ctx.allocator, out);
    }));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = impl->pool.get();
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout;
    TW_VK_TRY(vkAllocateDescriptorSets(ctx.device, &alloc, &impl->set));

    VkCommandPoolCreateInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cmd_info.queueFamilyIndex = ctx.queue_family;
    cmd_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    TW_VK_TRY(detail::make_owned(ctx.device, ctx.allocator, impl->commands,
                                 [&](VkCommandPool* out) { return vkCreateCommandPool(ctx.device, &cmd_info, ctx.allocator, out); }));
    return std::unique_ptr<GpuQuery>(new GpuQuery(std::move(impl)));
}

Status GpuQuery::query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                               std::span<SurfacePoint> out) {
    if (points.size() != out.size()) {
        return Error{ErrorCode::invalid_argument, fmt::format("GPU query: {} points but room for {} results", points.size(), out.size())};
    }
    if (points.empty()) return {};
    if (points.size() > (1u << 26)) {
        return Error{ErrorCode::invalid_argument, fmt::format("GPU query: {} points in one call, at most 2^26", points.size())};
    }
    Impl& m = *impl_;
    const WaveSet& set = body.waves();
    const detail::PhaseCells cells = detail::build_phase_cells(set, body.local_time(time), points);
    const auto waves = detail::gpu_waves(set);

    bool rebind = false;
    for (auto [buffer, bytes] : {std::pair{&m.waves, sizeof(gpu::GpuWave) * std::max<std::size_t>(1, waves.size())},
                                 std::pair{&m.phases, sizeof(float) * std::max<std::size_t>(1, cells.base_phase.size())},
                                 std::pair{&m.points, sizeof(gpu::GpuQueryPoint) * points.size()},
                                 std::pair{&m.results, sizeof(gpu::GpuQueryResult) * points.size()}}) {
        auto grown = m.ensure(*buffer, bytes);
        if (!grown) return grown.error();
        rebind = rebind || *grown;
    }
    // Every submit below waits for completion: no GPU work can still read the old fields.
    auto uploaded = m.shore.upload(m.ctx, body.shore());
    if (!uploaded) return uploaded.error();
    rebind = rebind || *uploaded;
    const ShoreWaves* shore = m.shore.model();
    std::vector<glm::vec2> origins(std::max<std::size_t>(1, cells.origins.size()), glm::vec2(0.0f));
    for (std::size_t c = 0; c < cells.origins.size(); ++c) {
        const glm::dvec2 rel = cells.origins[c] - (shore ? shore->corner() : glm::dvec2(0.0));
        origins[c] = glm::vec2(static_cast<float>(rel.x), static_cast<float>(rel.y));
    }
    auto grown_origins = m.ensure(m.cell_origins, sizeof(glm::vec2) * origins.size());
    if (!grown_origins) return grown_origins.error();
    rebind = rebind || *grown_origins;
    if (rebind) m.bind_buffers();
    std::memcpy(m.cell_origins.mapped(), origins.data(), sizeof(glm::vec2) * origins.size());
    std::memcpy(m.waves.mapped(), waves.data(), sizeof(gpu::GpuWave) * waves.size());
    std::memcpy(m.phases.mapped(), cells.base_phase.data(), sizeof(float) * cells.base_phase.size());
    std::memcpy(m.points.mapped(), cells.points.data(), sizeof(gpu::GpuQueryPoint) * points.size());

    // The shader derives the tolerance and step bound from sum(Q A) as the CPU does.
    gpu::GpuQueryParams params{};
    params.wave_count = static_cast<std::uint32_t>(waves.size());
    params.point_count = static_cast<std::uint32_t>(points.size());
    params.max_offset = static_cast<float>(set.max_horizontal_displacement());
    params.shore_resolution = shore ? static_cast<std::uint32_t>(shore->resolution()) : 0u;
    params.shore_texel = shore ? static_cast<float>(shore->texel()) : 1.0f;

    Status st = detail::submit_and_wait(m.ctx, m.commands.get(), [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipeline.get());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipeline_layout.get(), 0, 1, &m.set, 0, nullptr);
        vkCmdPushConstants(cmd, m.pipeline_layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(params), &params);
        vkCmdDispatch(cmd, (params.point_count + gpu::kQueryWorkgroupSize - 1) / gpu::kQueryWorkgroupSize, 1, 1);
        VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                             nullptr, 0, nullptr);
    });
    if (!st) return st;

    const auto* results = static_cast<const gpu::GpuQueryResult*>(m.results.mapped());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const gpu::GpuQueryResult& r = results[i];
        SurfacePoint& o = out[i];
        o.height = body.level() + static_cast<double>(r.height_normal.x);
        o.normal = {r.height_normal.y, r.height_normal.z, r.height_normal.w};
        o.velocity = {r.velocity_jac.x, r.velocity_jac.y, r.velocity_jac.z};
        o.jacobian = static_cast<double>(r.velocity_jac.w);
        o.displacement = {r.disp_iter.x, r.disp_iter.y};
        o.iterations = static_cast<int>(r.disp_iter.z);
        o.converged = r.disp_iter.w != 0.0f;
        if (shore) {
            o.depth = static_cast<double>(r.shore.x);
            o.shore_distance = static_cast<double>(r.shore.y);
        } else {
            o.depth = o.shore_distance = kDeepWater;
        }
        o.wet = tidewater::detail::surface_wet(o.height, body.level(), o.depth);
        o.foam = std::max(shore ? static_cast<double>(r.shore.z) : 0.0, crest_foam(o.jacobian));  // as detail::surface_foam
    }
    return {};
}

}  // namespace tidewater::render
