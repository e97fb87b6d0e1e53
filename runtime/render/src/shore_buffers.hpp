// The shore models' fields on the GPU (private), shared by the renderer and the GPU
// queries: packed as shaders/shore_fields.glsl reads them and kept up to date after an
// edit. Over the memory budget each model is drawn from a coarse level (every k-th
// texel, always resident) with its full-resolution tiles nearest the camera streamed
// over it (shore_stream.hpp).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "gpu_memory.hpp"
#include "host_device.h"
#include "shore_stream.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/render/device_context.hpp"

namespace tidewater::render::detail {

/// The shore fields packed for the shaders (shore_fields.glsl), model after model: each
/// model's shared layer slot after slot (one vec4 per slot and texel: depth, breaking,
/// steepness scale, shore distance), its runs of waves (one vec4 per slot, wave and texel:
/// phase residual, amplitude factor, wavevector x, z), its records (GpuShoreLayer: the
/// shared layer's, then each run's), and the pages of each layer's grid (a slot per
/// tile); one zero placeholder each without any.
struct PackedShore {
    std::vector<glm::vec4> per_wave{glm::vec4(0.0f)};
    std::vector<glm::vec4> shared{glm::vec4(0.0f)};
    std::vector<std::uint32_t> pages{0u};
    std::vector<gpu::GpuShoreLayer> layers{gpu::GpuShoreLayer{}};
};

/// Where one model's fields start in the packed buffers (elements), and the grid its
/// shared layer is drawn on (its own). model null: none.
struct ShorePlacement {
    const ShoreWaves* model = nullptr;
    std::uint32_t layers = 0, shared = 0, pages = 0;  ///< its first record, shared vec4, shared page
    glm::dvec2 corner{0.0};                           ///< world xz of its shared grid's outer corner, m
    double texel = 1.0;                               ///< m
    int resolution = 0;                               ///< texels per side
};

/// Vec4s one slot of `tiles` packs to: one per texel of the shared layer, one per wave
/// and texel of a run.
std::size_t packed_slot_vec4s(const ShoreTiles& tiles, bool shared);
/// Slot `slot` of `tiles` as the shaders read it, into `out` (packed_slot_vec4s of them).
void pack_slot(const ShoreTiles& tiles, std::size_t slot, bool shared, glm::vec4* out);
/// The same from a slot's floats `texels` (`stride` a texel), wherever they were read.
void pack_slot_floats(const float* texels, std::size_t stride, bool shared, glm::vec4* out);

/// Full-resolution pools to pack beside coarse models (ShoreBuffers over its budget): per
/// model, per layer (the shared one, then each run), the slots streamed tiles may take.
struct ShorePools {
    std::vector<const ShoreWaves*> fine;               ///< per model: the model at full resolution
    std::vector<std::vector<std::size_t>> pool_slots;  ///< per model and layer
};

/// Where pack_shores puts everything: the buffers' sizes (vec4s), the pages and records,
/// and the slots to pack.
struct ShoreLayout {
    std::size_t per_wave = 0, shared = 0;
    std::vector<std::uint32_t> pages;
    std::vector<gpu::GpuShoreLayer> layers;
    struct Fill {
        const ShoreTiles* tiles;
        bool shared;
        std::size_t at;      ///< its first vec4 in its buffer
        std::size_t packed;  ///< its first slots, packed from `tiles`
        std::size_t empty;   ///< the zeroed slots after them (a pool's room)
    };
    std::vector<Fill> fills;
};
/// pack_shores' layout, without packing anything.
ShoreLayout layout_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                          const std::vector<const ShoreWaves*>& placed_as = {}, const ShorePools* pools = nullptr,
                          std::vector<StreamedLayer>* streamed = nullptr);
/// Packs `layout`'s slots into `per_wave` and `shared` (layout.per_wave and layout.shared
/// vec4s), in parallel.
void fill_shores(const ShoreLayout& layout, glm::vec4* per_wave, glm::vec4* shared);

/// Packs `models` (null ones get no fields) one after the other, each on the grid it
/// has, and says where each starts; placements name `placed_as` (the models the caller
/// knows: a coarsened model is placed as its original). With `pools`, each model's records
/// read its full-resolution grids (placed_as) first: their pages name kShoreNotResident
/// for every stored tile and their slots are a pool (the open-sea and dry-land slots, then
/// the pool's), described in `streamed`; the packed model is their coarse grid.
PackedShore pack_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                        const std::vector<const ShoreWaves*>& placed_as = {}, const ShorePools* pools = nullptr,
                        std::vector<StreamedLayer>* streamed = nullptr);

/// Bytes `models` take on the GPU as pack_shores packs them, from every `stride`-th texel.
std::uint64_t packed_shore_bytes(const std::vector<const ShoreWaves*>& models, int stride);

/// The shore fields of a list of models on the GPU (the ocean's and each lake's for the
/// renderer, one for a GPU query), or placeholders, so that their bindings are always
/// valid. Keeps the models alive while they are the ones uploaded. Threading: one thread.
class ShoreBuffers {
  public:
    using Models = std::vector<std::shared_ptr<const ShoreWaves>>;
    /// True when `models` are what the buffers hold already (no upload needed).
    bool holds(const Models& models) const;
    /// Uploads `models` (null or all-deep ones: no fields) unless they are already there.
    /// Models laid out as the ones uploaded (the same grids, pages and slot counts: a
    /// re-bake after an edit) are written in place, only the slots they do not share with
    /// them (over the budget, the coarse slots made from those and the streamed tiles that
    /// changed). Returns true when the buffers were replaced and descriptors must be rewritten.
    /// The caller makes sure no GPU work still reads the old buffers.
    /// Over `max_bytes` each model is drawn from every k-th texel (the smallest k whose
    /// fields take at most half of it), and the rest of `max_bytes` is a pool for the
    /// full-resolution tiles stream() brings in: coarser, never out of memory. The buffers
    /// take no more than the most one storage buffer may span on the device
    /// (maxStorageBufferRange) together either, so that each can be bound.
    Result<bool> upload(const Device& ctx, const Models& models,
                        std::uint64_t max_bytes = std::numeric_limits<std::uint64_t>::max());
    Result<bool> upload(const Device& ctx, const std::shared_ptr<const ShoreWaves>& shore) {
        return upload(ctx, Models{shore});
    }
    /// Over the budget: brings the full-resolution tiles nearest `cameras` (world xz, m;
    /// each tile's distance is to the nearest of them, the views of one frame)
    /// into the pools, at most `max_bytes` (at least one tile), for frame `frame`; pool
    /// slots given up are rewritten only once the `frames_in_flight` frames that could read
    /// them are done. Pages change (pages_now()); the bytes written are returned.
    std::uint64_t stream(std::span<const glm::dvec2> cameras, std::uint64_t frame, std::uint32_t frames_in_flight,
                         std::uint64_t max_bytes);

    /// Bytes of the buffers (resident).
    std::uint64_t bytes() const { return per_wave_.size() + shared_.size() + pages_.size() + layers_.size(); }
    /// Texels skipped per texel kept on the coarse level (1: the models' own grids, nothing streamed).
    int stride() const { return stride_; }
    /// Bytes the last upload wrote: every buffer's, or the slots rewritten in place.
    std::uint64_t rewritten_bytes() const { return rewritten_bytes_; }
    /// Full-resolution tiles drawn over the coarse level now, and the tiles that could be.
    std::size_t streamed_tiles() const { return stream_.resident_tiles(); }
    std::size_t streamable_tiles() const { return stream_.streamable_tiles(); }
    std::size_t reading_tiles() const { return stream_.reading_tiles(); }
    /// The streamed layers: where their pages and pools lie (tests and checks).
    const ShoreStream& streaming() const { return stream_; }

    /// The first model uploaded (null: none).
    const ShoreWaves* model() const { return placements_.empty() ? nullptr : placements_.front().model; }
    /// Where models[i] of the last upload starts (model null: it has no fields).
    ShorePlacement placement(std::size_t i) const { return i < placements_.size() ? placements_[i] : ShorePlacement{}; }
    /// What the shaders read of the runs' and the shared fields (the mapped buffers).
    std::span<const glm::vec4> per_wave_values() const { return mapped_vec4s(per_wave_); }
    std::span<const glm::vec4> shared_values() const { return mapped_vec4s(shared_); }
    /// The pages as they are now, for a frame's own copy (they change as tiles stream);
    /// pages() holds them as uploaded, before any stream().
    std::span<const std::uint32_t> pages_now() const { return page_values_; }
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
    std::vector<gpu::GpuShoreLayer> layer_records_;  ///< as uploaded: where each layer's slots start
    std::vector<std::uint32_t> page_values_;         ///< the pages now
    Models uploaded_;                                ///< per placement, the model uploaded (kept alive) or null
    Models coarse_;                                  ///< the coarsened models drawn over budget
    ShoreStream stream_;                             ///< over budget: the full-resolution tiles near the camera
};

}  // namespace tidewater::render::detail
