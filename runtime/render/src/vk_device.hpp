// The Vulkan functions Tidewater calls (private), as one table loaded per device from
// the host's vkGetInstanceProcAddr / vkGetDeviceProcAddr (DeviceContext's loader hook)
// or from the system loader's. Nothing calls a vkFunction by its global name: the
// render library is compiled with VK_NO_PROTOTYPES, so a call that bypasses the table
// does not compile. A Device carries its table, and every owned handle keeps the table
// it was made with (vk_handle.hpp), so it is destroyed through the same functions on
// any thread.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <memory>

#include "tidewater/render/device_context.hpp"
#include "tidewater/result.hpp"

// Instance-level functions (loaded with vkGetInstanceProcAddr).
#define TIDEWATER_VK_INSTANCE_FUNCTIONS(X)    \
    X(GetPhysicalDeviceFormatProperties)      \
    X(GetPhysicalDeviceImageFormatProperties) \
    X(GetPhysicalDeviceMemoryProperties)      \
    X(GetPhysicalDeviceProperties)            \
    X(GetPhysicalDeviceQueueFamilyProperties)
// Device-level functions (loaded with vkGetDeviceProcAddr).
#define TIDEWATER_VK_DEVICE_FUNCTIONS(X) \
    X(AllocateCommandBuffers)            \
    X(AllocateDescriptorSets)            \
    X(AllocateMemory)                    \
    X(BeginCommandBuffer)                \
    X(BindBufferMemory)                  \
    X(BindImageMemory)                   \
    X(CmdBeginQuery)                     \
    X(CmdBeginRendering)                 \
    X(CmdBindDescriptorSets)             \
    X(CmdBindIndexBuffer)                \
    X(CmdBindPipeline)                   \
    X(CmdBindVertexBuffers)              \
    X(CmdCopyBufferToImage)              \
    X(CmdCopyImage)                      \
    X(CmdCopyImageToBuffer)              \
    X(CmdDispatch)                       \
    X(CmdDraw)                           \
    X(CmdDrawIndexed)                    \
    X(CmdEndQuery)                       \
    X(CmdEndRendering)                   \
    X(CmdPipelineBarrier)                \
    X(CmdPushConstants)                  \
    X(CmdResolveImage)                   \
    X(CmdResetQueryPool)                 \
    X(CmdSetScissor)                     \
    X(CmdSetViewport)                    \
    X(CmdWriteTimestamp)                 \
    X(CreateBuffer)                      \
    X(CreateCommandPool)                 \
    X(CreateComputePipelines)            \
    X(CreateDescriptorPool)              \
    X(CreateDescriptorSetLayout)         \
    X(CreateFence)                       \
    X(CreateGraphicsPipelines)           \
    X(CreateImage)                       \
    X(CreateImageView)                   \
    X(CreatePipelineLayout)              \
    X(CreateQueryPool)                   \
    X(CreateSampler)                     \
    X(CreateShaderModule)                \
    X(DestroyBuffer)                     \
    X(DestroyCommandPool)                \
    X(DestroyDescriptorPool)             \
    X(DestroyDescriptorSetLayout)        \
    X(DestroyFence)                      \
    X(DestroyImage)                      \
    X(DestroyImageView)                  \
    X(DestroyPipeline)                   \
    X(DestroyPipelineLayout)             \
    X(DestroyQueryPool)                  \
    X(DestroySampler)                    \
    X(DestroyShaderModule)               \
    X(DeviceWaitIdle)                    \
    X(EndCommandBuffer)                  \
    X(FreeCommandBuffers)                \
    X(FreeMemory)                        \
    X(GetBufferMemoryRequirements)       \
    X(GetImageMemoryRequirements)        \
    X(GetQueryPoolResults)               \
    X(MapMemory)                         \
    X(QueueSubmit)                       \
    X(ResetCommandPool)                  \
    X(UpdateDescriptorSets)              \
    X(WaitForFences)

// Loaded when DeviceContext::pipeline_executable_info says the extension is enabled.
#define TIDEWATER_VK_PIPELINE_EXECUTABLE_FUNCTIONS(X) \
    X(GetPipelineExecutablePropertiesKHR)             \
    X(GetPipelineExecutableStatisticsKHR)

namespace tidewater::render::detail {

/// One loaded Vulkan function. Calls that return a VkResult are [[nodiscard]]: a
/// result cannot be dropped without saying so.
template <typename Pfn>
struct VkFunction;
template <typename R, typename... Args>
struct VkFunction<R(VKAPI_PTR*)(Args...)> {
    R(VKAPI_PTR* pointer)(Args...) = nullptr;
    R operator()(Args... args) const { return pointer(args...); }
};
template <typename... Args>
struct VkFunction<VkResult(VKAPI_PTR*)(Args...)> {
    VkResult(VKAPI_PTR* pointer)(Args...) = nullptr;
    [[nodiscard]] VkResult operator()(Args... args) const { return pointer(args...); }
};

struct VulkanFunctions {
#define TIDEWATER_VK_MEMBER(name) VkFunction<PFN_vk##name> name;
    TIDEWATER_VK_INSTANCE_FUNCTIONS(TIDEWATER_VK_MEMBER)
    TIDEWATER_VK_DEVICE_FUNCTIONS(TIDEWATER_VK_MEMBER)
    TIDEWATER_VK_PIPELINE_EXECUTABLE_FUNCTIONS(TIDEWATER_VK_MEMBER)
#undef TIDEWATER_VK_MEMBER
    /// Bytes of device memory allocated through this table and not yet freed (GpuBuffer,
    /// GpuImage): what one Device's owner, a renderer say, holds. Any thread.
    mutable std::atomic<std::uint64_t> device_memory_bytes{0};
};

/// The host's device as Tidewater's code calls it: the context the host lent and the
/// functions loaded for it. Copies share the table.
struct Device : DeviceContext {
    std::shared_ptr<const VulkanFunctions> functions;
    const VulkanFunctions& vk() const { return *functions; }
};

/// The functions for `ctx`: through its get_instance_proc_addr / get_device_proc_addr
/// when it gives them (an error names any function they lack), else through the system
/// loader's. Fails when `ctx` has no instance or device.
Result<Device> load_device(const DeviceContext& ctx);

}  // namespace tidewater::render::detail
