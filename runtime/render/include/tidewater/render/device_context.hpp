// The Vulkan objects a host lends to Tidewater's GPU parts.
//
// Lifetime: the host creates and destroys every handle here and must keep
// them alive until the Tidewater objects built on them are destroyed.
// Tidewater never destroys, resets or presents on them.
// Threading: Tidewater submits to `queue` and waits for the device only inside its
// explicit creation, upload and query calls (Renderer::create, set_scene, set_water,
// GpuQuery's queries, OffscreenTarget::render) and when destroyed; recording
// (record_frame, record_views, record_in_pass) and the views' add_view, remove_view and
// resize never submit or wait. The host must not use the queue from
// another thread during those calls.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tidewater::render {

struct DeviceContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;  ///< Vulkan 1.3, with the features below enabled.
    std::uint32_t queue_family = 0;    ///< Must support graphics and compute.
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t api_version = VK_API_VERSION_1_3;
    VkPipelineCache pipeline_cache = VK_NULL_HANDLE;   ///< Optional; used, never destroyed.
    const VkAllocationCallbacks* allocator = nullptr;  ///< Optional; must outlive Tidewater's objects.
    /// The core features the host enabled on `device` (what it gave vkCreateDevice in
    /// pEnabledFeatures or VkPhysicalDeviceFeatures2). The renderer needs
    /// tessellationShader, and fillModeNonSolid for its wireframe view
    /// (RendererInitInfo::wireframe); a missing one is an error naming it.
    VkPhysicalDeviceFeatures enabled_features{};
    /// Whether the host enabled VkPhysicalDeviceVulkan13Features::dynamicRendering (the
    /// renderer records with vkCmdBeginRendering).
    bool dynamic_rendering = false;
    /// Whether the host enabled VK_KHR_pipeline_executable_properties and its
    /// pipelineExecutableInfo feature: the renderer's pipelines are then built with their
    /// statistics captured (Renderer::pipeline_statistics). Optional.
    bool pipeline_executable_info = false;
    /// Optional loader hook for engines with their own Vulkan loader (volk-style): give
    /// both and every Vulkan function Tidewater calls on this context is loaded through
    /// them (instance-level ones with `instance`, the rest with `device`). Null (the
    /// default): the system loader's exported functions.
    PFN_vkGetInstanceProcAddr get_instance_proc_addr = nullptr;
    PFN_vkGetDeviceProcAddr get_device_proc_addr = nullptr;
};

}  // namespace tidewater::render
