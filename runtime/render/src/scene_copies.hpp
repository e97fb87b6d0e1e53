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
    static Result<SceneCopies> create(const DeviceContext& ctx, VkCommandPool pool, const ColorTarget& color, const DepthTarget& depth);

    /// (Re)makes the copies at `extent`: waits for the device, then gives them a layout.
    Status resize(const DeviceContext& ctx, VkCommandPool pool, VkExtent2D extent);
    VkExtent2D extent() const { return extent_; }

    /// Records the copy of the host's targets into the copies. The targets go from
    /// attachment layouts to TRANSFER_SRC and back; the copies end SHADER_READ_ONLY.
    void record_copy(VkCommandBuffer cmd, const FrameTargets& targets) const;

    VkImageView color_view(bool copied) const { return (copied ? color_ : placeholder_color_).view(); }
    VkImageView depth_view(bool copied) const { return (copied ? depth_ : placeholder_depth_).view(); }

private:
    const ColorTarget* color_target_ = nullptr;
    const DepthTarget* depth_target_ = nullptr;
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
    /// image is in `depth_layout` (its format's attachment layout).
    FramePasses(const FrameTargets& targets, VkImageLayout depth_layout);
    FramePasses(const FramePasses&) = delete;  // `rendering` points into this object
    FramePasses& operator=(const FramePasses&) = delete;
    /// The water pass after the copy: loads what the opaque pass drew.
    void load_for_water();
};

}  // namespace tidewater::render::detail
