// A Vulkan host written the way an engine would, for the embedding tests: its own device
// (as the examples make theirs) under the validation layer, its own 256 x 144 colour and
// depth images, command pool and readback, and the barriers and submissions around a frame.
#pragma once

#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../../examples/common/example_device.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"

namespace tidewater::test {

/// A Vulkan host written the way an engine would, independent of Tidewater's helpers: its
/// device as the examples make theirs (examples/common/example_device.hpp), under the
/// validation layer, with its own targets and command pool.
class TestHost : public examples::ExampleDevice {
  public:
    std::vector<std::string> messages;
    VkCommandPool pool = VK_NULL_HANDLE;
    struct Image {
        VkImage image = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
    } color, depth, resolved;  // resolved: multisampled hosts only
    VkBuffer readback = VK_NULL_HANDLE;
    VkDeviceMemory readback_memory = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM, depth_format = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    /// The image a frame ends in: the colour image, or its resolve.
    const Image& shown() const { return samples == VK_SAMPLE_COUNT_1_BIT ? color : resolved; }
    static constexpr std::uint32_t kWidth = 256, kHeight = 144;

    bool has_stencil() const { return depth_format == VK_FORMAT_D32_SFLOAT_S8_UINT; }
    VkImageAspectFlags depth_aspects() const {
        return has_stencil() ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT;
    }
    VkImageLayout depth_layout() const {
        return has_stencil() ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                             : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    }

    static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
        if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
            static_cast<TestHost*>(user)->messages.push_back(data->pMessage ? data->pMessage : "?");
        return VK_FALSE;
    }

    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) {
        VkPhysicalDeviceMemoryProperties p;
        vkGetPhysicalDeviceMemoryProperties(physical, &p);
        for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
        return 0;
    }

    Image make_image(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                     VkSampleCountFlagBits image_samples = VK_SAMPLE_COUNT_1_BIT) {
        Image img;
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {kWidth, kHeight, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = image_samples;
        info.usage = usage;
        EXPECT_EQ(vkCreateImage(device, &info, nullptr, &img.image), VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, img.image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        EXPECT_EQ(vkAllocateMemory(device, &alloc, nullptr, &img.memory), VK_SUCCESS);
        vkBindImageMemory(device, img.image, img.memory, 0);
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = img.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {aspect, 0, 1, 0, 1};
        EXPECT_EQ(vkCreateImageView(device, &view, nullptr, &img.view), VK_SUCCESS);
        return img;
    }

    /// The device and the images; `image_samples` > 1: multisampled colour and depth, and a
    /// single-sample `resolved` colour image the frame resolves into (read back instead).
    void create(VkFormat color_fmt = VK_FORMAT_R8G8B8A8_UNORM, VkFormat depth_fmt = VK_FORMAT_D32_SFLOAT,
                VkSampleCountFlagBits image_samples = VK_SAMPLE_COUNT_1_BIT) {
        color_format = color_fmt;
        depth_format = depth_fmt;
        samples = image_samples;
        examples::ExampleDeviceOptions options;
        options.application = "tidewater embedding test";
        options.on_message = &on_message;
        options.message_user = this;
        ASSERT_TRUE(ExampleDevice::create(options)) << error();
        VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pi.queueFamilyIndex = family;
        vkCreateCommandPool(device, &pi, nullptr, &pool);
        color = make_image(color_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           VK_IMAGE_ASPECT_COLOR_BIT, samples);
        depth = make_image(depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           depth_aspects(), samples);
        if (samples != VK_SAMPLE_COUNT_1_BIT)
            resolved = make_image(color_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT);
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = kWidth * kHeight * 8;  // up to 8-byte texels (R16G16B16A16_SFLOAT)
        bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        vkCreateBuffer(device, &bi, nullptr, &readback);
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, readback, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        vkAllocateMemory(device, &alloc, nullptr, &readback_memory);
        vkBindBufferMemory(device, readback, readback_memory, 0);
    }

    void destroy() {
        if (!device) return;
        vkDeviceWaitIdle(device);
        vkDestroyBuffer(device, readback, nullptr);
        vkFreeMemory(device, readback_memory, nullptr);
        for (Image* img : {&color, &depth, &resolved}) {
            if (!img->image) continue;
            vkDestroyImageView(device, img->view, nullptr);
            vkDestroyImage(device, img->image, nullptr);
            vkFreeMemory(device, img->memory, nullptr);
        }
        vkDestroyCommandPool(device, pool, nullptr);
        ExampleDevice::destroy();
    }
};

inline void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                    VkImageLayout to) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &b);
}

/// Begins `cmd` and moves the host's images to attachment layouts.
inline void begin_attachments(TestHost& host, VkCommandBuffer cmd) {
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &bi);
    barrier(cmd, host.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    barrier(cmd, host.depth.image, host.depth_aspects(), VK_IMAGE_LAYOUT_UNDEFINED, host.depth_layout());
    if (host.resolved.image)
        barrier(cmd, host.resolved.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

/// A fresh primary command buffer, begun, with the host's images moved to attachment layouts.
inline VkCommandBuffer begin_commands(TestHost& host) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = host.pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(host.device, &ai, &cmd) != VK_SUCCESS) return VK_NULL_HANDLE;
    begin_attachments(host, cmd);
    return cmd;
}

inline bool submit_and_wait(TestHost& host, VkCommandBuffer cmd) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    return vkQueueSubmit(host.queue, 1, &si, VK_NULL_HANDLE) == VK_SUCCESS && vkQueueWaitIdle(host.queue) == VK_SUCCESS;
}

/// The renderer for the host's images: their formats and samples, one frame in flight.
inline render::RendererInitInfo renderer_info(const TestHost& host) {
    render::RendererInitInfo init;
    init.device = host.context();
    init.color_format = host.color_format;
    init.depth_format = host.depth_format;
    init.samples = host.samples;
    init.frames_in_flight = 1;
    return init;
}

/// IEEE half to float (the float target's texels).
inline float half_to_float(std::uint16_t h) {
    const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
}

/// A linear value as an 8-bit sRGB code (what an sRGB target stores for it).
inline std::uint8_t srgb_code(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(e * 255.0f));
}

/// Ends `cmd` after copying the host's colour image out, submits, waits, frees it and
/// returns the picture as display RGBA8, whatever the target's format.
inline render::RgbaImage finish_and_read(TestHost& host, VkCommandBuffer cmd) {
    barrier(cmd, host.shown().image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {TestHost::kWidth, TestHost::kHeight, 1};
    vkCmdCopyImageToBuffer(cmd, host.shown().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.readback, 1, &region);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                         nullptr);
    vkEndCommandBuffer(cmd);
    EXPECT_TRUE(submit_and_wait(host, cmd));
    vkFreeCommandBuffers(host.device, host.pool, 1, &cmd);

    render::RgbaImage img;
    img.width = TestHost::kWidth;
    img.height = TestHost::kHeight;
    img.pixels.resize(TestHost::kWidth * TestHost::kHeight * 4);
    void* mapped = nullptr;
    vkMapMemory(host.device, host.readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped);
    const bool bgra = host.color_format == VK_FORMAT_B8G8R8A8_UNORM || host.color_format == VK_FORMAT_B8G8R8A8_SRGB;
    for (std::size_t k = 0; k < TestHost::kWidth * TestHost::kHeight; ++k) {
        std::uint8_t* out = &img.pixels[k * 4];
        if (host.color_format == VK_FORMAT_R16G16B16A16_SFLOAT) {
            const auto* h = static_cast<const std::uint16_t*>(mapped) + k * 4;
            for (int c = 0; c < 3; ++c) out[c] = srgb_code(half_to_float(h[c]));
            out[3] = 255;
        } else {
            const auto* p = static_cast<const std::uint8_t*>(mapped) + k * 4;
            out[0] = p[bgra ? 2 : 0], out[1] = p[1], out[2] = p[bgra ? 0 : 2], out[3] = p[3];
        }
    }
    vkUnmapMemory(host.device, host.readback_memory);
    return img;
}

}  // namespace tidewater::test
