// submit_and_wait's template body (private).
#pragma once

#include "vk_handle.hpp"
#include "vk_util.hpp"

namespace tidewater::render::detail {

template <typename Record>
Status submit_and_wait(const Device& ctx, VkCommandPool pool, const Record& record) {
    const VulkanFunctions& vk = ctx.vk();
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    TW_VK_TRY(vk.AllocateCommandBuffers(ctx.device, &alloc, &cmd));
    // One-shot pools serve one submission at a time: resetting with RELEASE hands the
    // recording memory back (some drivers keep it in the pool otherwise).
    auto release = [&]() -> VkResult {
        vk.FreeCommandBuffers(ctx.device, pool, 1, &cmd);
        return vk.ResetCommandPool(ctx.device, pool, VK_COMMAND_POOL_RESET_RELEASE_RESOURCES_BIT);
    };
    auto fail = [&](VkResult r, const char* call) {
        (void)release();  // the first failure is the one reported
        return vk_error(r, call);
    };
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (const VkResult r = vk.BeginCommandBuffer(cmd, &begin); r != VK_SUCCESS) return fail(r, "vkBeginCommandBuffer");
    record(cmd);
    if (const VkResult r = vk.EndCommandBuffer(cmd); r != VK_SUCCESS) return fail(r, "vkEndCommandBuffer");
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    OwnedFence fence;
    if (const VkResult r = make_owned(
            ctx, fence, [&](VkFence* out) { return vk.CreateFence(ctx.device, &fence_info, ctx.allocator, out); });
        r != VK_SUCCESS)
        return fail(r, "vkCreateFence");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    const VkFence f = fence.get();
    if (const VkResult r = vk.QueueSubmit(ctx.queue, 1, &submit, f); r != VK_SUCCESS) return fail(r, "vkQueueSubmit");
    if (const VkResult r = vk.WaitForFences(ctx.device, 1, &f, VK_TRUE, UINT64_MAX); r != VK_SUCCESS) {
        // A lost device: wait for the queue as far as it can so that nothing is freed in use.
        (void)vk.DeviceWaitIdle(ctx.device);
        return fail(r, "vkWaitForFences");
    }
    if (const VkResult r = release(); r != VK_SUCCESS) return vk_error(r, "vkResetCommandPool");
    return {};
}

}  // namespace tidewater::render::detail
