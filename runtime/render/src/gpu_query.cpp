#include "tidewater/render/gpu_query.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "body_uploads.hpp"
#include "descriptor_sets.hpp"
#include "embedded_shaders.hpp"
#include "frame_constants.hpp"
#include "gpu_memory.hpp"
#include "phase_cells.hpp"
#include "scene_uploads.hpp"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/body_finder.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/surface_foam.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "vk_handle.hpp"
#include "vk_util.hpp"
#include "wake_uploads.hpp"

namespace tidewater::render {

using detail::GpuBuffer;

namespace {

/// A river evaluation: the river, its preset, and whether still water joins it.
struct RiverDispatch {
    const tidewater::detail::RiverBake* river = nullptr;
    const WaterBody* body = nullptr;  ///< the river's preset
    bool still = false;               ///< mouth or plume: the still body's waves fade in
};
}  // namespace

// Every submission is waited for before the call returns, so the members destroy their
// handles without a device-wide wait.
struct GpuQuery::Impl {
    detail::Device ctx;
    detail::OwnedSetLayout set_layout;
    detail::OwnedPipelineLayout pipeline_layout;
    detail::OwnedPipeline pipeline;
    detail::OwnedDescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;  // freed with the pool
    detail::OwnedCommandPool commands;
    GpuBuffer waves, phases, points, results, cell_origins;
    GpuBuffer river_texels, river_channel, river_waves;  // placeholders outside river mode
    GpuBuffer wake_points;
    const tidewater::detail::RiverBake* uploaded_river = nullptr;
    detail::ShoreBuffers shore;  // the same upload the renderer uses

    /// Grows `buffer` to hold at least `bytes`; reports whether it was replaced.
    Result<bool> ensure(GpuBuffer& buffer, VkDeviceSize bytes) {
        if (buffer.handle() && buffer.size() >= bytes) return false;
        auto fresh = GpuBuffer::create(ctx, std::max<VkDeviceSize>(bytes, 256), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!fresh) return fresh.error();
        buffer = std::move(fresh).value();
        return true;
    }

    void bind_buffers() {
        std::array<detail::BoundResource, gpu::eQueryBindingCount> r;
        r[gpu::eQueryWaves] = detail::bound_buffer(waves.handle());
        r[gpu::eQueryBasePhases] = detail::bound_buffer(phases.handle());
        r[gpu::eQueryPoints] = detail::bound_buffer(points.handle());
        r[gpu::eQueryResults] = detail::bound_buffer(results.handle());
        r[gpu::eQueryShoreWaves] = detail::bound_buffer(shore.per_wave());
        r[gpu::eQueryShoreShared] = detail::bound_buffer(shore.shared());
        r[gpu::eQueryShorePages] = detail::bound_buffer(shore.pages());
        r[gpu::eQueryShoreLayers] = detail::bound_buffer(shore.layers());
        r[gpu::eQueryCellOrigins] = detail::bound_buffer(cell_origins.handle());
        r[gpu::eQueryRiverTexels] = detail::bound_buffer(river_texels.handle());
        r[gpu::eQueryRiverChannel] = detail::bound_buffer(river_channel.handle());
        r[gpu::eQueryRiverWaves] = detail::bound_buffer(river_waves.handle());
        r[gpu::eQueryWakePoints] = detail::bound_buffer(wake_points.handle());
        detail::write_set(ctx, set, detail::kQuerySetRows, r);
    }

    /// Uploads a river's fields (null: placeholders) unless they are there already.
    Result<bool> use_river(const tidewater::detail::RiverBake* river);

    /// Solves `points` against `still` (its waves and shore) or, with `river`, the river's
    /// water with `still` fading in at its mouth. `flow`, when not empty, receives the
    /// current (xy) and flow-detail slope (zw) at each point. `wakes` (null: none) ride
    /// still water only.
    Status solve(const WaterBody& still, const RiverDispatch* river, double time,
                 std::span<const glm::dvec2> query_points, std::span<SurfacePoint> out, std::span<glm::vec4> flow,
                 const Wakes* wakes = nullptr);
};

Result<bool> GpuQuery::Impl::use_river(const tidewater::detail::RiverBake* river) {
    if (river_texels.handle() && river == uploaded_river) return false;
    std::vector<float> texels;
    std::vector<glm::vec4> channel;
    if (river) detail::append_river_fields(*river, texels, channel);
    auto fresh_texels = GpuBuffer::storage_with(ctx, texels.data(), texels.size() * sizeof(float));
    if (!fresh_texels) return fresh_texels.error();
    auto fresh_channel = GpuBuffer::storage_with(ctx, channel.data(), channel.size() * sizeof(glm::vec4));
    if (!fresh_channel) return fresh_channel.error();
    river_texels = std::move(fresh_texels).value();
    river_channel = std::move(fresh_channel).value();
    uploaded_river = river;
    return true;
}

GpuQuery::GpuQuery(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuQuery::~GpuQuery() = default;

Result<std::unique_ptr<GpuQuery>> GpuQuery::create(const DeviceContext& context) {
    if (!context.device || !context.queue || !context.physical_device) {
        return Error{ErrorCode::invalid_argument,
                     "GpuQuery: the DeviceContext has no device, physical device or queue"};
    }
    auto device = detail::load_device(context);
    if (!device) return device.error();
    auto impl = std::make_unique<Impl>();
    impl->ctx = std::move(device).value();
    const detail::Device& ctx = impl->ctx;
    const detail::VulkanFunctions& vk = ctx.vk();

    TW_VK_TRY(detail::make_set_layout(ctx, detail::kQuerySetRows, VK_SHADER_STAGE_COMPUTE_BIT, impl->set_layout));
    const VkDescriptorSetLayout set_layout = impl->set_layout.get();

    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::GpuQueryParams)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    TW_VK_TRY(detail::make_owned(ctx, impl->pipeline_layout, [&](VkPipelineLayout* out) {
        return vk.CreatePipelineLayout(ctx.device, &layout_info, ctx.allocator, out);
    }));

    const auto spirv = detail::embedded_spirv("query.comp");
    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = spirv.size_bytes();
    module_info.pCode = spirv.data();
    detail::OwnedShaderModule module;
    TW_VK_TRY(detail::make_owned(ctx, module, [&](VkShaderModule* out) {
        return vk.CreateShaderModule(ctx.device, &module_info, ctx.allocator, out);
    }));
    VkComputePipelineCreateInfo pipe{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipe.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipe.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipe.stage.module = module.get();
    pipe.stage.pName = "main";
    pipe.layout = impl->pipeline_layout.get();
    const VkResult made = detail::make_owned(ctx, impl->pipeline, [&](VkPipeline* out) {
        return vk.CreateComputePipelines(ctx.device, ctx.pipeline_cache, 1, &pipe, ctx.allocator, out);
    });
    if (made != VK_SUCCESS) return detail::vk_error(made, "vkCreateComputePipelines(query.comp)");

    TW_VK_TRY(detail::make_descriptor_pool(ctx, detail::kQuerySetRows, 1, impl->pool));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = impl->pool.get();
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout;
    TW_VK_TRY(vk.AllocateDescriptorSets(ctx.device, &alloc, &impl->set));

    VkCommandPoolCreateInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cmd_info.queueFamilyIndex = ctx.queue_family;
    cmd_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    TW_VK_TRY(detail::make_owned(ctx, impl->commands, [&](VkCommandPool* out) {
        return vk.CreateCommandPool(ctx.device, &cmd_info, ctx.allocator, out);
    }));
    return std::unique_ptr<GpuQuery>(new GpuQuery(std::move(impl)));
}

Status GpuQuery::Impl::solve(const WaterBody& still, const RiverDispatch* river, double time,
                             std::span<const glm::dvec2> query_points, std::span<SurfacePoint> out,
                             std::span<glm::vec4> flow, const Wakes* wakes) {
    const WaveSet& still_set = still.waves();
    const bool river_mode = river != nullptr;
    // The still water's waves: none in a river's own channel away from its mouth.
    const bool still_waves = !river_mode || river->still;
    const detail::PhaseCells cells = detail::build_phase_cells(still_set, still.local_time(time), query_points);
    auto wave_data = detail::gpu_waves(still_set);
    if (!still_waves) wave_data.clear();

    const std::vector<gpu::GpuRiverWave> channel_waves =
        river_mode ? detail::gpu_river_waves(*river->body, time, river->river->mean_speed)
                   : std::vector<gpu::GpuRiverWave>{};
    const double river_max_offset = river_mode ? river->body->waves().max_horizontal_displacement() : 0.0;
    bool rebind = false;
    for (auto [buffer, bytes] :
         {std::pair{&waves, sizeof(gpu::GpuWave) * std::max<std::size_t>(1, wave_data.size())},
          std::pair{&phases, sizeof(float) * std::max<std::size_t>(1, cells.base_phase.size())},
          std::pair{&points, sizeof(gpu::GpuQueryPoint) * query_points.size()},
          std::pair{&results, sizeof(gpu::GpuQueryResult) * query_points.size()},
          std::pair{&river_waves, sizeof(gpu::GpuRiverWave) * std::max<std::size_t>(1, channel_waves.size())}}) {
        auto grown = ensure(*buffer, bytes);
        if (!grown) return grown.error();
        rebind = rebind || *grown;
    }
    // Every submit below waits for completion: no GPU work can still read the old fields.
    auto uploaded = shore.upload(ctx, still_waves ? still.shore() : nullptr);
    if (!uploaded) return uploaded.error();
    rebind = rebind || *uploaded;
    // A query answers from the full-resolution fields: a coarse level (the fields past what
    // one storage buffer may span on this device) would answer something else.
    if (shore.stride() > 1)
        return Error{ErrorCode::unsupported,
                     fmt::format("GPU query: the shore model's fields ({:.0f} MiB) are more than one storage buffer "
                                 "spans on this device: query on the CPU, or bake the shore coarser",
                                 static_cast<double>(still.shore()->device_bytes()) / 1048576.0)};
    auto river_uploaded = use_river(river_mode ? river->river : nullptr);
    if (!river_uploaded) return river_uploaded.error();
    rebind = rebind || *river_uploaded;
    const ShoreWaves* model = shore.model();
    const detail::ShorePlacement placed = shore.placement(0);  // the grid the fields were packed on
    // Cell origins are relative to the river grid's corner in river mode, else to the shore's.
    const glm::dvec2 zero = river_mode ? river->river->grid.corner : (model ? placed.corner : glm::dvec2(0.0));
    std::vector<glm::vec2> origins(std::max<std::size_t>(1, cells.origins.size()), glm::vec2(0.0f));
    for (std::size_t c = 0; c < cells.origins.size(); ++c) {
        const glm::dvec2 rel = cells.origins[c] - zero;
        origins[c] = glm::vec2(static_cast<float>(rel.x), static_cast<float>(rel.y));
    }
    auto grown_origins = ensure(cell_origins, sizeof(glm::vec2) * origins.size());
    if (!grown_origins) return grown_origins.error();
    rebind = rebind || *grown_origins;
    // The wakes, relative to the cell origins' zero (still water only).
    detail::WakeUpload wake_upload;
    if (wakes != nullptr && !river_mode) {
        auto packed = detail::pack_wakes(*wakes, time, zero);
        if (!packed) return packed.error();
        wake_upload = std::move(packed).value();
    }
    auto grown_wakes =
        ensure(wake_points, detail::wake_buffer_bytes(std::max<std::size_t>(1, wake_upload.points.size())));
    if (!grown_wakes) return grown_wakes.error();
    rebind = rebind || *grown_wakes;
    if (rebind) bind_buffers();
    std::memcpy(cell_origins.mapped(), origins.data(), sizeof(glm::vec2) * origins.size());
    if (!wave_data.empty()) std::memcpy(waves.mapped(), wave_data.data(), sizeof(gpu::GpuWave) * wave_data.size());
    if (!channel_waves.empty())
        std::memcpy(river_waves.mapped(), channel_waves.data(), sizeof(gpu::GpuRiverWave) * channel_waves.size());
    std::memcpy(phases.mapped(), cells.base_phase.data(), sizeof(float) * cells.base_phase.size());
    std::memcpy(points.mapped(), cells.points.data(), sizeof(gpu::GpuQueryPoint) * query_points.size());
    detail::write_wake_buffer(wake_upload, wake_points.mapped());

    // The shader derives the tolerance and step bound from sum(Q A) as the CPU does.
    gpu::GpuQueryParams params{};
    params.wave_count = static_cast<std::uint32_t>(wave_data.size());
    params.point_count = static_cast<std::uint32_t>(query_points.size());
    params.max_offset =
        static_cast<float>((still_waves ? still_set.max_horizontal_displacement() : 0.0) + river_max_offset);
    params.river_wave_count = static_cast<std::uint32_t>(channel_waves.size());
    params.shore_resolution = model ? static_cast<std::uint32_t>(placed.resolution) : 0u;
    params.shore_texel = model ? static_cast<float>(placed.texel) : 1.0f;
    if (model && river_mode) {
        const glm::dvec2 offset = placed.corner - zero;
        params.shore_offset = glm::vec2(static_cast<float>(offset.x), static_cast<float>(offset.y));
    }
    if (river_mode) {
        params.river_nx = static_cast<std::uint32_t>(river->river->grid.nx);
        params.river_nz = static_cast<std::uint32_t>(river->river->grid.nz);
        params.river_texel = static_cast<float>(river->river->grid.texel);
        params.still = river->still ? 1.0f : 0.0f;
        params.river_bank_ramp = static_cast<float>(tidewater::detail::river_bank_ramp_depth(river->body->waves()));
        params.flow = detail::gpu_flow_detail(river->body->profile().flow, river->body->local_time(time), zero);
    }
    params.wake_count = static_cast<std::uint32_t>(wake_upload.points.size());
    params.wake_turbulent = wake_upload.turbulent;
    params.wake_radius = static_cast<float>(wake_upload.displacement_bound);

    const detail::VulkanFunctions& vk = ctx.vk();
    Status st = detail::submit_and_wait(ctx, commands.get(), [&](VkCommandBuffer cmd) {
        vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
        vk.CmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout.get(), 0, 1, &set, 0, nullptr);
        vk.CmdPushConstants(cmd, pipeline_layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(params), &params);
        vk.CmdDispatch(cmd, (params.point_count + gpu::kQueryWorkgroupSize - 1) / gpu::kQueryWorkgroupSize, 1, 1);
        VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vk.CmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                              nullptr, 0, nullptr);
    });
    if (!st) return st;

    const double level = river_mode ? river->river->mouth_level : still.level();
    // As the CPU: the still body's whitecaps where its waves join, else the river's.
    const double whitecap = river_mode && !river->still ? river->body->whitecap_jacobian() : still.whitecap_jacobian();
    const auto* r = static_cast<const gpu::GpuQueryResult*>(results.mapped());
    for (std::size_t i = 0; i < query_points.size(); ++i) {
        SurfacePoint& o = out[i];
        o.height = level + static_cast<double>(r[i].height_normal.x);
        o.normal = {r[i].height_normal.y, r[i].height_normal.z, r[i].height_normal.w};
        o.velocity = {r[i].velocity_jac.x, r[i].velocity_jac.y, r[i].velocity_jac.z};
        o.jacobian = static_cast<double>(r[i].velocity_jac.w);
        o.displacement = {r[i].disp_iter.x, r[i].disp_iter.y};
        o.iterations = static_cast<int>(r[i].disp_iter.z);
        o.converged = r[i].disp_iter.w != 0.0f;
        o.depth = model || river_mode ? shore_far_to_infinite(static_cast<double>(r[i].shore.x)) : kDeepWater;
        o.shore_distance = model ? shore_far_to_infinite(static_cast<double>(r[i].shore.y)) : kDeepWater;
        const double rest_surface = river_mode ? level + static_cast<double>(r[i].shore.w) : still.level();
        o.wet = tidewater::detail::surface_wet(o.height, rest_surface, o.depth);
        const std::array<double, tidewater::detail::kFoamLags> lagged{r[i].lagged_jac.x, r[i].lagged_jac.y,
                                                                      r[i].lagged_jac.z, r[i].lagged_jac.w};
        o.foam = tidewater::detail::surface_foam(model ? static_cast<double>(r[i].shore.z) : 0.0, o.jacobian, lagged,
                                                 whitecap);
        o.wake = static_cast<double>(r[i].wake.x);
        o.foam = std::max(o.foam, static_cast<double>(r[i].wake.y));
        if (!flow.empty()) flow[i] = r[i].flow;
    }
    return {};
}

Status GpuQuery::query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                               std::span<SurfacePoint> out, const Wakes* wakes) {
    if (points.size() != out.size()) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("GPU query: {} points but room for {} results", points.size(), out.size())};
    }
    if (points.empty()) return {};
    if (points.size() > (1u << 26)) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("GPU query: {} points in one call, at most 2^26", points.size())};
    }
    return impl_->solve(body, nullptr, time, points, out, {}, wakes);
}

Status GpuQuery::query_world(const Scene& scene, double time, std::span<const glm::dvec2> points,
                             std::span<WorldPoint> out, std::span<glm::dvec2> detail) {
    if (points.size() != out.size() || (!detail.empty() && detail.size() != points.size()))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("GPU query_world: {} points but room for {} results", points.size(), out.size())};
    const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
    if (has_bodies && (!scene.bake || !scene.bake->bodies || !scene.baked()))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("GPU query_world: {} has lakes or rivers but is not baked (or was edited since): pass "
                                 "it through bake_scene first",
                                 scene_label(scene))};
    if (points.empty()) return {};
    if (points.size() > (1u << 26))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("GPU query_world: {} points in one call, at most 2^26", points.size())};
    namespace td = tidewater::detail;
    const td::WaterBodiesBake* bodies = scene.bake ? scene.bake->bodies.get() : nullptr;
    const td::BodyFinder finder(scene, bodies);
    // The scene's boats (boat i is emitter i) ride the ocean and the lakes.
    Wakes boats;
    scene_boat_wakes(scene.boats, time, boats);
    const Wakes* wakes = scene.boats.empty() ? nullptr : &boats;
    std::vector<td::PointBody> where(points.size());
    std::vector<std::vector<std::size_t>> groups(finder.evaluation_count());
    for (std::size_t i = 0; i < points.size(); ++i) {
        where[i] = finder.find(points[i]);
        groups[where[i].evaluation].push_back(i);
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::vector<std::size_t>& members = groups[g];
        if (members.empty()) continue;
        std::vector<glm::dvec2> group_points(members.size());
        for (std::size_t k = 0; k < members.size(); ++k) group_points[k] = points[members[k]];
        std::vector<SurfacePoint> results(members.size());
        std::vector<glm::vec4> flow(members.size(), glm::vec4(0.0f));
        const td::EvaluationKey key = finder.evaluation_key(g);
        Status st;
        switch (key.kind) {
            case td::EvaluationKind::land:
                for (std::size_t k = 0; k < members.size(); ++k) results[k] = td::land_surface(scene, group_points[k]);
                break;
            case td::EvaluationKind::ocean:
                st = impl_->solve(scene.ocean, nullptr, time, group_points, results, {}, wakes);
                break;
            case td::EvaluationKind::lake:
                st = impl_->solve(scene.lakes[static_cast<std::size_t>(key.lake)].body, nullptr, time, group_points,
                                  results, {}, wakes);
                break;
            case td::EvaluationKind::river: {
                const td::RiverBake& baked = bodies->rivers[static_cast<std::size_t>(key.river)];
                RiverDispatch river{&baked, &scene.rivers[static_cast<std::size_t>(key.river)].body, key.plume};
                st = impl_->solve(td::still_body(scene, baked), &river, time, group_points, results, flow);
                break;
            }
        }
        if (!st) return st;
        for (std::size_t k = 0; k < members.size(); ++k) {
            const std::size_t i = members[k];
            out[i] = td::world_point(scene, key, where[i], results[k], glm::dvec2(flow[k].x, flow[k].y));
            if (!detail.empty()) detail[i] = glm::dvec2(flow[k].z, flow[k].w);
        }
    }
    return {};
}

}  // namespace tidewater::render
