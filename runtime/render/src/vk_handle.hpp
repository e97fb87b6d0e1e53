// Owning wrappers for device-level Vulkan handles (private). Each keeps the device,
// allocator and function table it was made with and destroys its handle through them,
// so no class keeps a hand-written destroy list and a handle can be destroyed on any
// thread. Move-only.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <utility>

#include "vk_device.hpp"

namespace tidewater::render::detail {

/// `Destroy` names the table's destroy function (&VulkanFunctions::DestroyPipeline, ...).
template <typename Handle, auto Destroy>
class VkOwned {
  public:
    VkOwned() = default;
    VkOwned(const Device& device, Handle handle)
        : device_(device.device), allocator_(device.allocator), functions_(device.functions), handle_(handle) {}
    VkOwned(VkOwned&& other) noexcept { *this = std::move(other); }
    VkOwned& operator=(VkOwned&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = std::exchange(other.device_, VK_NULL_HANDLE);
            allocator_ = std::exchange(other.allocator_, nullptr);
            functions_ = std::move(other.functions_);
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    VkOwned(const VkOwned&) = delete;
    VkOwned& operator=(const VkOwned&) = delete;
    ~VkOwned() { reset(); }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) ((*functions_).*Destroy)(device_, handle_, allocator_);
        handle_ = VK_NULL_HANDLE;
        functions_.reset();
    }
    Handle get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator_ = nullptr;
    std::shared_ptr<const VulkanFunctions> functions_;
    Handle handle_ = VK_NULL_HANDLE;
};

using OwnedPipeline = VkOwned<VkPipeline, &VulkanFunctions::DestroyPipeline>;
using OwnedPipelineLayout = VkOwned<VkPipelineLayout, &VulkanFunctions::DestroyPipelineLayout>;
using OwnedSetLayout = VkOwned<VkDescriptorSetLayout, &VulkanFunctions::DestroyDescriptorSetLayout>;
using OwnedDescriptorPool = VkOwned<VkDescriptorPool, &VulkanFunctions::DestroyDescriptorPool>;
using OwnedSampler = VkOwned<VkSampler, &VulkanFunctions::DestroySampler>;
using OwnedCommandPool = VkOwned<VkCommandPool, &VulkanFunctions::DestroyCommandPool>;
using OwnedQueryPool = VkOwned<VkQueryPool, &VulkanFunctions::DestroyQueryPool>;
using OwnedShaderModule = VkOwned<VkShaderModule, &VulkanFunctions::DestroyShaderModule>;
using OwnedFence = VkOwned<VkFence, &VulkanFunctions::DestroyFence>;

/// Runs `create(&handle)` (a vkCreate* call through `device`'s table) and wraps the
/// handle on success.
template <typename Owned, typename Create>
[[nodiscard]] VkResult make_owned(const Device& device, Owned& out, const Create& create) {
    decltype(out.get()) handle = VK_NULL_HANDLE;
    const VkResult r = create(&handle);
    if (r == VK_SUCCESS) out = Owned(device, handle);
    return r;
}

}  // namespace tidewater::render::detail
