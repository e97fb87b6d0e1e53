#include "vulkan_faults.hpp"

#include <dlfcn.h>

#include <cstring>
#include <vector>

namespace tidewater::test {

namespace {
// The loader unloads the driver and the validation layer with the instance. LeakSanitizer
// reads the stacks of what is left at exit, and an unloaded library's frames have no name
// for lsan_vulkan_driver.supp to match: loaded here first, they stay (RTLD_NODELETE).
// Absent ones (another driver) are skipped.
const bool g_vulkan_libraries_kept = [] {
    for (const char* name : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"})
        static_cast<void>(dlopen(name, RTLD_LAZY | RTLD_NODELETE));
    return true;
}();
}  // namespace

VulkanFaults& vulkan_faults() {
    static VulkanFaults plan;
    return plan;
}

void VulkanFaults::arm(FaultKind kind, int fail_at) {
    const std::lock_guard lock(mutex_);
    armed_ = true;
    kind_ = kind;
    fail_at_ = fail_at;
    calls_ = 0;
    tripped_ = false;
    lost_ = false;
    tripped_in_.clear();
    fault_ = VK_SUCCESS;
}

void VulkanFaults::disarm() {
    const std::lock_guard lock(mutex_);
    armed_ = false;
    lost_ = false;
}

int VulkanFaults::calls() const {
    const std::lock_guard lock(mutex_);
    return calls_;
}
bool VulkanFaults::tripped() const {
    const std::lock_guard lock(mutex_);
    return tripped_;
}
std::string VulkanFaults::tripped_in() const {
    const std::lock_guard lock(mutex_);
    return tripped_in_;
}
VkResult VulkanFaults::fault() const {
    const std::lock_guard lock(mutex_);
    return fault_;
}
bool VulkanFaults::device_is_lost() const {
    const std::lock_guard lock(mutex_);
    return lost_;
}

VkResult VulkanFaults::on_call(const char* name, CallKind kind) {
    const std::lock_guard lock(mutex_);
    if (!armed_) return VK_SUCCESS;
    if (kind_ == FaultKind::device_lost) {
        if (kind == CallKind::other) return VK_SUCCESS;  // a lost device still makes objects
        if (lost_) return VK_ERROR_DEVICE_LOST;
        if (++calls_ != fail_at_) return VK_SUCCESS;
        lost_ = true;
        fault_ = VK_ERROR_DEVICE_LOST;
    } else {
        if (++calls_ != fail_at_) return VK_SUCCESS;
        fault_ = fail_at_ % 2 == 1 ? VK_ERROR_OUT_OF_HOST_MEMORY : VK_ERROR_OUT_OF_DEVICE_MEMORY;
    }
    tripped_ = true;
    tripped_in_ = name;
    return fault_;
}

namespace {

using CallKind = VulkanFaults::CallKind;

// A function that fails as the plan says, or else calls the driver's.
template <typename Tag, typename Pfn>
struct Faulty;
template <typename Tag, typename... Args>
struct Faulty<Tag, VkResult(VKAPI_PTR*)(Args...)> {
    static inline VkResult(VKAPI_PTR* real)(Args...) = nullptr;
    static VKAPI_ATTR VkResult VKAPI_CALL call(Args... args) {
        const VkResult fault = vulkan_faults().on_call(Tag::name, CallKind::other);
        return fault != VK_SUCCESS ? fault : real(args...);
    }
};

#define TW_FAULTY_TAG(fn)                             \
    struct Tag##fn {                                  \
        static constexpr const char* name = "vk" #fn; \
    };
#define TW_GENERIC_FUNCTIONS(X)  \
    X(AllocateMemory)            \
    X(BeginCommandBuffer)        \
    X(BindBufferMemory)          \
    X(BindImageMemory)           \
    X(CreateBuffer)              \
    X(CreateCommandPool)         \
    X(CreateDescriptorPool)      \
    X(CreateDescriptorSetLayout) \
    X(CreateFence)               \
    X(CreateImage)               \
    X(CreateImageView)           \
    X(CreatePipelineLayout)      \
    X(CreateQueryPool)           \
    X(CreateSampler)             \
    X(CreateShaderModule)        \
    X(EndCommandBuffer)          \
    X(MapMemory)                 \
    X(ResetCommandPool)
TW_GENERIC_FUNCTIONS(TW_FAULTY_TAG)
#undef TW_FAULTY_TAG

// The functions whose failure the spec shapes: outputs set to null, a loss reported by
// submissions, waits and reads.
PFN_vkAllocateCommandBuffers real_allocate_command_buffers = nullptr;
PFN_vkAllocateDescriptorSets real_allocate_descriptor_sets = nullptr;
PFN_vkCreateGraphicsPipelines real_create_graphics_pipelines = nullptr;
PFN_vkCreateComputePipelines real_create_compute_pipelines = nullptr;
PFN_vkQueueSubmit real_queue_submit = nullptr;
PFN_vkWaitForFences real_wait_for_fences = nullptr;
PFN_vkDeviceWaitIdle real_device_wait_idle = nullptr;
PFN_vkGetQueryPoolResults real_get_query_pool_results = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL faulty_allocate_command_buffers(VkDevice device, const VkCommandBufferAllocateInfo* info,
                                                               VkCommandBuffer* out) {
    const VkResult fault = vulkan_faults().on_call("vkAllocateCommandBuffers", CallKind::other);
    if (fault == VK_SUCCESS) return real_allocate_command_buffers(device, info, out);
    for (std::uint32_t i = 0; i < info->commandBufferCount; ++i) out[i] = VK_NULL_HANDLE;
    return fault;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_allocate_descriptor_sets(VkDevice device, const VkDescriptorSetAllocateInfo* info,
                                                               VkDescriptorSet* out) {
    const VkResult fault = vulkan_faults().on_call("vkAllocateDescriptorSets", CallKind::other);
    if (fault == VK_SUCCESS) return real_allocate_descriptor_sets(device, info, out);
    for (std::uint32_t i = 0; i < info->descriptorSetCount; ++i) out[i] = VK_NULL_HANDLE;
    return fault;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_create_graphics_pipelines(VkDevice device, VkPipelineCache cache,
                                                                std::uint32_t count,
                                                                const VkGraphicsPipelineCreateInfo* infos,
                                                                const VkAllocationCallbacks* allocator,
                                                                VkPipeline* out) {
    const VkResult fault = vulkan_faults().on_call("vkCreateGraphicsPipelines", CallKind::other);
    if (fault == VK_SUCCESS) return real_create_graphics_pipelines(device, cache, count, infos, allocator, out);
    for (std::uint32_t i = 0; i < count; ++i) out[i] = VK_NULL_HANDLE;
    return fault;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_create_compute_pipelines(VkDevice device, VkPipelineCache cache,
                                                               std::uint32_t count,
                                                               const VkComputePipelineCreateInfo* infos,
                                                               const VkAllocationCallbacks* allocator,
                                                               VkPipeline* out) {
    const VkResult fault = vulkan_faults().on_call("vkCreateComputePipelines", CallKind::other);
    if (fault == VK_SUCCESS) return real_create_compute_pipelines(device, cache, count, infos, allocator, out);
    for (std::uint32_t i = 0; i < count; ++i) out[i] = VK_NULL_HANDLE;
    return fault;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_queue_submit(VkQueue queue, std::uint32_t count, const VkSubmitInfo* submits,
                                                   VkFence fence) {
    const VkResult fault = vulkan_faults().on_call("vkQueueSubmit", CallKind::submit);
    return fault != VK_SUCCESS ? fault : real_queue_submit(queue, count, submits, fence);  // failed: nothing submitted
}
// A failed wait still lets the work it waited for finish first, as the driver's own
// failure would leave it running: the fault tests what the caller does with the error.
VKAPI_ATTR VkResult VKAPI_CALL faulty_wait_for_fences(VkDevice device, std::uint32_t count, const VkFence* fences,
                                                      VkBool32 all, std::uint64_t timeout) {
    const VkResult fault = vulkan_faults().on_call("vkWaitForFences", CallKind::wait);
    if (fault == VK_SUCCESS) return real_wait_for_fences(device, count, fences, all, timeout);
    static_cast<void>(real_device_wait_idle(device));
    return fault;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_device_wait_idle(VkDevice device) {
    const VkResult fault = vulkan_faults().on_call("vkDeviceWaitIdle", CallKind::wait);
    const VkResult waited = real_device_wait_idle(device);
    return fault != VK_SUCCESS ? fault : waited;
}
VKAPI_ATTR VkResult VKAPI_CALL faulty_get_query_pool_results(VkDevice device, VkQueryPool pool, std::uint32_t first,
                                                             std::uint32_t count, std::size_t size, void* data,
                                                             VkDeviceSize stride, VkQueryResultFlags flags) {
    const VkResult fault = vulkan_faults().on_call("vkGetQueryPoolResults", CallKind::read);
    return fault != VK_SUCCESS ? fault
                               : real_get_query_pool_results(device, pool, first, count, size, data, stride, flags);
}

struct Wrapped {
    const char* name;
    PFN_vkVoidFunction wrapper;
    void (*keep_real)(PFN_vkVoidFunction);
};

template <typename Pfn>
void store(Pfn& slot, PFN_vkVoidFunction real) {
    slot = reinterpret_cast<Pfn>(real);
}

const std::vector<Wrapped>& wrapped() {
#define TW_WRAP_GENERIC(fn)                                                                     \
    Wrapped{"vk" #fn, reinterpret_cast<PFN_vkVoidFunction>(&Faulty<Tag##fn, PFN_vk##fn>::call), \
            [](PFN_vkVoidFunction real) { store(Faulty<Tag##fn, PFN_vk##fn>::real, real); }},
#define TW_WRAP(fn, wrapper, slot)                                                                                   \
    Wrapped {                                                                                                        \
        "vk" #fn, reinterpret_cast<PFN_vkVoidFunction>(&wrapper), [](PFN_vkVoidFunction real) { store(slot, real); } \
    }
    static const std::vector<Wrapped> table = {
        TW_GENERIC_FUNCTIONS(TW_WRAP_GENERIC)  //
        TW_WRAP(AllocateCommandBuffers, faulty_allocate_command_buffers, real_allocate_command_buffers),
        TW_WRAP(AllocateDescriptorSets, faulty_allocate_descriptor_sets, real_allocate_descriptor_sets),
        TW_WRAP(CreateGraphicsPipelines, faulty_create_graphics_pipelines, real_create_graphics_pipelines),
        TW_WRAP(CreateComputePipelines, faulty_create_compute_pipelines, real_create_compute_pipelines),
        TW_WRAP(QueueSubmit, faulty_queue_submit, real_queue_submit),
        TW_WRAP(WaitForFences, faulty_wait_for_fences, real_wait_for_fences),
        TW_WRAP(DeviceWaitIdle, faulty_device_wait_idle, real_device_wait_idle),
        TW_WRAP(GetQueryPoolResults, faulty_get_query_pool_results, real_get_query_pool_results),
    };
#undef TW_WRAP
#undef TW_WRAP_GENERIC
    return table;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faulty_device_proc(VkDevice device, const char* name) {
    const PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
    if (!real) return real;
    for (const Wrapped& w : wrapped())
        if (std::strcmp(w.name, name) == 0) {
            w.keep_real(real);
            return w.wrapper;
        }
    return real;
}
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faulty_instance_proc(VkInstance instance, const char* name) {
    return vkGetInstanceProcAddr(instance, name);
}

}  // namespace

render::DeviceContext VulkanFaults::hooked(render::DeviceContext ctx) {
    ctx.get_instance_proc_addr = &faulty_instance_proc;
    ctx.get_device_proc_addr = &faulty_device_proc;
    return ctx;
}

}  // namespace tidewater::test
