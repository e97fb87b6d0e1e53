// Frame recording's barriers (private): the opaque scene (the host's colour and
// depth after the terrain pass) copied for the water's refraction and reflection,
// and the rendering info of the two passes around it.
#pragma once

#include <vulkan/vulkan.h>

#include "gpu_memory.hpp"
#include "target_formats.hpp"
#include "tidewater/render/renderer.hpp"

namespace tidewater::render::detail {

/// What a pass without a scene copy samples in its place (record_in_pass): black, and
/// reversed-Z's far plane, one texel each. One set for every view.
struct PlaceholderCopies {
    GpuImage color, depth;
    /// Uploads both (submits on `pool` and waits for it).
    static Result<PlaceholderCopies> create(const Device& ctx, VkCommandPool pool, const ColorTarget& color,
                                            const DepthTarget& depth);
};

/// One view's copies of the opaque scene, the size of its targets. Made without GPU work
/// or waits (a view added or resized never stalls the frames in flight): each frame's
/// copy writes every texel and gives them their layout anew, so a recorded frame the
/// host never submitted leaves nothing for the next one to assume. With multisampled targets (`samples` > 1)
/// the colour copy is resolved (averaged) and the depth copy is written by the opaque
/// pass's depth resolve (sample 0).
class SceneCopies {
  public:
    static Result<SceneCopies> create(const Device& ctx, const ColorTarget& color, const DepthTarget& depth,
                                      VkSampleCountFlagBits samples, VkExtent2D extent);
    VkExtent2D extent() const { return extent_; }

    /// Records the copy of the view's rectangle of the host's targets (targets.offset,
    /// targets.extent) into the copies. The targets go from attachment layouts to
    /// TRANSFER_SRC and back; the copies end SHADER_READ_ONLY.
    void record_copy(const VulkanFunctions& vk, VkCommandBuffer cmd, const FrameTargets& targets);
    /// The same of what the host drew before the frame (the depth of multisampled targets
    /// resolved by a pass that draws nothing), for the pass that lights it under the water.
    void record_host_copy(const VulkanFunctions& vk, VkCommandBuffer cmd, const FrameTargets& targets);
    /// Multisampled targets: the depth copy's layout around the opaque pass that resolves
    /// into it (before: waits for the last frame's reads; after: ready to sample).
    void depth_to_resolve(const VulkanFunctions& vk, VkCommandBuffer cmd);
    void depth_resolved(const VulkanFunctions& vk, VkCommandBuffer cmd) const;
    bool multisampled() const { return samples_ != VK_SAMPLE_COUNT_1_BIT; }
    VkImageView depth_resolve_view() const { return depth_.view(); }

    VkImageView color_view() const { return color_.view(); }
    VkImageView depth_view() const { return depth_.view(); }

  private:
    const ColorTarget* color_target_ = nullptr;
    const DepthTarget* depth_target_ = nullptr;
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
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
