// submit_and_wait's template body (private).
#pragma once

#include "vk_util.hpp"

namespace tidewater::render::detail {

template <typename Record>
Status submit_and_wait(const DeviceContext& ctx, VkCommandPool pool, const Record& record) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    TW_VK_TRY(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd));
    struct Free {
        const DeviceContext& c;
        VkCommandPool p;
        VkCommandBuffer b;
        // One-shot pools serve one submission at a time: resetting with RELEASE hands the
        // recording memory back (some drivers keep it in the pool otherwise).
        ~Free() {
            vkFreeCommandBuffers(c.device, p, 1, &b);
            vkResetCommandPool(c.device, p, VK_COMMAND_POOL_RESET_RELEASE_RESOURCES_BIT);
        }
    } free_cmd{ctx, pool, cmd};
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    TW_VK_TRY(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    TW_VK_TRY(vkEndCommandBuffer(cmd));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    TW_VK_TRY(vkCreateFence(ctx.device, &fence_info, ctx.allocator, &fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VkResult r = vkQueueSubmit(ctx.queue, 1, &submit, fence);
    if (r == VK_SUCCESS) r = vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, UINT64_MAX);
    vkDestroyFence(ctx.device, fence, ctx.allocator);
    if (r != VK_SUCCESS) return vk_error(r, "vkQueueSubmit/vkWaitForFences");
    return {};
}

}  // namespace tidewater::render::detail
