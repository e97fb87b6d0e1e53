// Tables the shaders read instead of evaluating a costly function per pixel (private):
// a square texture drawn by a full-screen fragment shader from push constants. The sky
// table (shaders/sky.glsl) is drawn each frame; the foam's noise table
// (shaders/foam_noise.frag) once, when the renderer is made.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "gpu_memory.hpp"
#include "host_device.h"
#include "tidewater/result.hpp"
#include "vk_handle.hpp"

namespace tidewater::render::detail {

class DrawnTable {
  public:
    /// A `side`-square half-float RGBA table drawn by `fragment` (an embedded shader, with
    /// sky.vert's full-screen triangle) from `push_bytes` of fragment push constants. Submits
    /// and waits once, to give the table its sampled layout.
    static Result<DrawnTable> create(const Device& ctx, VkCommandPool pool, std::uint32_t side,
                                     std::string_view fragment, std::uint32_t push_bytes);

    /// Records the table's redraw from `push`, outside any pass: it waits for the fragment
    /// reads of the frames recorded before on the same queue, and the fragment stages
    /// after it read the new table.
    void record(const VulkanFunctions& vk, VkCommandBuffer cmd, std::span<const std::byte> push) const;
    VkImageView view() const { return table_.view(); }

  private:
    GpuImage table_;
    OwnedPipelineLayout layout_;
    OwnedPipeline pipeline_;
};

/// The sky toward `sun_direction` (need not be unit) for the air's `turbidity`, as the
/// shaders take it (frame constants and the sky table's push constants).
gpu::GpuSky gpu_sky(glm::dvec3 sun_direction, double turbidity);

/// The sky table: the daylight sky without the sun's disc, which the water's reflections
/// (four facets a pixel), the wet sand and the fog read at a texture fetch each.
class SkyTable {
  public:
    static Result<SkyTable> create(const Device& ctx, VkCommandPool pool);
    /// Records the redraw for `sky` (DrawnTable::record).
    void record(const VulkanFunctions& vk, VkCommandBuffer cmd, const gpu::GpuSky& sky);
    /// Whether the last redraw recorded was for `sky`.
    bool holds(const gpu::GpuSky& sky) const;
    VkImageView view() const { return table_.view(); }

  private:
    DrawnTable table_;
    std::optional<gpu::GpuSky> recorded_;
};

/// The foam's noise (shaders/foam_noise.frag): four channels of gradient noise that tile
/// every gpu::kFoamNoiseCells lattice cells, drawn once (submits and waits).
Result<DrawnTable> make_foam_noise_table(const Device& ctx, VkCommandPool pool);

}  // namespace tidewater::render::detail
