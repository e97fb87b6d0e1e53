// Frame recording's barriers (private): the opaque scene (the host's colour and
// depth after the terrain pass) copied for the water's refraction and reflection,
// and the rendering info of the two passes around it.
#pragma once

#include <vulkan/vulkan.h>

#include "gpu_memory.hpp"
#include "target_formats.hpp"
#include "tidewater/render/renderer.hpp"

namespace tidewater::render::detail {

class SceneCopies {
  public:
    /// 1x1 placeholders (bound by record_in_pass, which has no copy) and no copies yet.
    /// With multisampled targets (`samples` > 1) the colour copy is resolved (averaged)
    /// and the depth copy is written by the opaque pass's depth resolve (sample 0).
    static Result<SceneCopies> create(const Device& ctx, VkCommandPool pool, const ColorTarget& color,
                                      const DepthTarget& depth, VkSampleCountFlagBits samples);

    /// (Re)makes the copies at `extent`: waits for the device, then gives them a layout. A
    /// failed wait (a lost device) is returned before anything is replaced.
    Status resize(const Device& ctx, VkCommandPool pool, VkExtent2D extent);
    VkExtent2D extent() const { return extent_; }

    /// Records the copy of the host's targets into the copies. The targets go from
    /// attachment layouts to TRANSFER_SRC and back; the copies end SHADER_READ_ONLY.
    void record_copy(const VulkanFunctions& vk, VkCommandBuffer cmd, const FrameTargets& targets) const;
    /// Multisampled targets: the depth copy's layout around the opaque pass that resolves
    /// into it (before: waits for the last frame's reads; after: ready to sample).
    void depth_to_resolve(const VulkanFunctions& vk, VkCommandBuffer cmd) const;
    void depth_resolved(const VulkanFunctions& vk, VkCommandBuffer cmd) const;
    bool multisampled() const { return samples_ != VK_SAMPLE_COUNT_1_BIT; }
    VkImageView depth_resolve_view() const { return depth_.view(); }

    VkImageView color_view(bool copied) const { return (copied ? color_ : placeholder_color_).view(); }
    VkImageView depth_view(bool copied) const { return (copied ? depth_ : placeholder_depth_).view(); }

  private:
    const ColorTarget* color_target_ = nullptr;
    const DepthTarget* depth_target_ = nullptr;
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    GpuImage placeholder_color_, placeholder_depth_;
    GpuImage color_, depth_;
    VkExtent2D extent_{};
};

/// The colour and depth attachments of the host's targets and the rendering info over them.
struct FramePasses {
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};

    /// The opaque pass: clears (reversed-Z far is 0) when the targets ask for it; the depth
    /// image is in `depth_layout` (its format's attachment layout). Multisampled targets
    /// resolve their depth (sample 0) into `depth_resolve` at the end of it.
    FramePasses(const FrameTargets& targets, VkImageLayout depth_layout, VkImageView depth_resolve);
    FramePasses(const FramePasses&) = delete;  // `rendering` points into this object
    FramePasses& operator=(const FramePasses&) = delete;
    /// The water pass after the copy: loads what the opaque pass drew, and resolves the
    /// colour into the targets' resolve image when they give one.
    void load_for_water(const FrameTargets& targets);
};

}  // namespace tidewater::render::detail
