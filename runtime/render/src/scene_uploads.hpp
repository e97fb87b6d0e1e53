// A scene's data on the GPU (private), shared by the renderer and the GPU queries:
// the shore fields (shaders/shore_fields.glsl), and the terrain's patch and height
// texture. Uploads submit and wait: they are the explicit, blocking calls.
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
#include "terrain_lod.hpp"
#include "terrain_mesh.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/render/device_context.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {

/// The shore fields packed for the shaders (shore_fields.glsl), model after model: each
/// model's shared layer slot after slot (one vec4 per slot and texel: depth, breaking,
/// steepness scale, shore distance), its runs of waves (one vec4 per slot, wave and texel:
/// phase residual, amplitude factor, wavevector x, z), a record per run (GpuShoreLayer),
/// and the pages of its shared grid and of each run's (a slot per tile); one zero
/// placeholder each without any.
struct PackedShore {
    std::vector<glm::vec4> per_wave{glm::vec4(0.0f)};
    std::vector<glm::vec4> shared{glm::vec4(0.0f)};
    std::vector<std::uint32_t> pages{0u};
    std::vector<gpu::GpuShoreLayer> layers{gpu::GpuShoreLayer{}};
};

/// Where one model's fields start in the packed buffers (elements) and the shared grid
/// they were packed on: the model's own, or every `stride`-th texel of it; model null: none.
struct ShorePlacement {
    const ShoreWaves* model = nullptr;
    std::uint32_t layers = 0, shared = 0, pages = 0;  ///< its first run record, shared vec4, shared page
    glm::dvec2 corner{0.0};                           ///< world xz of the packed shared grid's outer corner, m
    double texel = 1.0;                               ///< m
    int resolution = 0;                               ///< texels per side
};

/// Packs `models` (null ones get no fields) one after the other, each on the grid it
/// has, and says where each starts; placements name `placed_as` (the models the caller
/// knows: a coarsened model is placed as its original).
PackedShore pack_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                        const std::vector<const ShoreWaves*>& placed_as = {});

/// Bytes `models` take on the GPU as pack_shores packs them.
std::uint64_t packed_shore_bytes(const std::vector<const ShoreWaves*>& models, int stride);

/// The shore fields of a list of models on the GPU (the ocean's and each lake's for the
/// renderer, one for a GPU query), or placeholders, so that their bindings are always
/// valid. Keeps the models alive while they are the ones uploaded.
class ShoreBuffers {
  public:
    using Models = std::vector<std::shared_ptr<const ShoreWaves>>;
    /// True when `models` are what the buffers hold already (no upload needed).
    bool holds(const Models& models) const;
    /// Uploads `models` (null or all-deep ones: no fields) unless they are already there.
    /// Models laid out as the ones uploaded (the same grids, pages and slot counts: a
    /// re-bake after an edit) are written in place, only the slots they do not share with
    /// them (over the budget, the coarse slots made from those). Returns true when the buffers were replaced and
    /// descriptors must be rewritten.
    /// The caller makes sure no GPU work still reads the old buffers.
    /// Over `max_bytes` the fields are packed on every k-th texel (the smallest k that
    /// fits): coarser, never out of memory.
    Result<bool> upload(const Device& ctx, const Models& models,
                        std::uint64_t max_bytes = std::numeric_limits<std::uint64_t>::max());
    Result<bool> upload(const Device& ctx, const std::shared_ptr<const ShoreWaves>& shore) {
        return upload(ctx, Models{shore});
    }
    /// Bytes of the four buffers.
    std::uint64_t bytes() const { return per_wave_.size() + shared_.size() + pages_.size() + layers_.size(); }
    /// Texels skipped per texel kept (1: the models' own grids).
    int stride() const { return stride_; }
    /// Bytes the last upload wrote: every buffer's, or the slots rewritten in place.
    std::uint64_t rewritten_bytes() const { return rewritten_bytes_; }

    /// The first model uploaded (null: none).
    const ShoreWaves* model() const { return placements_.empty() ? nullptr : placements_.front().model; }
    /// Where models[i] of the last upload starts (model null: it has no fields).
    ShorePlacement placement(std::size_t i) const { return i < placements_.size() ? placements_[i] : ShorePlacement{}; }
    /// What the shaders read of the runs' and the shared fields (the mapped buffers).
    std::span<const glm::vec4> per_wave_values() const { return mapped_vec4s(per_wave_); }
    std::span<const glm::vec4> shared_values() const { return mapped_vec4s(shared_); }
    VkBuffer per_wave() const { return per_wave_.handle(); }
    VkBuffer shared() const { return shared_.handle(); }
    VkBuffer pages() const { return pages_.handle(); }
    VkBuffer layers() const { return layers_.handle(); }

  private:
    static std::span<const glm::vec4> mapped_vec4s(const GpuBuffer& b) {
        return {static_cast<const glm::vec4*>(b.mapped()), b.handle() ? b.size() / sizeof(glm::vec4) : 0};
    }
    static const ShoreWaves* wanted(const std::shared_ptr<const ShoreWaves>& shore) {
        return shore && !shore->trivial() ? shore.get() : nullptr;
    }

    /// Writes the slots of `drawn` (`models` as drawn at `stride`: themselves, or their
    /// coarsenings) that differ from the ones drawn now into the buffers, when they are
    /// laid out alike; false (nothing written) when not.
    bool rewrite_in_place(const Models& models, const std::vector<const ShoreWaves*>& drawn, int stride);

    GpuBuffer per_wave_, shared_, pages_, layers_;
    int stride_ = 1;
    std::uint64_t max_bytes_ = 0, rewritten_bytes_ = 0;
    std::vector<ShorePlacement> placements_;
    std::vector<gpu::GpuShoreLayer> layer_records_;  ///< as uploaded: where each run's slots start
    Models uploaded_;                                ///< per placement, the model uploaded (kept alive) or null
    Models coarse_;                                  ///< the coarsened models drawn over budget
};

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
