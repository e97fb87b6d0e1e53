// The sky table (private; shaders/sky.glsl): the daylight sky without the sun's disc,
// drawn into a small texture whenever a frame's sky may have changed, so that the water's
// reflections (four facets a pixel), the wet sand and the fog read it at a texture fetch
// each instead of evaluating the Preetham sky.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec3.hpp>
#include <optional>

#include "gpu_memory.hpp"
#include "host_device.h"
#include "tidewater/result.hpp"
#include "vk_handle.hpp"

namespace tidewater::render::detail {

/// The sky toward `sun_direction` (need not be unit) for the air's `turbidity`, as the
/// shaders take it (frame constants and the table's push constants).
gpu::GpuSky gpu_sky(glm::dvec3 sun_direction, double turbidity);

class SkyTable {
  public:
    /// The table (gpu::kSkyTableSide texels a side), its pipeline and pipeline layout
    /// (push constants only). Submits and waits once, to give the table its sampled
    /// layout; it holds no sky until a refresh is recorded.
    static Result<SkyTable> create(const Device& ctx, VkCommandPool pool);

    /// Records the table's refresh for `sky`, outside any pass: it waits for the fragment
    /// reads of the frames recorded before on the same queue, and the fragment stages
    /// after it read the new table.
    void record(const VulkanFunctions& vk, VkCommandBuffer cmd, const gpu::GpuSky& sky);
    /// Whether the last refresh recorded was for `sky`.
    bool holds(const gpu::GpuSky& sky) const;
    VkImageView view() const { return table_.view(); }

  private:
    GpuImage table_;
    OwnedPipelineLayout layout_;
    OwnedPipeline pipeline_;
    std::optional<gpu::GpuSky> recorded_;
};

}  // namespace tidewater::render::detail
