// Tidewater's Vulkan calls go through one table of function pointers (private), loaded
// from the host's vkGetInstanceProcAddr / vkGetDeviceProcAddr when it hands them in
// (DeviceContext), or taken from the system loader. Every render source includes this
// header after <vulkan/vulkan.h>: each vkFunction name below then reads the table that
// the public call being served made current (ScopedDispatch), or the system loader's.
// Threading: the current table is per thread.
#pragma once

#include <memory>
#include <vulkan/vulkan.h>

#include "tidewater/render/device_context.hpp"
#include "tidewater/result.hpp"

// Instance-level functions (loaded with vkGetInstanceProcAddr).
#define TIDEWATER_VK_INSTANCE_FUNCTIONS(X) \
    X(CreateDevice) \
    X(DestroyInstance) \
    X(EnumeratePhysicalDevices) \
    X(GetPhysicalDeviceFeatures) \
    X(GetPhysicalDeviceFeatures2) \
    X(GetPhysicalDeviceFormatProperties) \
    X(GetPhysicalDeviceImageFormatProperties) \
    X(GetPhysicalDeviceMemoryProperties) \
    X(GetPhysicalDeviceProperties) \
    X(GetPhysicalDeviceQueueFamilyProperties)
// Device-level functions (loaded with vkGetDeviceProcAddr).
#define TIDEWATER_VK_DEVICE_FUNCTIONS(X) \
    X(AllocateCommandBuffers) \
    X(AllocateDescriptorSets) \
    X(AllocateMemory) \
    X(BeginCommandBuffer) \
    X(BindBufferMemory) \
    X(BindImageMemory) \
    X(CmdBeginRendering) \
    X(CmdBindDescriptorSets) \
    X(CmdBindIndexBuffer) \
    X(CmdBindPipeline) \
    X(CmdBindVertexBuffers) \
    X(CmdCopyBufferToImage) \
    X(CmdCopyImage) \
    X(CmdCopyImageToBuffer) \
    X(CmdDispatch) \
    X(CmdDraw) \
    X(CmdDrawIndexed) \
    X(CmdEndRendering) \
    X(CmdPipelineBarrier) \
    X(CmdPushConstants) \
    X(CmdResolveImage) \
    X(CmdResetQueryPool) \
    X(CmdSetScissor) \
    X(CmdSetViewport) \
    X(CmdWriteTimestamp) \
    X(CreateBuffer) \
    X(CreateCommandPool) \
    X(CreateComputePipelines) \
    X(CreateDescriptorPool) \
    X(CreateDescriptorSetLayout) \
    X(CreateFence) \
    X(CreateGraphicsPipelines) \
    X(CreateImage) \
    X(CreateImageView) \
    X(CreatePipelineLayout) \
    X(CreateQueryPool) \
    X(CreateSampler) \
    X(CreateShaderModule) \
    X(DestroyBuffer) \
    X(DestroyCommandPool) \
    X(DestroyDescriptorPool) \
    X(DestroyDescriptorSetLayout) \
    X(DestroyDevice) \
    X(DestroyFence) \
    X(DestroyImage) \
    X(DestroyImageView) \
    X(DestroyPipeline) \
    X(DestroyPipelineLayout) \
    X(DestroyQueryPool) \
    X(DestroySampler) \
    X(DestroyShaderModule) \
    X(DeviceWaitIdle) \
    X(EndCommandBuffer) \
    X(FreeCommandBuffers) \
    X(FreeMemory) \
    X(GetBufferMemoryRequirements) \
    X(GetDeviceQueue) \
    X(GetImageMemoryRequirements) \
    X(GetQueryPoolResults) \
    X(MapMemory) \
    X(QueueSubmit) \
    X(ResetCommandPool) \
    X(UpdateDescriptorSets) \
    X(WaitForFences)

namespace tidewater::render::detail {

struct VulkanFunctions {
#define TIDEWATER_VK_MEMBER(name) PFN_vk##name name = nullptr;
    TIDEWATER_VK_INSTANCE_FUNCTIONS(TIDEWATER_VK_MEMBER)
    TIDEWATER_VK_DEVICE_FUNCTIONS(TIDEWATER_VK_MEMBER)
#undef TIDEWATER_VK_MEMBER
};

/// The system loader's functions.
const VulkanFunctions& system_functions();
/// The functions for `ctx`: the system loader's unless it carries the host's
/// get_instance_proc_addr / get_device_proc_addr; an error names a function they lack.
Result<std::shared_ptr<const VulkanFunctions>> load_functions(const DeviceContext& ctx);
/// The table the current thread's public call uses (the system loader's by default).
const VulkanFunctions& dispatch();

/// Makes `functions` current on this thread for its lifetime (nests).
class ScopedDispatch {
public:
    explicit ScopedDispatch(const VulkanFunctions* functions);
    ~ScopedDispatch();
    ScopedDispatch(const ScopedDispatch&) = delete;
    ScopedDispatch& operator=(const ScopedDispatch&) = delete;

private:
    const VulkanFunctions* previous_;
};

}  // namespace tidewater::render::detail

#ifndef TIDEWATER_VK_NO_REDIRECT
#define vkAllocateCommandBuffers (::tidewater::render::detail::dispatch().AllocateCommandBuffers)
#define vkAllocateDescriptorSets (::tidewater::render::detail::dispatch().AllocateDescriptorSets)
#define vkAllocateMemory (::tidewater::render::detail::dispatch().AllocateMemory)
#define vkBeginCommandBuffer (::tidewater::render::detail::dispatch().BeginCommandBuffer)
#define vkBindBufferMemory (::tidewater::render::detail::dispatch().BindBufferMemory)
#define vkBindImageMemory (::tidewater::render::detail::dispatch().BindImageMemory)
#define vkCmdBeginRendering (::tidewater::render::detail::dispatch().CmdBeginRendering)
#define vkCmdBindDescriptorSets (::tidewater::render::detail::dispatch().CmdBindDescriptorSets)
#define vkCmdBindIndexBuffer (::tidewater::render::detail::dispatch().CmdBindIndexBuffer)
#define vkCmdBindPipeline (::tidewater::render::detail::dispatch().CmdBindPipeline)
#define vkCmdBindVertexBuffers (::tidewater::render::detail::dispatch().CmdBindVertexBuffers)
#define vkCmdCopyBufferToImage (::tidewater::render::detail::dispatch().CmdCopyBufferToImage)
#define vkCmdCopyImage (::tidewater::render::detail::dispatch().CmdCopyImage)
#define vkCmdCopyImageToBuffer (::tidewater::render::detail::dispatch().CmdCopyImageToBuffer)
#define vkCmdResolveImage (::tidewater::render::detail::dispatch().CmdResolveImage)
#define vkCmdDispatch (::tidewater::render::detail::dispatch().CmdDispatch)
#define vkCmdDraw (::tidewater::render::detail::dispatch().CmdDraw)
#define vkCmdDrawIndexed (::tidewater::render::detail::dispatch().CmdDrawIndexed)
#define vkCmdEndRendering (::tidewater::render::detail::dispatch().CmdEndRendering)
#define vkCmdPipelineBarrier (::tidewater::render::detail::dispatch().CmdPipelineBarrier)
#define vkCmdPushConstants (::tidewater::render::detail::dispatch().CmdPushConstants)
#define vkCmdResetQueryPool (::tidewater::render::detail::dispatch().CmdResetQueryPool)
#define vkCmdSetScissor (::tidewater::render::detail::dispatch().CmdSetScissor)
#define vkCmdSetViewport (::tidewater::render::detail::dispatch().CmdSetViewport)
#define vkCmdWriteTimestamp (::tidewater::render::detail::dispatch().CmdWriteTimestamp)
#define vkCreateBuffer (::tidewater::render::detail::dispatch().CreateBuffer)
#define vkCreateCommandPool (::tidewater::render::detail::dispatch().CreateCommandPool)
#define vkCreateComputePipelines (::tidewater::render::detail::dispatch().CreateComputePipelines)
#define vkCreateDescriptorPool (::tidewater::render::detail::dispatch().CreateDescriptorPool)
#define vkCreateDescriptorSetLayout (::tidewater::render::detail::dispatch().CreateDescriptorSetLayout)
#define vkCreateDevice (::tidewater::render::detail::dispatch().CreateDevice)
#define vkCreateFence (::tidewater::render::detail::dispatch().CreateFence)
#define vkCreateGraphicsPipelines (::tidewater::render::detail::dispatch().CreateGraphicsPipelines)
#define vkCreateImage (::tidewater::render::detail::dispatch().CreateImage)
#define vkCreateImageView (::tidewater::render::detail::dispatch().CreateImageView)
#define vkCreatePipelineLayout (::tidewater::render::detail::dispatch().CreatePipelineLayout)
#define vkCreateQueryPool (::tidewater::render::detail::dispatch().CreateQueryPool)
#define vkCreateSampler (::tidewater::render::detail::dispatch().CreateSampler)
#define vkCreateShaderModule (::tidewater::render::detail::dispatch().CreateShaderModule)
#define vkDestroyBuffer (::tidewater::render::detail::dispatch().DestroyBuffer)
#define vkDestroyCommandPool (::tidewater::render::detail::dispatch().DestroyCommandPool)
#define vkDestroyDescriptorPool (::tidewater::render::detail::dispatch().DestroyDescriptorPool)
#define vkDestroyDescriptorSetLayout (::tidewater::render::detail::dispatch().DestroyDescriptorSetLayout)
#define vkDestroyDevice (::tidewater::render::detail::dispatch().DestroyDevice)
#define vkDestroyFence (::tidewater::render::detail::dispatch().DestroyFence)
#define vkDestroyImage (::tidewater::render::detail::dispatch().DestroyImage)
#define vkDestroyImageView (::tidewater::render::detail::dispatch().DestroyImageView)
#define vkDestroyInstance (::tidewater::render::detail::dispatch().DestroyInstance)
#define vkDestroyPipeline (::tidewater::render::detail::dispatch().DestroyPipeline)
#define vkDestroyPipelineLayout (::tidewater::render::detail::dispatch().DestroyPipelineLayout)
#define vkDestroyQueryPool (::tidewater::render::detail::dispatch().DestroyQueryPool)
#define vkDestroySampler (::tidewater::render::detail::dispatch().DestroySampler)
#define vkDestroyShaderModule (::tidewater::render::detail::dispatch().DestroyShaderModule)
#define vkDeviceWaitIdle (::tidewater::render::detail::dispatch().DeviceWaitIdle)
#define vkEndCommandBuffer (::tidewater::render::detail::dispatch().EndCommandBuffer)
#define vkEnumeratePhysicalDevices (::tidewater::render::detail::dispatch().EnumeratePhysicalDevices)
#define vkFreeCommandBuffers (::tidewater::render::detail::dispatch().FreeCommandBuffers)
#define vkFreeMemory (::tidewater::render::detail::dispatch().FreeMemory)
#define vkGetBufferMemoryRequirements (::tidewater::render::detail::dispatch().GetBufferMemoryRequirements)
#define vkGetDeviceQueue (::tidewater::render::detail::dispatch().GetDeviceQueue)
#define vkGetImageMemoryRequirements (::tidewater::render::detail::dispatch().GetImageMemoryRequirements)
#define vkGetPhysicalDeviceFeatures (::tidewater::render::detail::dispatch().GetPhysicalDeviceFeatures)
#define vkGetPhysicalDeviceFeatures2 (::tidewater::render::detail::dispatch().GetPhysicalDeviceFeatures2)
#define vkGetPhysicalDeviceFormatProperties (::tidewater::render::detail::dispatch().GetPhysicalDeviceFormatProperties)
#define vkGetPhysicalDeviceImageFormatProperties (::tidewater::render::detail::dispatch().GetPhysicalDeviceImageFormatProperties)
#define vkGetPhysicalDeviceMemoryProperties (::tidewater::render::detail::dispatch().GetPhysicalDeviceMemoryProperties)
#define vkGetPhysicalDeviceProperties (::tidewater::render::detail::dispatch().GetPhysicalDeviceProperties)
#define vkGetPhysicalDeviceQueueFamilyProperties (::tidewater::render::detail::dispatch().GetPhysicalDeviceQueueFamilyProperties)
#define vkGetQueryPoolResults (::tidewater::render::detail::dispatch().GetQueryPoolResults)
#define vkMapMemory (::tidewater::render::detail::dispatch().MapMemory)
#define vkQueueSubmit (::tidewater::render::detail::dispatch().QueueSubmit)
#define vkResetCommandPool (::tidewater::render::detail::dispatch().ResetCommandPool)
#define vkUpdateDescriptorSets (::tidewater::render::detail::dispatch().UpdateDescriptorSets)
#define vkWaitForFences (::tidewater::render::detail::dispatch().WaitForFences)
#endif
