// The Vulkan objects a host lends to Tidewater's GPU parts.
//
// Lifetime: the host creates and destroys every handle here and must keep
// them alive until the Tidewater objects built on them are destroyed.
// Tidewater never destroys, resets or presents on them.
// Threading: Tidewater submits to `queue` only inside its explicit upload and
// query calls; the host must not use the queue from another thread during those.
#pragma once

#include <cstdint>
#include <vulkan/vulkan.h>

namespace tidewater::render {

struct DeviceContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;  ///< Created with Vulkan 1.3 dynamicRendering enabled.
    std::uint32_t queue_family = 0;    ///< Must support graphics and compute.
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t api_version = VK_API_VERSION_1_3;
    VkPipelineCache pipeline_cache = VK_NULL_HANDLE;  ///< Optional; used, never destroyed.
    const VkAllocationCallbacks* allocator = nullptr; ///< Optional; must outlive Tidewater's objects.
};

}  // namespace tidewater::render
