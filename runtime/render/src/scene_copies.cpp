#include "scene_copies.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "scene_uploads.hpp"
#include "vk_util.hpp"

namespace tidewater::render::detail {

namespace {
constexpr VkImageUsageFlags kCopyUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkPipelineStageFlags kColorStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags kDepthStage =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
}  // namespace

Result<PlaceholderCopies> PlaceholderCopies::create(const Device& ctx, VkCommandPool pool,
                                                    const ColorTarget& color_target, const DepthTarget& depth_target) {
    auto color = GpuImage::create(ctx, {1, 1}, color_target.format, kCopyUsage, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!color) return color.error();
    auto depth = GpuImage::create(ctx, {1, 1}, depth_target.format, kCopyUsage, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (!depth) return depth.error();
    // Black, and reversed-Z's far plane (0 in every depth format).
    const std::uint64_t zero = 0;
    if (auto st = upload_image(ctx, pool, *color, &zero, color_target.texel_bytes, VK_IMAGE_ASPECT_COLOR_BIT); !st)
        return st.error();
    if (auto st = upload_image(ctx, pool, *depth, &zero, depth_target.texel_bytes, VK_IMAGE_ASPECT_DEPTH_BIT,
                               depth_target.aspects);
        !st)
        return st.error();
    return PlaceholderCopies{std::move(color).value(), std::move(depth).value()};
}

Result<SceneCopies> SceneCopies::create(const Device& ctx, const ColorTarget& color_target,
                                        const DepthTarget& depth_target, VkSampleCountFlagBits samples,
                                        VkExtent2D extent) {
    if (extent.width == 0 || extent.height == 0 || extent.width > 16384 || extent.height > 16384)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: extent {}x{} is out of range (1 to 16384)", extent.width, extent.height)};
    SceneCopies c;
    c.samples_ = samples;
    c.color_target_ = &color_target;
    c.depth_target_ = &depth_target;
    auto color = GpuImage::create(ctx, extent, color_target.format, kCopyUsage, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!color) return color.error();
    // Multisampled targets resolve their depth into the copy as an attachment.
    const VkImageUsageFlags depth_usage =
        kCopyUsage | (c.multisampled() ? static_cast<VkImageUsageFlags>(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)
                                       : VkImageUsageFlags{0});
    auto depth = GpuImage::create(ctx, extent, depth_target.format, depth_usage, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (!depth) return depth.error();
    c.color_ = std::move(color).value();
    c.depth_ = std::move(depth).value();
    c.extent_ = extent;
    return c;
}

void SceneCopies::record_copy(const VulkanFunctions& vk, VkCommandBuffer cmd, const FrameTargets& t) {
    transition(vk, cmd, t.color_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const DepthTarget& d = *depth_target_;
    transition(vk, cmd, t.depth_image, d.aspects, d.attachment_layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               kDepthStage, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_TRANSFER_READ_BIT);
    // Only the depth aspect is copied (and sampled); barriers cover every aspect. With
    // multisampling the colour is resolved and the depth was resolved by the pass.
    const struct {
        VkImage source;
        const GpuImage& copy;
        VkImageAspectFlags aspect, barrier_aspects;
    } pairs[2] = {{t.color_image, color_, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_ASPECT_COLOR_BIT},
                  {t.depth_image, depth_, VK_IMAGE_ASPECT_DEPTH_BIT, d.aspects}};
    for (const auto& p : pairs) {
        if (multisampled() && &p.copy == &depth_) continue;
        // The previous frame's water pass sampled the copy: wait for it before overwriting.
        // Every texel is written again, so the old contents and layout go (from UNDEFINED:
        // no layout is assumed from a frame the host may not have submitted).
        transition(vk, cmd, p.copy.handle(), p.barrier_aspects, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                   VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        const VkOffset3D from{t.offset.x, t.offset.y, 0};
        if (multisampled()) {
            VkImageResolve region{};
            region.srcSubresource = {p.aspect, 0, 0, 1};
            region.srcOffset = from;
            region.dstSubresource = {p.aspect, 0, 0, 1};
            region.extent = {t.extent.width, t.extent.height, 1};
            vk.CmdResolveImage(cmd, p.source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, p.copy.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        } else {
            VkImageCopy region{};
            region.srcSubresource = {p.aspect, 0, 0, 1};
            region.srcOffset = from;
            region.dstSubresource = {p.aspect, 0, 0, 1};
            region.extent = {t.extent.width, t.extent.height, 1};
            vk.CmdCopyImage(cmd, p.source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, p.copy.handle(),
                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        }
        transition(vk, cmd, p.copy.handle(), p.barrier_aspects, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    }
    transition(vk, cmd, t.color_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
               kColorStage, VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    transition(vk, cmd, t.depth_image, d.aspects, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d.attachment_layout,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, kDepthStage,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

void SceneCopies::record_host_copy(const VulkanFunctions& vk, VkCommandBuffer cmd, const FrameTargets& t) {
    if (multisampled()) {
        depth_to_resolve(vk, cmd);
        FramePasses resolve(t, depth_target_->attachment_layout, depth_.view());
        resolve.color.loadOp = resolve.depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        vk.CmdBeginRendering(cmd, &resolve.rendering);
        vk.CmdEndRendering(cmd);
        depth_resolved(vk, cmd);
    }
    record_copy(vk, cmd, t);
}

void SceneCopies::depth_to_resolve(const VulkanFunctions& vk, VkCommandBuffer cmd) {
    const DepthTarget& d = *depth_target_;
    transition(vk, cmd, depth_.handle(), d.aspects, VK_IMAGE_LAYOUT_UNDEFINED, d.attachment_layout,
               VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT, kDepthStage | kColorStage,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

void SceneCopies::depth_resolved(const VulkanFunctions& vk, VkCommandBuffer cmd) const {
    const DepthTarget& d = *depth_target_;
    // Depth resolves run at the end of the pass, in the colour-output stage.
    transition(vk, cmd, depth_.handle(), d.aspects, d.attachment_layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               kDepthStage | kColorStage,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

FramePasses::FramePasses(const FrameTargets& t, VkImageLayout depth_layout, VkImageView depth_resolve) {
    color.imageView = t.color_view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = t.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth = color;
    depth.imageView = t.depth_view;
    depth.imageLayout = depth_layout;
    depth.clearValue.depthStencil = {0.0f, 0};  // reversed-Z: far
    if (depth_resolve) {
        depth.resolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;  // every Vulkan 1.2 device has it
        depth.resolveImageView = depth_resolve;
        depth.resolveImageLayout = depth_layout;
    }
    rendering.renderArea = {t.offset, t.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
}

void FramePasses::load_for_water(const FrameTargets& t) {
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.resolveMode = VK_RESOLVE_MODE_NONE;
    depth.resolveImageView = VK_NULL_HANDLE;
    if (t.resolve_view) {
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = t.resolve_view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
}

}  // namespace tidewater::render::detail
