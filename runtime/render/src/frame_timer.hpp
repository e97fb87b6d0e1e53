// GPU timestamps per frame (private): four marks per in-flight slot, read back
// as the time of each pass once the host knows the frame has finished; and, where the
// device enabled pipelineStatisticsQuery, the invocations of each stage in the opaque
// and the water pass, with the samples each wrote where it enabled occlusionQueryPrecise.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "tidewater/render/renderer.hpp"
#include "vk_handle.hpp"

namespace tidewater::render::detail {

class FrameTimer {
  public:
    enum Mark : std::uint32_t { start, opaque_done, copy_done, water_done, mark_count };

    /// A query pool for `slots` frames, or none when the queue family has no timestamps.
    static Result<FrameTimer> create(const Device& ctx, std::uint32_t slots);
    bool available() const { return static_cast<bool>(pool_); }

    /// Resets the slot's queries and writes the start mark.
    void begin(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot) const;
    void mark(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Mark mark,
              VkPipelineStageFlagBits stage) const;
    enum Pass : std::uint32_t { opaque_pass, water_pass, pass_count };
    /// Begins and ends counting `pass`'s invocations (outside the pass's rendering).
    void begin_pass(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Pass pass) const;
    void end_pass(const VulkanFunctions& vk, VkCommandBuffer cmd, std::uint32_t slot, Pass pass) const;
    /// The slot's pass times; fails while the GPU has not finished it.
    Result<PassTimings> read(const Device& ctx, std::uint32_t slot) const;

  private:
    OwnedQueryPool pool_;
    OwnedQueryPool invocations_;  ///< pass_count per slot; none without pipelineStatisticsQuery
    OwnedQueryPool samples_;      ///< pass_count per slot; none without occlusionQueryPrecise as well
    double period_ns_ = 1.0;
};

}  // namespace tidewater::render::detail
