#include "vulkan_faults.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace tidewater::test {

namespace {
// The loader unloads the driver and the validation layer with the instance. LeakSanitizer
// reads the stacks of what is left at exit, and an unloaded library's frames have no name
// for the suppressions below to match: loaded here first, they stay (RTLD_NODELETE).
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

// A function that fails as the plan says, or else calls the driver's. Its Tag names it,
// says what kind of call it is and, where the spec shapes a failure, what a failed call
// leaves (`failed`: outputs set to null, a wait that still lets the work finish).
template <typename Tag, typename Pfn>
struct Faulty;
template <typename Tag, typename... Args>
struct Faulty<Tag, VkResult(VKAPI_PTR*)(Args...)> {
    static inline VkResult(VKAPI_PTR* real)(Args...) = nullptr;
    static VKAPI_ATTR VkResult VKAPI_CALL call(Args... args) {
        const VkResult fault = vulkan_faults().on_call(Tag::name, Tag::kind);
        if (fault == VK_SUCCESS) return real(args...);
        if constexpr (requires { Tag::failed(args...); }) Tag::failed(args...);
        return fault;
    }
};

#define TW_FAULTY_TAG(fn, call_kind)                          \
    struct Tag##fn {                                          \
        static constexpr const char* name = "vk" #fn;         \
        static constexpr CallKind kind = CallKind::call_kind; \
    };
#define TW_PLAIN_FUNCTIONS(X)           \
    X(AllocateMemory, other)            \
    X(BeginCommandBuffer, other)        \
    X(BindBufferMemory, other)          \
    X(BindImageMemory, other)           \
    X(CreateBuffer, other)              \
    X(CreateCommandPool, other)         \
    X(CreateDescriptorPool, other)      \
    X(CreateDescriptorSetLayout, other) \
    X(CreateFence, other)               \
    X(CreateImage, other)               \
    X(CreateImageView, other)           \
    X(CreatePipelineLayout, other)      \
    X(CreateQueryPool, other)           \
    X(CreateSampler, other)             \
    X(CreateShaderModule, other)        \
    X(EndCommandBuffer, other)          \
    X(MapMemory, other)                 \
    X(ResetCommandPool, other)          \
    X(QueueSubmit, submit)              \
    X(GetQueryPoolResults, read)
TW_PLAIN_FUNCTIONS(TW_FAULTY_TAG)
#undef TW_FAULTY_TAG

// Failed allocations and pipeline creations leave their outputs null.
struct TagAllocateCommandBuffers {
    static constexpr const char* name = "vkAllocateCommandBuffers";
    static constexpr CallKind kind = CallKind::other;
    static void failed(VkDevice, const VkCommandBufferAllocateInfo* info, VkCommandBuffer* out) {
        std::fill_n(out, info->commandBufferCount, VK_NULL_HANDLE);
    }
};
struct TagAllocateDescriptorSets {
    static constexpr const char* name = "vkAllocateDescriptorSets";
    static constexpr CallKind kind = CallKind::other;
    static void failed(VkDevice, const VkDescriptorSetAllocateInfo* info, VkDescriptorSet* out) {
        std::fill_n(out, info->descriptorSetCount, VK_NULL_HANDLE);
    }
};
template <typename Info>
void no_pipelines(VkDevice, VkPipelineCache, std::uint32_t count, const Info*, const VkAllocationCallbacks*,
                  VkPipeline* out) {
    std::fill_n(out, count, VK_NULL_HANDLE);
}
struct TagCreateGraphicsPipelines {
    static constexpr const char* name = "vkCreateGraphicsPipelines";
    static constexpr CallKind kind = CallKind::other;
    static constexpr auto failed = &no_pipelines<VkGraphicsPipelineCreateInfo>;
};
struct TagCreateComputePipelines {
    static constexpr const char* name = "vkCreateComputePipelines";
    static constexpr CallKind kind = CallKind::other;
    static constexpr auto failed = &no_pipelines<VkComputePipelineCreateInfo>;
};
// A failed wait still lets the work it waited for finish, as the driver's own failure
// would leave it running: the fault tests what the caller does with the error.
struct TagDeviceWaitIdle {
    static constexpr const char* name = "vkDeviceWaitIdle";
    static constexpr CallKind kind = CallKind::wait;
    static void failed(VkDevice device);
};
struct TagWaitForFences {
    static constexpr const char* name = "vkWaitForFences";
    static constexpr CallKind kind = CallKind::wait;
    static void failed(VkDevice device, std::uint32_t, const VkFence*, VkBool32, std::uint64_t) {
        TagDeviceWaitIdle::failed(device);
    }
};
void TagDeviceWaitIdle::failed(VkDevice device) {
    static_cast<void>(Faulty<TagDeviceWaitIdle, PFN_vkDeviceWaitIdle>::real(device));
}

struct Wrapped {
    const char* name;
    PFN_vkVoidFunction wrapper;
    void (*keep_real)(PFN_vkVoidFunction);
};

template <typename Tag, typename Pfn>
Wrapped wrap() {
    using F = Faulty<Tag, Pfn>;
    return {Tag::name, reinterpret_cast<PFN_vkVoidFunction>(&F::call),
            [](PFN_vkVoidFunction real) { F::real = reinterpret_cast<Pfn>(real); }};
}

// The functions whose Tag says what a failure leaves (above).
#define TW_SHAPED_FUNCTIONS(X) \
    X(AllocateCommandBuffers)  \
    X(AllocateDescriptorSets)  \
    X(CreateGraphicsPipelines) \
    X(CreateComputePipelines)  \
    X(DeviceWaitIdle)          \
    X(WaitForFences)

const std::vector<Wrapped>& wrapped() {
#define TW_WRAP(fn, ...) wrap<Tag##fn, PFN_vk##fn>(),
    static const std::vector<Wrapped> table = {TW_PLAIN_FUNCTIONS(TW_WRAP) TW_SHAPED_FUNCTIONS(TW_WRAP)};
#undef TW_WRAP
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

// LeakSanitizer's suppressions for these tests (ASan builds): what lavapipe, the LLVM it
// compiles shaders with, the validation layer and the loader keep until exit. Each names
// a library, not a function, so a leak allocated by Tidewater's code is still reported.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libvulkan_lvp.so\n"
           "leak:libLLVM-15.so\n"
           "leak:libVkLayer_khronos_validation.so\n"
           "leak:libvulkan.so\n";
}
