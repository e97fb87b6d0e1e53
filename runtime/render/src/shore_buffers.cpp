#include "shore_buffers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "tidewater/detail/parallel.hpp"

namespace tidewater::render::detail {

std::size_t packed_slot_vec4s(const ShoreTiles& tiles, bool shared) {
    return ShoreTiles::kSlotTexels * (shared ? 1 : tiles.stride / 4);
}

// A shared slot's texels (depth, breaking, steepness scale, shore distance), or a run's
// waves one after the other, each wave's texels (phase residual, amplitude factor,
// wavevector x, z).
void pack_slot(const ShoreTiles& tiles, std::size_t slot, bool shared, glm::vec4* out) {
    if (tiles.in_memory(slot)) {
        pack_slot_floats(tiles.slot(slot), tiles.stride, shared, out);
        return;
    }
    // A saved bake's slot that nothing has read: read for the device, not kept in host
    // memory (a failure packs zeros and keeps its error: ShoreTiles::status).
    std::vector<float> floats(tiles.slot_floats());
    tiles.copy_slot(slot, floats.data());
    pack_slot_floats(floats.data(), tiles.stride, shared, out);
}

void pack_slot_floats(const float* texels, std::size_t stride, bool shared, glm::vec4* out) {
    if (shared) {
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* t = texels + k * stride;
            *out++ = {t[0], t[1], t[2], t[3]};
        }
        return;
    }
    const std::size_t nw = stride / 4;
    for (std::size_t w = 0; w < nw; ++w)
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* t = texels + k * stride;
            *out++ = {t[w], t[nw + w], t[2 * nw + w], t[3 * nw + w]};
        }
}

namespace {

/// A model's layers in the order of its records: the shared fields, then each run.
struct LayerView {
    const ShoreTiles* tiles;
    const ShoreGrid* grid;
    std::uint32_t first, count;  ///< its waves (0, 0: the shared fields)
};
std::vector<LayerView> layer_views(const ShoreWaves& m) {
    std::vector<LayerView> v{{&m.shared(), &m.grid(), 0u, 0u}};
    for (const ShoreWaveLayer& l : m.layers())
        v.push_back({&l.tiles, &l.grid, static_cast<std::uint32_t>(l.first), static_cast<std::uint32_t>(l.count)});
    return v;
}

/// Whether `b` packs to the same places as `a`: the same grids, pages and slot counts.
bool same_layout(const ShoreWaves& a, const ShoreWaves& b) {
    const std::vector<LayerView> x = layer_views(a), y = layer_views(b);
    if (x.size() != y.size()) return false;
    for (std::size_t l = 0; l < x.size(); ++l)
        if (!(*x[l].grid == *y[l].grid) || x[l].first != y[l].first || x[l].count != y[l].count ||
            x[l].tiles->stride != y[l].tiles->stride || x[l].tiles->slot_count() != y[l].tiles->slot_count() ||
            x[l].tiles->pages != y[l].tiles->pages)
            return false;
    return true;
}

}  // namespace

ShoreLayout layout_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                          const std::vector<const ShoreWaves*>& placed_as, const ShorePools* pools,
                          std::vector<StreamedLayer>* streamed) {
    ShoreLayout p;
    placements.assign(models.size(), ShorePlacement{});
    if (streamed) streamed->clear();
    struct Pooled {
        std::size_t record;  ///< in p.layers
        LayerView layer;     ///< the full-resolution one
        std::size_t slots;
        bool shared;
    };
    std::vector<Pooled> pooled;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves* shore = models[m];
        if (!shore) continue;
        const ShoreWaves* fine = pools && m < pools->fine.size() ? pools->fine[m] : nullptr;
        // The draws' shore positions are relative to the grid drawn first: the full-resolution
        // one when it streams, else the one packed.
        const ShoreWaves& frame = fine ? *fine : *shore;
        ShorePlacement& place = placements[m];
        place.model = m < placed_as.size() ? placed_as[m] : shore;
        place.layers = static_cast<std::uint32_t>(p.layers.size());
        place.texel = frame.texel();
        place.corner = frame.corner();
        place.resolution = frame.resolution();
        auto grid_of = [&](const ShoreGrid& g) {
            const glm::dvec2 offset = g.corner - frame.corner();
            return glm::vec4(static_cast<float>(offset.x), static_cast<float>(offset.y), static_cast<float>(g.texel),
                             static_cast<float>(g.resolution));
        };
        const std::vector<LayerView> coarse = layer_views(*shore);
        const std::vector<LayerView> full = fine ? layer_views(*fine) : std::vector<LayerView>{};
        for (std::size_t l = 0; l < coarse.size(); ++l) {
            const LayerView& v = coarse[l];
            const bool shared = l == 0;
            std::size_t& end = shared ? p.shared : p.per_wave;
            gpu::GpuShoreLayer record;
            record.grid = grid_of(*v.grid);
            record.waves = glm::uvec4(v.first, v.count, static_cast<std::uint32_t>(p.pages.size()),
                                      static_cast<std::uint32_t>(end));
            record.coarse_grid = record.grid;
            record.coarse = glm::uvec4(record.waves.z, record.waves.w, 0u, 0u);
            p.pages.insert(p.pages.end(), v.tiles->pages.begin(), v.tiles->pages.end());
            p.fills.push_back({v.tiles, shared, end, v.tiles->slot_count(), 0});
            end += v.tiles->slot_count() * packed_slot_vec4s(*v.tiles, shared);
            if (fine) {
                record.grid = grid_of(*full[l].grid);
                pooled.push_back({p.layers.size(), full[l], pools->pool_slots[m][l], shared});
            }
            p.layers.push_back(record);
        }
    }
    // The pools after every coarse level: each full-resolution grid's pages (its stored
    // tiles not resident yet), its open-sea and dry-land slots, and room for the streamed ones.
    for (const Pooled& pool : pooled) {
        gpu::GpuShoreLayer& record = p.layers[pool.record];
        std::size_t& end = pool.shared ? p.shared : p.per_wave;
        const ShoreTiles& tiles = *pool.layer.tiles;
        record.waves.z = static_cast<std::uint32_t>(p.pages.size());
        record.waves.w = static_cast<std::uint32_t>(end);
        for (std::uint32_t page : tiles.pages)
            p.pages.push_back(page < gpu::kShoreFirstStoredSlot ? page : gpu::kShoreNotResident);
        p.fills.push_back({&tiles, pool.shared, end, gpu::kShoreFirstStoredSlot, pool.slots});
        if (streamed) streamed->push_back({&tiles, *pool.layer.grid, pool.shared, record.waves.z, end, pool.slots});
        end += (gpu::kShoreFirstStoredSlot + pool.slots) * packed_slot_vec4s(tiles, pool.shared);
    }
    // One zero placeholder in each buffer that would be empty: bindings are always valid.
    p.per_wave = std::max<std::size_t>(p.per_wave, 1);
    p.shared = std::max<std::size_t>(p.shared, 1);
    if (p.pages.empty()) p.pages.push_back(0u);
    if (p.layers.empty()) p.layers.push_back(gpu::GpuShoreLayer{});
    return p;
}

void fill_shores(const ShoreLayout& layout, glm::vec4* per_wave, glm::vec4* shared) {
    // Slot by slot on every core: a large model packs hundreds of MiB.
    std::vector<std::pair<std::size_t, std::size_t>> jobs;  // (fill, slot)
    for (std::size_t f = 0; f < layout.fills.size(); ++f)
        for (std::size_t s = 0; s < layout.fills[f].packed + layout.fills[f].empty; ++s) jobs.emplace_back(f, s);
    tidewater::detail::parallel_chunks(jobs.size(), 16, 0, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j) {
            const ShoreLayout::Fill& fill = layout.fills[jobs[j].first];
            const std::size_t slot = jobs[j].second, per_slot = packed_slot_vec4s(*fill.tiles, fill.shared);
            glm::vec4* out = (fill.shared ? shared : per_wave) + fill.at + slot * per_slot;
            if (slot < fill.packed)
                pack_slot(*fill.tiles, slot, fill.shared, out);
            else
                std::fill(out, out + per_slot, glm::vec4(0.0f));
        }
    });
    // The placeholders of buffers no fill reaches.
    if (layout.fills.empty() ||
        std::none_of(layout.fills.begin(), layout.fills.end(), [](const ShoreLayout::Fill& f) { return !f.shared; }))
        per_wave[0] = glm::vec4(0.0f);
    if (layout.fills.empty()) shared[0] = glm::vec4(0.0f);
}

PackedShore pack_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                        const std::vector<const ShoreWaves*>& placed_as, const ShorePools* pools,
                        std::vector<StreamedLayer>* streamed) {
    const ShoreLayout layout = layout_shores(models, placements, placed_as, pools, streamed);
    PackedShore p;
    p.per_wave.resize(layout.per_wave);
    p.shared.resize(layout.shared);
    fill_shores(layout, p.per_wave.data(), p.shared.data());
    p.pages = layout.pages;
    p.layers = layout.layers;
    return p;
}

std::uint64_t packed_shore_bytes(const std::vector<const ShoreWaves*>& models, int stride) {
    std::uint64_t bytes = 0;
    for (const ShoreWaves* m : models)
        if (m) bytes += m->coarsened_device_bytes(stride);
    return bytes;
}

namespace {

/// Over `max_bytes`, the pools beside the models drawn from every `stride`-th texel: what
/// the coarse level leaves, shared between the layers in proportion to their stored bytes.
ShorePools plan_pools(const std::vector<const ShoreWaves*>& models, int stride, std::uint64_t max_bytes) {
    ShorePools pools;
    pools.fine = models;
    std::uint64_t fixed = packed_shore_bytes(models, stride), stored = 0;
    for (const ShoreWaves* m : models) {
        if (!m) continue;
        for (const LayerView& v : layer_views(*m)) {
            const std::uint64_t slot_bytes = v.tiles->slot_floats() * sizeof(float);
            fixed += v.tiles->pages.size() * sizeof(std::uint32_t) + gpu::kShoreFirstStoredSlot * slot_bytes;
            stored += v.tiles->stored_tiles() * slot_bytes;
        }
    }
    const double share = max_bytes > fixed && stored > 0
                             ? std::min(1.0, static_cast<double>(max_bytes - fixed) / static_cast<double>(stored))
                             : 0.0;
    for (const ShoreWaves* m : models) {
        pools.pool_slots.emplace_back();
        if (!m) continue;
        for (const LayerView& v : layer_views(*m))
            pools.pool_slots.back().push_back(
                static_cast<std::size_t>(share * static_cast<double>(v.tiles->stored_tiles())));
    }
    return pools;
}

}  // namespace

bool ShoreBuffers::holds(const Models& models) const {
    if (!per_wave_.handle() || models.size() != placements_.size()) return false;
    for (std::size_t m = 0; m < models.size(); ++m)
        if (wanted(models[m]) != placements_[m].model) return false;
    return true;
}

bool ShoreBuffers::rewrite_in_place(const Models& models, const std::vector<const ShoreWaves*>& drawn, int stride) {
    if (!per_wave_.handle() || stride != stride_ || models.size() != uploaded_.size()) return false;
    // What each placement drew: the model uploaded, or its coarsening over the budget.
    auto drawn_before = [&](std::size_t m) { return stride_ > 1 ? coarse_[m].get() : uploaded_[m].get(); };
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves *now = drawn[m], *then = drawn_before(m);
        if ((now == nullptr) != (then == nullptr) || (now && !same_layout(*then, *now))) return false;
        // The streamed tiles keep their pages too.
        if (now && stride_ > 1 && !same_layout(*uploaded_[m], *wanted(models[m]))) return false;
    }
    // The slots the new models do not share with the uploaded ones, written where they are.
    std::size_t written = 0;
    auto* shared_out = static_cast<glm::vec4*>(shared_.mapped());
    auto* per_wave_out = static_cast<glm::vec4*>(per_wave_.mapped());
    std::vector<const ShoreTiles*> streamed_tiles;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves *now = drawn[m], *then = drawn_before(m);
        if (!now) continue;
        const std::vector<LayerView> after = layer_views(*now), before = layer_views(*then);
        for (std::size_t l = 0; l < after.size(); ++l) {
            const bool shared = l == 0;
            const std::size_t per_slot = packed_slot_vec4s(*after[l].tiles, shared);
            glm::vec4* out = (shared ? shared_out : per_wave_out) + layer_records_[placements_[m].layers + l].coarse.y;
            for (std::size_t slot = 0; slot < after[l].tiles->slot_count(); ++slot) {
                if (after[l].tiles->same_slot(slot, *before[l].tiles)) continue;
                pack_slot(*after[l].tiles, slot, shared, out + slot * per_slot);
                written += per_slot * sizeof(glm::vec4);
            }
        }
        if (stride_ > 1)
            for (const LayerView& v : layer_views(*wanted(models[m]))) streamed_tiles.push_back(v.tiles);
        placements_[m].model = wanted(models[m]);
        uploaded_[m] = models[m];
    }
    if (stride_ > 1) written += stream_.refresh(streamed_tiles, shared_out, per_wave_out);
    rewritten_bytes_ = written;
    return true;
}

Result<bool> ShoreBuffers::upload(const Device& ctx, const Models& models, std::uint64_t max_bytes) {
    if (holds(models) && max_bytes == max_bytes_) {
        rewritten_bytes_ = 0;
        return false;
    }
    std::vector<const ShoreWaves*> wanted_models;
    for (const auto& m : models) wanted_models.push_back(wanted(m));
    // What the buffers may take together: the budget, and no more than one storage buffer
    // may span on this device (maxStorageBufferRange: 128 MiB on some), which bounds each.
    VkPhysicalDeviceProperties properties;
    ctx.vk().GetPhysicalDeviceProperties(ctx.physical_device, &properties);
    const std::uint64_t fit = std::min<std::uint64_t>(max_bytes, properties.limits.maxStorageBufferRange);
    // Over that, the coarse level is every k-th texel of each model (the smallest k whose
    // fields take at most half of it, at most 64), sized from the tiles' pages before
    // anything is coarsened; the rest streams full-resolution tiles. A model re-baked from
    // the one drawn is coarsened sharing the drawn coarsening's tiles away from its edit.
    int stride = 1;
    if (packed_shore_bytes(wanted_models, 1) > fit) {
        stride = 2;
        while (packed_shore_bytes(wanted_models, stride) > fit / 2 && stride < 64) ++stride;
    }
    // A saved bake's tiles are read on demand, and what the device takes is not kept in host
    // memory: within the budget every tile is read as it is packed; over it the coarse level
    // reads each tile once, and the full-resolution tiles stream from the bake folder
    // (ShoreStream). A tile that cannot be read fails the upload with its file's name,
    // before new buffers replace the drawn ones (an edit written in place writes the
    // slots it re-baked, which are in memory).
    auto unreadable = [&]() -> Status {
        for (const auto& m : models)
            if (m)
                if (auto st = m->status(); !st) return st.error();
        return {};
    };
    Models coarse;
    std::vector<const ShoreWaves*> drawn = wanted_models;
    if (stride > 1)
        for (std::size_t m = 0; m < drawn.size(); ++m) {
            const bool from_drawn =
                stride == stride_ && m < uploaded_.size() && m < coarse_.size() && uploaded_[m] && coarse_[m];
            coarse.push_back(wanted_models[m]
                                 ? wanted_models[m]->coarsened(stride, from_drawn ? uploaded_[m].get() : nullptr,
                                                               from_drawn ? coarse_[m].get() : nullptr)
                                 : nullptr);
            drawn[m] = coarse.back().get();
        }
    if (auto st = unreadable(); !st) return st.error();
    // A model edited in a few slots (ShoreWaves shares the rest): only those are written.
    if (max_bytes == max_bytes_ && rewrite_in_place(models, drawn, stride)) {
        coarse_ = std::move(coarse);
        if (auto st = unreadable(); !st) return st.error();
        return false;
    }
    std::vector<ShorePlacement> placements;
    std::vector<StreamedLayer> streamed;
    const ShorePools pools = stride > 1 ? plan_pools(wanted_models, stride, fit) : ShorePools{};
    const ShoreLayout layout =
        layout_shores(drawn, placements, wanted_models, stride > 1 ? &pools : nullptr, &streamed);
    // The offsets are 32-bit element indices in the shaders.
    if (std::max(layout.per_wave, layout.shared) > std::numeric_limits<std::uint32_t>::max())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: the shore models hold {} texels, more than 2^32",
                                 std::max(layout.per_wave, layout.shared))};
    // The fields are packed straight into the mapped buffers: no copy of them on the host.
    GpuBuffer fresh[4];
    const std::size_t sizes[4] = {layout.per_wave * sizeof(glm::vec4), layout.shared * sizeof(glm::vec4),
                                  layout.pages.size() * sizeof(std::uint32_t),
                                  layout.layers.size() * sizeof(gpu::GpuShoreLayer)};
    for (int i = 0; i < 4; ++i) {
        auto made = GpuBuffer::create(ctx, sizes[i], VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!made) return made.error();
        fresh[i] = std::move(made).value();
    }
    fill_shores(layout, static_cast<glm::vec4*>(fresh[0].mapped()), static_cast<glm::vec4*>(fresh[1].mapped()));
    if (auto st = unreadable(); !st) return st.error();
    std::memcpy(fresh[2].mapped(), layout.pages.data(), sizes[2]);
    std::memcpy(fresh[3].mapped(), layout.layers.data(), sizes[3]);
    per_wave_ = std::move(fresh[0]);
    shared_ = std::move(fresh[1]);
    pages_ = std::move(fresh[2]);
    layers_ = std::move(fresh[3]);
    placements_ = std::move(placements);
    stride_ = stride;
    max_bytes_ = max_bytes;
    coarse_ = std::move(coarse);
    layer_records_ = layout.layers;
    page_values_ = layout.pages;
    stream_.reset(std::move(streamed));
    rewritten_bytes_ = bytes();
    uploaded_.clear();
    for (std::size_t m = 0; m < models.size(); ++m) uploaded_.push_back(placements_[m].model ? models[m] : nullptr);
    return true;
}

std::uint64_t ShoreBuffers::stream(std::span<const glm::dvec2> cameras, std::uint64_t frame,
                                   std::uint32_t frames_in_flight, std::uint64_t max_bytes) {
    if (stride_ <= 1) return 0;
    return stream_.step(cameras, frame, frames_in_flight, max_bytes, page_values_,
                        static_cast<glm::vec4*>(shared_.mapped()), static_cast<glm::vec4*>(per_wave_.mapped()));
}

}  // namespace tidewater::render::detail
