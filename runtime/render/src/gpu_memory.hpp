// Buffers and images with their own memory (private). Tidewater allocates a
// handful of resources per renderer, so each gets a dedicated allocation.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

#include "tidewater/result.hpp"
#include "vk_device.hpp"

namespace tidewater::render::detail {

std::optional<std::uint32_t> find_memory_type(const Device& device, std::uint32_t type_bits,
                                              VkMemoryPropertyFlags wanted);

/// A host-visible, coherent, persistently mapped buffer. Move-only.
class GpuBuffer {
  public:
    GpuBuffer() = default;
    static Result<GpuBuffer> create(const Device& ctx, VkDeviceSize size, VkBufferUsageFlags usage);
    /// A storage buffer holding a copy of `bytes` at `data` (at least 16 bytes, so that an
    /// empty array still binds).
    static Result<GpuBuffer> storage_with(const Device& ctx, const void* data, std::size_t bytes);
    GpuBuffer(GpuBuffer&& other) noexcept { *this = std::move(other); }
    GpuBuffer& operator=(GpuBuffer&& other) noexcept;
    ~GpuBuffer() { reset(); }
    GpuBuffer(const GpuBuffer&) = delete;
    GpuBuffer& operator=(const GpuBuffer&) = delete;

    void reset();
    VkBuffer handle() const { return buffer_; }
    void* mapped() const { return mapped_; }
    VkDeviceSize size() const { return size_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator_ = nullptr;
    std::shared_ptr<const VulkanFunctions> functions_;  // those it was made with
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memory_bytes_ = 0;  // counted in functions_->device_memory_bytes
    void* mapped_ = nullptr;
    VkDeviceSize size_ = 0;
};

/// A device-local 2D image with one view. Move-only.
class GpuImage {
  public:
    GpuImage() = default;
    static Result<GpuImage> create(const Device& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                   VkImageAspectFlags aspect, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
    GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
    GpuImage& operator=(GpuImage&& other) noexcept;
    ~GpuImage() { reset(); }
    GpuImage(const GpuImage&) = delete;
    GpuImage& operator=(const GpuImage&) = delete;

    void reset();
    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator_ = nullptr;
    std::shared_ptr<const VulkanFunctions> functions_;  // those it was made with
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memory_bytes_ = 0;  // counted in functions_->device_memory_bytes
    VkImageView view_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
};

/// Records with `record` into a fresh command buffer from `pool`, submits to the
/// context's queue and waits for it to finish; every failure (a lost device included)
/// comes back as an Error carrying its VkResult.
template <typename Record>
Status submit_and_wait(const Device& ctx, VkCommandPool pool, const Record& record);

}  // namespace tidewater::render::detail

#include "gpu_memory_inl.hpp"
