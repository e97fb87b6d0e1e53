// A device as a host's loader hook (DeviceContext::get_instance_proc_addr) may present
// it: reporting a smaller maxStorageBufferRange than the driver's, as a GPU with 128 MiB
// storage buffers does. Everything else is the system loader's.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "tidewater/render/device_context.hpp"

namespace tidewater::test {

/// The range reported while a context made by with_storage_range() is in use (bytes).
inline std::uint32_t& reported_storage_range() {
    static std::uint32_t range = 0;
    return range;
}

inline VKAPI_ATTR void VKAPI_CALL properties_with_storage_range(VkPhysicalDevice device,
                                                                VkPhysicalDeviceProperties* properties) {
    vkGetPhysicalDeviceProperties(device, properties);
    properties->limits.maxStorageBufferRange =
        std::min(properties->limits.maxStorageBufferRange, reported_storage_range());
}

inline VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL storage_range_instance_proc(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkGetPhysicalDeviceProperties") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&properties_with_storage_range);
    return vkGetInstanceProcAddr(instance, name);
}

inline VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL storage_range_device_proc(VkDevice device, const char* name) {
    return vkGetDeviceProcAddr(device, name);
}

/// `ctx` loaded through a hook that reports at most `range` bytes as the device's
/// maxStorageBufferRange (one process-wide setting: one such context at a time).
inline render::DeviceContext with_storage_range(render::DeviceContext ctx, std::uint32_t range) {
    reported_storage_range() = range;
    ctx.get_instance_proc_addr = &storage_range_instance_proc;
    ctx.get_device_proc_addr = &storage_range_device_proc;
    return ctx;
}

}  // namespace tidewater::test
