#include "tidewater/render/offscreen.hpp"

#include <fmt/format.h>

#include <cstring>
#include <vector>

#include "gpu_memory.hpp"
#include "vk_util.hpp"

namespace tidewater::render {

using detail::GpuBuffer;
using detail::GpuImage;

// Every submission of this target is waited for before render() returns, so its
// members destroy their handles without a device-wide wait.
struct OffscreenTarget::Impl {
    detail::Device ctx;
    GpuImage color, depth;
    GpuImage resolved;  // multisampled targets: the picture, resolved by the water pass
    GpuBuffer readback;
    detail::OwnedCommandPool pool;
};

OffscreenTarget::OffscreenTarget(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OffscreenTarget::~OffscreenTarget() = default;

Result<std::unique_ptr<OffscreenTarget>> OffscreenTarget::create(const DeviceContext& context, std::uint32_t width,
                                                                 std::uint32_t height, VkSampleCountFlagBits samples) {
    if (width < 16 || height < 16 || width > 8192 || height > 8192) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("image size {}x{} is out of range (16x16 to 8192x8192)", width, height)};
    }
    auto device = detail::load_device(context);
    if (!device) return device.error();
    auto impl = std::make_unique<Impl>();
    impl->ctx = std::move(device).value();
    auto color = GpuImage::create(impl->ctx, {width, height}, kColorFormat,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT, samples);
    if (!color) return color.error();
    impl->color = std::move(color).value();
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        auto resolved = GpuImage::create(impl->ctx, {width, height}, kColorFormat,
                                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                         VK_IMAGE_ASPECT_COLOR_BIT);
        if (!resolved) return resolved.error();
        impl->resolved = std::move(resolved).value();
    }
    auto depth = GpuImage::create(impl->ctx, {width, height}, kDepthFormat,
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  VK_IMAGE_ASPECT_DEPTH_BIT, samples);
    if (!depth) return depth.error();
    impl->depth = std::move(depth).value();
    auto readback = GpuBuffer::create(impl->ctx, VkDeviceSize{width} * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (!readback) return readback.error();
    impl->readback = std::move(readback).value();
    VkCommandPoolCreateInfo cp{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cp.queueFamilyIndex = impl->ctx.queue_family;
    cp.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    const detail::Device& ctx = impl->ctx;
    TW_VK_TRY(detail::make_owned(ctx, impl->pool, [&](VkCommandPool* out) {
        return ctx.vk().CreateCommandPool(ctx.device, &cp, ctx.allocator, out);
    }));
    return std::unique_ptr<OffscreenTarget>(new OffscreenTarget(std::move(impl)));
}

Result<RgbaImage> OffscreenTarget::render(Renderer& renderer, const FrameInfo& frame) {
    ViewFrame whole{kMainView, frame, {}};
    whole.targets.extent = impl_->color.extent();
    return render_views(renderer, std::span<const ViewFrame>(&whole, 1));
}

Result<RgbaImage> OffscreenTarget::render_views(Renderer& renderer, std::span<const ViewFrame> views) {
    Impl& m = *impl_;
    const detail::VulkanFunctions& vk = m.ctx.vk();
    const VkExtent2D extent = m.color.extent();
    std::vector<ViewFrame> placed(views.begin(), views.end());
    for (ViewFrame& v : placed) {
        const VkOffset2D o = v.targets.offset;
        const VkExtent2D e = v.targets.extent;
        if (o.x < 0 || o.y < 0 || e.width == 0 || e.height == 0 ||
            static_cast<std::uint64_t>(o.x) + e.width > extent.width ||
            static_cast<std::uint64_t>(o.y) + e.height > extent.height)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("offscreen target: view {}'s rectangle {}x{} at ({}, {}) is not inside the "
                                     "{}x{} image",
                                     v.view.value, e.width, e.height, o.x, o.y, extent.width, extent.height)};
        // The renderer's own copies follow the view's size (a no-op when they already do).
        if (auto st = renderer.resize(e, v.view); !st) return st.error();
    }
    Status recorded;
    Status submitted = detail::submit_and_wait(m.ctx, m.pool.get(), [&](VkCommandBuffer cmd) {
        detail::transition(vk, cmd, m.color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                           VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        detail::transition(vk, cmd, m.depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                           VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                           VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
        const bool multisampled = m.resolved.handle() != VK_NULL_HANDLE;
        if (multisampled)
            detail::transition(vk, cmd, m.resolved.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        for (ViewFrame& v : placed) {
            FrameTargets& targets = v.targets;
            targets.color_image = m.color.handle();
            targets.color_view = m.color.view();
            targets.depth_image = m.depth.handle();
            targets.depth_view = m.depth.view();
            if (multisampled) {
                targets.resolve_image = m.resolved.handle();
                targets.resolve_view = m.resolved.view();
            }
        }
        recorded = renderer.record_views(cmd, placed);
        const VkImage picture = multisampled ? m.resolved.handle() : m.color.handle();
        detail::transition(vk, cmd, picture, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                           VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        vk.CmdCopyImageToBuffer(cmd, picture, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, m.readback.handle(), 1, &region);
        VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vk.CmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                              nullptr, 0, nullptr);
    });
    if (!recorded) return recorded.error();
    if (!submitted) return submitted.error();
    RgbaImage image;
    image.width = static_cast<int>(extent.width);
    image.height = static_cast<int>(extent.height);
    image.pixels.resize(static_cast<std::size_t>(extent.width) * extent.height * 4);
    std::memcpy(image.pixels.data(), m.readback.mapped(), image.pixels.size());
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;  // opaque PNGs
    return image;
}

}  // namespace tidewater::render
