// Owning wrappers for device-level Vulkan handles (private): each destroys its
// handle with the device and allocator it was made with, so no class keeps a
// hand-written destroy list. Move-only.
#pragma once

#include <utility>
#include <vulkan/vulkan.h>

#include "vk_dispatch.hpp"

namespace tidewater::render::detail {

/// `Destroy` names the table's destroy function (VulkanFunctions::DestroyPipeline, ...),
/// looked up when the handle is destroyed.
template <typename Handle, auto Destroy>
class VkOwned {
public:
    VkOwned() = default;
    VkOwned(VkDevice device, const VkAllocationCallbacks* allocator, Handle handle)
        : device_(device), allocator_(allocator), handle_(handle) {}
    VkOwned(VkOwned&& other) noexcept { *this = std::move(other); }
    VkOwned& operator=(VkOwned&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = std::exchange(other.device_, VK_NULL_HANDLE);
            allocator_ = std::exchange(other.allocator_, nullptr);
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    VkOwned(const VkOwned&) = delete;
    VkOwned& operator=(const VkOwned&) = delete;
    ~VkOwned() { reset(); }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) (dispatch().*Destroy)(device_, handle_, allocator_);
        handle_ = VK_NULL_HANDLE;
    }
    Handle get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator_ = nullptr;
    Handle handle_ = VK_NULL_HANDLE;
};

using OwnedPipeline = VkOwned<VkPipeline, &VulkanFunctions::DestroyPipeline>;
using OwnedPipelineLayout = VkOwned<VkPipelineLayout, &VulkanFunctions::DestroyPipelineLayout>;
using OwnedSetLayout = VkOwned<VkDescriptorSetLayout, &VulkanFunctions::DestroyDescriptorSetLayout>;
using OwnedDescriptorPool = VkOwned<VkDescriptorPool, &VulkanFunctions::DestroyDescriptorPool>;
using OwnedSampler = VkOwned<VkSampler, &VulkanFunctions::DestroySampler>;
using OwnedCommandPool = VkOwned<VkCommandPool, &VulkanFunctions::DestroyCommandPool>;
using OwnedQueryPool = VkOwned<VkQueryPool, &VulkanFunctions::DestroyQueryPool>;

/// Runs `create(&handle)` (a vkCreate* call) and wraps the handle on success.
template <typename Owned, typename Create>
VkResult make_owned(VkDevice device, const VkAllocationCallbacks* allocator, Owned& out, const Create& create) {
    decltype(out.get()) handle = VK_NULL_HANDLE;
    const VkResult r = create(&handle);
    if (r == VK_SUCCESS) out = Owned(device, allocator, handle);
    return r;
}

}  // namespace tidewater::render::detail
