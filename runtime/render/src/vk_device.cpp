// The function tables behind vk_device.hpp. The system loader's two lookup functions
// are the only Vulkan names this library calls directly (declared here, since the
// library is compiled with VK_NO_PROTOTYPES).
#include "vk_device.hpp"

#include <fmt/format.h>

#include <string>

extern "C" {
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetInstanceProcAddr(VkInstance instance, const char* name);
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetDeviceProcAddr(VkDevice device, const char* name);
}

namespace tidewater::render::detail {

Result<Device> load_device(const DeviceContext& ctx) {
    if (!ctx.instance || !ctx.device) return Error{ErrorCode::invalid_argument, "DeviceContext: no instance or device"};
    const bool hooked = ctx.get_instance_proc_addr || ctx.get_device_proc_addr;
    if (hooked && (!ctx.get_instance_proc_addr || !ctx.get_device_proc_addr))
        return Error{
            ErrorCode::invalid_argument,
            "DeviceContext: give both get_instance_proc_addr and get_device_proc_addr, or neither (the system loader)"};
    const PFN_vkGetInstanceProcAddr instance_proc = hooked ? ctx.get_instance_proc_addr : &::vkGetInstanceProcAddr;
    const PFN_vkGetDeviceProcAddr device_proc = hooked ? ctx.get_device_proc_addr : &::vkGetDeviceProcAddr;
    auto f = std::make_shared<VulkanFunctions>();
    std::string missing;
    auto note_missing = [&](bool found, const char* name) {
        if (!found) missing += fmt::format("{}{}", missing.empty() ? "" : ", ", name);
    };
#define TIDEWATER_VK_LOAD_INSTANCE(name)                                                       \
    f->name.pointer = reinterpret_cast<PFN_vk##name>(instance_proc(ctx.instance, "vk" #name)); \
    note_missing(f->name.pointer != nullptr, "vk" #name);
#define TIDEWATER_VK_LOAD_DEVICE(name)                                                     \
    f->name.pointer = reinterpret_cast<PFN_vk##name>(device_proc(ctx.device, "vk" #name)); \
    note_missing(f->name.pointer != nullptr, "vk" #name);
    TIDEWATER_VK_INSTANCE_FUNCTIONS(TIDEWATER_VK_LOAD_INSTANCE)
    TIDEWATER_VK_DEVICE_FUNCTIONS(TIDEWATER_VK_LOAD_DEVICE)
    if (ctx.pipeline_executable_info) {
        TIDEWATER_VK_PIPELINE_EXECUTABLE_FUNCTIONS(TIDEWATER_VK_LOAD_DEVICE)
    }
#undef TIDEWATER_VK_LOAD_INSTANCE
#undef TIDEWATER_VK_LOAD_DEVICE
    if (!missing.empty())
        return Error{ErrorCode::unsupported, fmt::format("DeviceContext: the {} has no {}",
                                                         hooked ? "host's loader" : "Vulkan loader", missing)};
    Device device;
    static_cast<DeviceContext&>(device) = ctx;
    device.functions = std::move(f);
    return device;
}

}  // namespace tidewater::render::detail
