#include "shore_stream.hpp"

#include <algorithm>
#include <limits>

#include "host_device.h"
#include "shore_buffers.hpp"

namespace tidewater::render::detail {

namespace {

constexpr std::uint32_t kFirstPoolPage = gpu::kShoreFirstStoredSlot;  // pool slot p is page p + this
constexpr std::size_t kMaxReads = 32;  // tiles asked of the bake folder and not packed, at most

/// Squared distance from the nearest of `cameras` to the centre of tile `t` of `layer`, m^2.
double tile_distance2(const StreamedLayer& layer, std::uint32_t t, std::span<const glm::dvec2> cameras) {
    const int per_side = layer.tiles->tiles_per_side;
    const double side = static_cast<double>(ShoreTiles::kTile) * layer.grid.texel;
    const glm::dvec2 centre =
        layer.grid.corner + side * glm::dvec2(static_cast<double>(static_cast<int>(t) % per_side) + 0.5,
                                              static_cast<double>(static_cast<int>(t) / per_side) + 0.5);
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec2 camera : cameras) {
        const glm::dvec2 d = centre - camera;
        nearest = std::min(nearest, d.x * d.x + d.y * d.y);
    }
    return nearest;
}

}  // namespace

ShoreStream::Source ShoreStream::source_of(const ShoreTiles& tiles, std::size_t slot) {
    const void* floats = tiles.slots[slot] ? static_cast<const void*>(tiles.slots[slot].get())
                                           : static_cast<const void*>(tiles.lazy.get());
    return {floats, slot};
}

void ShoreStream::reset(std::vector<StreamedLayer> layers) {
    reader_.forget();
    read_.clear();
    layers_ = std::move(layers);
    pools_.assign(layers_.size(), Pool{});
    for (std::size_t l = 0; l < layers_.size(); ++l) {
        const ShoreTiles& tiles = *layers_[l].tiles;
        Pool& pool = pools_[l];
        for (std::size_t t = 0; t < tiles.pages.size(); ++t)
            if (tiles.pages[t] >= gpu::kShoreFirstStoredSlot) pool.candidates.push_back(static_cast<std::uint32_t>(t));
        const std::size_t n = layers_[l].pool_slots;
        pool.tile.assign(n, -1);
        pool.source.assign(n, Source{});
        pool.reading.assign(tiles.pages.size(), 0);
        pool.unreadable.assign(tiles.pages.size(), 0);
        pool.free_from.assign(n, 0);
        pool.slot_of.assign(tiles.pages.size(), -1);
    }
}

std::uint64_t ShoreStream::pack(std::size_t l, std::size_t p, std::uint32_t t, const float* floats,
                                glm::vec4* shared_out, glm::vec4* per_wave_out) {
    const StreamedLayer& layer = layers_[l];
    const std::size_t per_slot = packed_slot_vec4s(*layer.tiles, layer.shared);
    glm::vec4* out = (layer.shared ? shared_out : per_wave_out) + layer.first_element + (kFirstPoolPage + p) * per_slot;
    pack_slot_floats(floats, layer.tiles->stride, layer.shared, out);
    pools_[l].source[p] = source_of(*layer.tiles, layer.tiles->pages[t]);
    return per_slot * sizeof(glm::vec4);
}

std::uint64_t ShoreStream::step(std::span<const glm::dvec2> cameras, std::uint64_t frame,
                                std::uint32_t frames_in_flight, std::uint64_t max_bytes, std::span<std::uint32_t> pages,
                                glm::vec4* shared_out, glm::vec4* per_wave_out) {
    std::uint64_t written = 0;
    for (ShoreSlotReader::Read& r : reader_.take()) read_.push_back(std::move(r));
    std::vector<double> dist2;
    std::vector<std::uint32_t> order;
    std::vector<char> wanted;
    for (std::size_t l = 0; l < layers_.size(); ++l) {
        const StreamedLayer& layer = layers_[l];
        Pool& pool = pools_[l];
        const std::size_t keep = std::min(layer.pool_slots, pool.candidates.size());
        if (keep == 0) continue;
        // The `keep` stored tiles nearest the cameras.
        dist2.resize(pool.slot_of.size());
        for (std::uint32_t t : pool.candidates) dist2[t] = tile_distance2(layer, t, cameras);
        order = pool.candidates;
        auto nearer = [&](std::uint32_t a, std::uint32_t b) {
            return dist2[a] < dist2[b] || (dist2[a] == dist2[b] && a < b);
        };
        std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep - 1), order.end(), nearer);
        order.resize(keep);
        wanted.assign(pool.slot_of.size(), 0);
        for (std::uint32_t t : order) wanted[t] = 1;
        // Tiles read from disk that are no longer wanted are dropped.
        std::erase_if(read_, [&](const ShoreSlotReader::Read& r) {
            const bool drop = r.layer == l && !wanted[r.tile];
            if (drop) pool.reading[r.tile] = 0;
            return drop;
        });
        std::vector<std::uint32_t> missing;
        for (std::uint32_t t : order)
            if (pool.slot_of[t] < 0) missing.push_back(t);
        if (missing.empty()) continue;
        std::sort(missing.begin(), missing.end(), nearer);
        // Room for the missing ones: the farthest resident tiles no longer wanted give their
        // slots up; frames still in flight may read them, so they are written later.
        std::size_t free = static_cast<std::size_t>(std::count(pool.tile.begin(), pool.tile.end(), -1));
        if (free < missing.size()) {
            std::vector<std::size_t> unwanted;
            for (std::size_t p = 0; p < pool.tile.size(); ++p)
                if (pool.tile[p] >= 0 && !wanted[static_cast<std::size_t>(pool.tile[p])]) unwanted.push_back(p);
            std::sort(unwanted.begin(), unwanted.end(), [&](std::size_t a, std::size_t b) {
                return nearer(static_cast<std::uint32_t>(pool.tile[b]), static_cast<std::uint32_t>(pool.tile[a]));
            });
            for (std::size_t i = 0; i < unwanted.size() && free < missing.size(); ++i, ++free) {
                const std::size_t p = unwanted[i];
                const auto t = static_cast<std::size_t>(pool.tile[p]);
                pages[layer.first_page + t] = gpu::kShoreNotResident;
                pool.slot_of[t] = -1;
                pool.tile[p] = -1;
                pool.source[p] = Source{};
                pool.free_from[p] = frame + frames_in_flight;
            }
        }
        // The missing tiles, nearest first, into slots no frame in flight reads: from host
        // memory, or once read from disk (asked for now, packed a later frame).
        std::size_t p = 0;
        for (std::uint32_t t : missing) {
            if (written > 0 && written >= max_bytes) return written;
            if (pool.unreadable[t]) continue;
            while (p < pool.tile.size() && (pool.tile[p] >= 0 || pool.free_from[p] > frame)) ++p;
            if (p == pool.tile.size()) break;
            const ShoreTiles& tiles = *layer.tiles;
            const std::size_t slot = tiles.pages[t];
            const float* floats = nullptr;
            auto read = std::find_if(read_.begin(), read_.end(),
                                     [&](const ShoreSlotReader::Read& r) { return r.layer == l && r.tile == t; });
            if (tiles.in_memory(slot)) {
                floats = tiles.slot(slot);
            } else if (read != read_.end()) {
                pool.reading[t] = 0;
                if (!read->ok) {
                    pool.unreadable[t] = 1;
                    read_.erase(read);
                    continue;
                }
                floats = read->floats.data();
            } else {
                // Read and waiting counts too: what is read beyond a frame's bytes stays bounded.
                if (!pool.reading[t] && reading_tiles() < kMaxReads) {
                    reader_.request(l, t, tiles.lazy, slot, tiles.slot_floats());
                    pool.reading[t] = 1;
                }
                continue;
            }
            written += pack(l, p, t, floats, shared_out, per_wave_out);
            if (read != read_.end()) read_.erase(read);
            pool.tile[p] = t;
            pool.slot_of[t] = static_cast<std::int64_t>(p);
            pages[layer.first_page + t] = kFirstPoolPage + static_cast<std::uint32_t>(p);
        }
    }
    return written;
}

std::uint64_t ShoreStream::refresh(const std::vector<const ShoreTiles*>& tiles, glm::vec4* shared_out,
                                   glm::vec4* per_wave_out) {
    std::uint64_t written = 0;
    // Reads asked of the model before are dropped: asked again of the new one.
    reader_.forget();
    read_.clear();
    for (std::size_t l = 0; l < layers_.size() && l < tiles.size(); ++l) {
        layers_[l].tiles = tiles[l];
        Pool& pool = pools_[l];
        std::fill(pool.reading.begin(), pool.reading.end(), 0);
        for (std::size_t p = 0; p < pool.tile.size(); ++p) {
            if (pool.tile[p] < 0) continue;
            const auto t = static_cast<std::uint32_t>(pool.tile[p]);
            const std::size_t slot = tiles[l]->pages[t];
            if (source_of(*tiles[l], slot) == pool.source[p]) continue;
            // Re-baked slots are in memory; any other is read here, once, and not kept.
            if (tiles[l]->in_memory(slot)) {
                written += pack(l, p, t, tiles[l]->slot(slot), shared_out, per_wave_out);
            } else {
                std::vector<float> floats(tiles[l]->slot_floats());
                tiles[l]->copy_slot(slot, floats.data());
                written += pack(l, p, t, floats.data(), shared_out, per_wave_out);
            }
        }
    }
    return written;
}

std::size_t ShoreStream::resident_tiles() const {
    std::size_t n = 0;
    for (const Pool& pool : pools_)
        n += static_cast<std::size_t>(
            std::count_if(pool.tile.begin(), pool.tile.end(), [](std::int64_t t) { return t >= 0; }));
    return n;
}

std::size_t ShoreStream::streamable_tiles() const {
    std::size_t n = 0;
    for (const Pool& pool : pools_) n += pool.candidates.size();
    return n;
}

}  // namespace tidewater::render::detail
