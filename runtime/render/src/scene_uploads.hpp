// A scene's data on the GPU (private), shared by the renderer and the GPU queries:
// the shore fields (shore_buffers.hpp), and the terrain's patch and height texture.
// Uploads submit and wait: they are the explicit, blocking calls.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "frame_constants.hpp"
#include "gpu_memory.hpp"
#include "shore_buffers.hpp"
#include "terrain_lod.hpp"
#include "terrain_mesh.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/render/device_context.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {

/// Uploads `bytes` of pixels into `image`'s `aspect` and leaves it SHADER_READ_ONLY_OPTIMAL;
/// the layout transitions cover `barrier_aspects` (0: `aspect`; a depth-stencil image: both).
/// `region`: the texels written, into an image already SHADER_READ_ONLY_OPTIMAL whose
/// other texels are kept; none: the whole image, its old contents discarded.
Status upload_image(const Device& ctx, VkCommandPool pool, GpuImage& image, const void* data, VkDeviceSize bytes,
                    VkImageAspectFlags aspect, VkImageAspectFlags barrier_aspects = 0,
                    std::optional<VkRect2D> region = std::nullopt);

/// The terrain on the GPU: its mesh and the height texture the water reads for depth.
/// The terrain on the device: the patch its level-of-detail nodes draw (terrain_lod.hpp)
/// and its height texture, at most `max_bytes` (a heightmap beyond it is drawn coarser).
struct TerrainUpload {
    GpuBuffer vertices, indices;  ///< the patch (terrain_mesh.hpp)
    std::uint32_t index_count = 0, quadrant_index_count = 0;
    GpuImage heights;  ///< R16 unorm over [lowest, highest]
    TerrainPlacement placement;
    TerrainLodGrid lod;                ///< what the node selection needs
    double water_half_size = 3000.0;   ///< m, half the side of the water grid.
    std::uint64_t resident_bytes = 0;  ///< the texture and the patch
    TerrainHeights sampling;           ///< how the texture was sampled (its texels dropped)
    std::uint64_t written_bytes = 0;   ///< of the texture, by the last create or update

    static Result<TerrainUpload> create(const Device& ctx, VkCommandPool pool, const Terrain& terrain,
                                        std::uint64_t max_bytes);
    /// Writes the texels that `after` changes from `before` (the terrain the texture was
    /// sampled from) into the texture, when height_texture_patch allows; false, with
    /// nothing written, when it does not. No GPU work may be reading the texture.
    Result<bool> update(const Device& ctx, VkCommandPool pool, const Terrain& before, const Terrain& after);
};

}  // namespace tidewater::render::detail
