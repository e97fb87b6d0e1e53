// A scene's data on the GPU (private), shared by the renderer and the GPU queries:
// the shore fields (shaders/shore_fields.glsl), and the terrain's mesh and height
// texture. Uploads submit and wait: they are the explicit, blocking calls.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>
#include <vulkan/vulkan.h>

#include "frame_constants.hpp"
#include "gpu_memory.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/render/device_context.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {

/// The shore fields packed for the shaders: one vec4 per wave and texel (phase residual,
/// amplitude factor, wavevector x, z) and one per texel (depth, breaking, steepness
/// scale, shore distance); one zero placeholder each without a shore.
struct PackedShore {
    std::vector<glm::vec4> per_wave{glm::vec4(0.0f)};
    std::vector<glm::vec4> shared{glm::vec4(0.0f)};
};

PackedShore pack_shore(const ShoreWaves* shore);

/// The shore fields of one model on the GPU, or placeholders, so that their bindings are
/// always valid. Keeps the model alive while it is the one uploaded.
class ShoreBuffers {
public:
    /// True when `shore` is what the buffers hold already (no upload needed).
    bool holds(const std::shared_ptr<const ShoreWaves>& shore) const { return per_wave_.handle() && wanted(shore) == uploaded_; }
    /// Uploads `shore` (null or all-deep: placeholders) unless it is already there.
    /// Returns true when the buffers were replaced and descriptors must be rewritten.
    /// The caller makes sure no GPU work still reads the old buffers.
    Result<bool> upload(const DeviceContext& ctx, const std::shared_ptr<const ShoreWaves>& shore);

    const ShoreWaves* model() const { return uploaded_; }  ///< Null: placeholders.
    VkBuffer per_wave() const { return per_wave_.handle(); }
    VkBuffer shared() const { return shared_.handle(); }

private:
    static const ShoreWaves* wanted(const std::shared_ptr<const ShoreWaves>& shore) {
        return shore && !shore->trivial() ? shore.get() : nullptr;
    }

    GpuBuffer per_wave_, shared_;
    const ShoreWaves* uploaded_ = nullptr;
    std::shared_ptr<const ShoreWaves> alive_;
};

/// Uploads `bytes` of pixels into `image` and leaves it SHADER_READ_ONLY_OPTIMAL.
Status upload_image(const DeviceContext& ctx, VkCommandPool pool, GpuImage& image, const void* data, VkDeviceSize bytes,
                    VkImageAspectFlags aspect);

/// The terrain on the GPU: its mesh and the height texture the water reads for depth.
struct TerrainUpload {
    GpuBuffer vertices, indices;
    std::uint32_t index_count = 0;
    std::uint64_t vertex_count = 0;
    GpuImage heights;
    TerrainPlacement placement;
    double water_half_size = 3000.0;  ///< m, half the side of the water grid.

    static Result<TerrainUpload> create(const DeviceContext& ctx, VkCommandPool pool, const Terrain& terrain);
};

}  // namespace tidewater::render::detail
