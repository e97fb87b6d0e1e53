#include "frame_timer.hpp"

#include <vector>

#include "vk_util.hpp"

namespace tidewater::render::detail {

namespace {

// Written in this order (the bits' order) by vkGetQueryPoolResults.
constexpr VkQueryPipelineStatisticFlags kCounted =
    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT | VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT;
constexpr std::uint32_t kCountedValues = 5;

}  // namespace

Result<FrameTimer> FrameTimer::create(const Device& ctx, std::uint32_t slots) {
    FrameTimer t;
    std::uint32_t family_count = 0;
    ctx.vk().GetPhysicalDeviceQueueFamilyProperties(ctx.physical_device, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    ctx.vk().GetPhysicalDeviceQueueFamilyProperties(ctx.physical_device, &family_count, families.data());
    if (ctx.enabled_features.pipelineStatisticsQuery) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        info.queryCount = pass_count * slots;
        info.pipelineStatistics = kCounted;
        TW_VK_TRY(make_owned(ctx, t.invocations_, [&](VkQueryPool* out) {
            return ctx.vk().CreateQueryPool(ctx.device, &info, ctx.allocator, out);
        }));
        if (ctx.enabled_features.occlusionQueryPrecise) {
            VkQueryPoolCreateInfo samples{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
            samples.queryType = VK_QUERY_TYPE_OCCLUSION;
            samples.queryCount = pass_count * slots;
            TW_VK_TRY(make_owned(ctx, t.samples_, [&](VkQueryPool* out) {
                return ctx.vk().CreateQueryPool(ctx.device, &samples, ctx.allocator, out);
            }));
        }
    }
    if (ctx.queue_family >= family_count || families[ctx.queue_family].timestampValidBits == 0) return t;
    VkPhysicalDeviceProperties props;
    ctx.vk().GetPhysicalDeviceProperties(ctx.physical_device, &props);
    t.period_ns_ = static_cast<double>(props.limits.timestampPeriod);
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = mark_count * slots;
    TW_VK_TRY(make_owned(ctx, t.pool_, [&](VkQueryPool* out) {
        return ctx.vk().CreateQueryPool(ctx.device, &info, ctx.allocator, out);
    }));
    return t;
}

void FrameTimer::begin_pass(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Pass pass) const {
    if (invocations_) vk.CmdBeginQuery(cmd, invocations_.get(), slot * pass_count + pass, 0);
    if (samples_) vk.CmdBeginQuery(cmd, samples_.get(), slot * pass_count + pass, VK_QUERY_CONTROL_PRECISE_BIT);
}

void FrameTimer::end_pass(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Pass pass) const {
    if (invocations_) vk.CmdEndQuery(cmd, invocations_.get(), slot * pass_count + pass);
    if (samples_) vk.CmdEndQuery(cmd, samples_.get(), slot * pass_count + pass);
}

void FrameTimer::begin(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot) const {
    if (invocations_) vk.CmdResetQueryPool(cmd, invocations_.get(), slot * pass_count, pass_count);
    if (samples_) vk.CmdResetQueryPool(cmd, samples_.get(), slot * pass_count, pass_count);
    if (!pool_) return;
    vk.CmdResetQueryPool(cmd, pool_.get(), slot * mark_count, mark_count);
    vk.CmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), slot * mark_count + start);
}

void FrameTimer::mark(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Mark m,
                      VkPipelineStageFlagBits stage) const {
    if (pool_) vk.CmdWriteTimestamp(cmd, stage, pool_.get(), slot * mark_count + m);
}

Result<PassTimings> FrameTimer::read(const Device& ctx, std::uint32_t slot) const {
    if (!pool_) return Error{ErrorCode::unsupported, "renderer: this queue has no timestamps"};
    std::uint64_t ticks[mark_count];
    const VkResult r =
        ctx.vk().GetQueryPoolResults(ctx.device, pool_.get(), slot * mark_count, mark_count, sizeof(ticks), ticks,
                                     sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT);
    if (r != VK_SUCCESS) return vk_error(r, "vkGetQueryPoolResults");
    auto ms = [&](Mark a, Mark b) { return static_cast<double>(ticks[b] - ticks[a]) * period_ns_ * 1e-6; };
    PassTimings p;
    p.sky_and_terrain_ms = ms(start, opaque_done);
    p.scene_copy_ms = ms(opaque_done, copy_done);
    p.water_ms = ms(copy_done, water_done);
    p.total_ms = ms(start, water_done);
    if (invocations_) {
        std::uint64_t counts[pass_count][kCountedValues];
        const VkResult c =
            ctx.vk().GetQueryPoolResults(ctx.device, invocations_.get(), slot * pass_count, pass_count, sizeof(counts),
                                         counts, sizeof(counts[0]), VK_QUERY_RESULT_64_BIT);
        if (c != VK_SUCCESS) return vk_error(c, "vkGetQueryPoolResults (pipeline statistics)");
        auto invocations = [&](Pass pass) {
            const std::uint64_t* v = counts[pass];
            return PassInvocations{v[0], v[3], v[4], v[1], v[2]};
        };
        p.invocations_counted = true;
        p.opaque_invocations = invocations(opaque_pass);
        p.water_invocations = invocations(water_pass);
    }
    if (samples_) {
        std::uint64_t samples[pass_count];
        const VkResult s =
            ctx.vk().GetQueryPoolResults(ctx.device, samples_.get(), slot * pass_count, pass_count, sizeof(samples),
                                         samples, sizeof(samples[0]), VK_QUERY_RESULT_64_BIT);
        if (s != VK_SUCCESS) return vk_error(s, "vkGetQueryPoolResults (occlusion)");
        p.samples_counted = true;
        p.opaque_invocations.samples_passed = samples[opaque_pass];
        p.water_invocations.samples_passed = samples[water_pass];
    }
    return p;
}

}  // namespace tidewater::render::detail
