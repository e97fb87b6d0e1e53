#include "gpu_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <utility>

namespace tidewater::render::detail {

std::optional<std::uint32_t> find_memory_type(const Device& device, std::uint32_t type_bits,
                                              VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties props;
    device.vk().GetPhysicalDeviceMemoryProperties(device.physical_device, &props);
    for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
    return std::nullopt;
}

namespace {

Result<VkDeviceMemory> allocate(const Device& ctx, VkMemoryRequirements req, VkMemoryPropertyFlags wanted,
                                const char* what) {
    auto type = find_memory_type(ctx, req.memoryTypeBits, wanted);
    if (!type) type = find_memory_type(ctx, req.memoryTypeBits, 0);
    if (!type) return Error{ErrorCode::unsupported, fmt::format("Vulkan: no memory type fits the {}", what)};
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = *type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    TW_VK_TRY(ctx.vk().AllocateMemory(ctx.device, &info, ctx.allocator, &memory));
    ctx.vk().device_memory_bytes += req.size;
    return memory;
}

void free_memory(const VulkanFunctions& vk, VkDevice device, VkDeviceMemory memory, VkDeviceSize bytes,
                 const VkAllocationCallbacks* allocator) {
    vk.FreeMemory(device, memory, allocator);
    vk.device_memory_bytes -= bytes;
}

}  // namespace

Result<GpuBuffer> GpuBuffer::storage_with(const Device& ctx, const void* data, std::size_t bytes) {
    auto made = create(ctx, std::max<std::size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!made) return made.error();
    if (bytes > 0) std::memcpy(made->mapped(), data, bytes);
    return made;
}

Result<GpuBuffer> GpuBuffer::create(const Device& ctx, VkDeviceSize size, VkBufferUsageFlags usage) {
    GpuBuffer b;
    b.device_ = ctx.device;
    b.allocator_ = ctx.allocator;
    b.functions_ = ctx.functions;
    b.size_ = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    TW_VK_TRY(ctx.vk().CreateBuffer(ctx.device, &info, ctx.allocator, &b.buffer_));
    VkMemoryRequirements req;
    ctx.vk().GetBufferMemoryRequirements(ctx.device, b.buffer_, &req);
    auto memory =
        allocate(ctx, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "buffer");
    if (!memory) return memory.error();
    b.memory_ = *memory;
    b.memory_bytes_ = req.size;
    TW_VK_TRY(ctx.vk().BindBufferMemory(ctx.device, b.buffer_, b.memory_, 0));
    TW_VK_TRY(ctx.vk().MapMemory(ctx.device, b.memory_, 0, VK_WHOLE_SIZE, 0, &b.mapped_));
    return b;
}

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = other.allocator_;
        functions_ = std::move(other.functions_);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        memory_bytes_ = std::exchange(other.memory_bytes_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

void GpuBuffer::reset() {
    if (!device_) return;
    if (buffer_) functions_->DestroyBuffer(device_, buffer_, allocator_);
    if (memory_) free_memory(*functions_, device_, memory_, memory_bytes_, allocator_);  // unmaps implicitly
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
    device_ = VK_NULL_HANDLE;
    functions_.reset();
}

Result<GpuImage> GpuImage::create(const Device& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                  VkImageAspectFlags aspect, VkSampleCountFlagBits samples) {
    VkImageFormatProperties fp;
    if (ctx.vk().GetPhysicalDeviceImageFormatProperties(ctx.physical_device, format, VK_IMAGE_TYPE_2D,
                                                        VK_IMAGE_TILING_OPTIMAL, usage, 0, &fp) != VK_SUCCESS) {
        return Error{ErrorCode::unsupported,
                     fmt::format("Vulkan: image format {} with usage 0x{:x} is not supported by this device",
                                 static_cast<int>(format), usage)};
    }
    GpuImage img;
    img.device_ = ctx.device;
    img.allocator_ = ctx.allocator;
    img.functions_ = ctx.functions;
    img.format_ = format;
    img.extent_ = extent;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    TW_VK_TRY(ctx.vk().CreateImage(ctx.device, &info, ctx.allocator, &img.image_));
    VkMemoryRequirements req;
    ctx.vk().GetImageMemoryRequirements(ctx.device, img.image_, &req);
    auto memory = allocate(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "image");
    if (!memory) return memory.error();
    img.memory_ = *memory;
    img.memory_bytes_ = req.size;
    TW_VK_TRY(ctx.vk().BindImageMemory(ctx.device, img.image_, img.memory_, 0));
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = img.image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    TW_VK_TRY(ctx.vk().CreateImageView(ctx.device, &view, ctx.allocator, &img.view_));
    return img;
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = other.allocator_;
        functions_ = std::move(other.functions_);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        memory_bytes_ = std::exchange(other.memory_bytes_, 0);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        format_ = other.format_;
        extent_ = other.extent_;
    }
    return *this;
}

void GpuImage::reset() {
    if (!device_) return;
    if (view_) functions_->DestroyImageView(device_, view_, allocator_);
    if (image_) functions_->DestroyImage(device_, image_, allocator_);
    if (memory_) free_memory(*functions_, device_, memory_, memory_bytes_, allocator_);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    device_ = VK_NULL_HANDLE;
    functions_.reset();
}

}  // namespace tidewater::render::detail
