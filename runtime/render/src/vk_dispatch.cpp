// The function tables behind vk_dispatch.hpp. This file names the system loader's
// functions themselves, so it does not redirect them.
#define TIDEWATER_VK_NO_REDIRECT
#include "vk_dispatch.hpp"

#include <fmt/format.h>

namespace tidewater::render::detail {

namespace {
thread_local const VulkanFunctions* t_current = nullptr;
}  // namespace

const VulkanFunctions& system_functions() {
    static const VulkanFunctions table = [] {
        VulkanFunctions f;
#define TIDEWATER_VK_SYSTEM(name) f.name = &::vk##name;
        TIDEWATER_VK_INSTANCE_FUNCTIONS(TIDEWATER_VK_SYSTEM)
        TIDEWATER_VK_DEVICE_FUNCTIONS(TIDEWATER_VK_SYSTEM)
#undef TIDEWATER_VK_SYSTEM
        return f;
    }();
    return table;
}

Result<std::shared_ptr<const VulkanFunctions>> load_functions(const DeviceContext& ctx) {
    if (!ctx.get_instance_proc_addr && !ctx.get_device_proc_addr)
        return std::shared_ptr<const VulkanFunctions>(std::shared_ptr<const VulkanFunctions>{}, &system_functions());
    if (!ctx.get_instance_proc_addr || !ctx.get_device_proc_addr)
        return Error{ErrorCode::invalid_argument,
                     "DeviceContext: give both get_instance_proc_addr and get_device_proc_addr, or neither (the system loader)"};
    auto f = std::make_shared<VulkanFunctions>();
    std::string missing;
#define TIDEWATER_VK_LOAD_INSTANCE(name)                                                                     \
    f->name = reinterpret_cast<PFN_vk##name>(ctx.get_instance_proc_addr(ctx.instance, "vk" #name));        \
    if (!f->name) missing += std::string(missing.empty() ? "" : ", ") + "vk" #name;
#define TIDEWATER_VK_LOAD_DEVICE(name)                                                                       \
    f->name = reinterpret_cast<PFN_vk##name>(ctx.get_device_proc_addr(ctx.device, "vk" #name));            \
    if (!f->name) missing += std::string(missing.empty() ? "" : ", ") + "vk" #name;
    TIDEWATER_VK_INSTANCE_FUNCTIONS(TIDEWATER_VK_LOAD_INSTANCE)
    TIDEWATER_VK_DEVICE_FUNCTIONS(TIDEWATER_VK_LOAD_DEVICE)
#undef TIDEWATER_VK_LOAD_INSTANCE
#undef TIDEWATER_VK_LOAD_DEVICE
    if (!missing.empty())
        return Error{ErrorCode::unsupported, fmt::format("DeviceContext: the host's loader has no {}", missing)};
    return std::shared_ptr<const VulkanFunctions>(std::move(f));
}

const VulkanFunctions& dispatch() { return t_current ? *t_current : system_functions(); }

ScopedDispatch::ScopedDispatch(const VulkanFunctions* functions) : previous_(t_current) {
    if (functions) t_current = functions;
}
ScopedDispatch::~ScopedDispatch() { t_current = previous_; }

}  // namespace tidewater::render::detail
