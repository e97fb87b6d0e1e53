// The shore model in tiles: only where the waves feel the bottom are its fields
// stored (DESIGN.md, "Worlds at real scale"). The grid is cut into tiles of
// gpu::kShoreTileTexels texels a side; a page per tile names the slot that holds it.
// Tiles where every wave is as it is in the open sea, and tiles of dry land a tile
// or more from the shoreline, are not stored: their pages name the shared open-sea
// and dry-land slots. The CPU queries and the GPU (shaders/shore_fields.glsl) read
// the same slots with the same taps.
// Each slot is its own allocation, shared between copies of the tiles until one of them
// writes it (slot_for_writing): a model edited in a few tiles copies only those slots.
// A saved bake's layers read their stored slots on demand (lazy_shore_slots.hpp): until
// written, such a slot's entry is null and its floats come from the reader.
// Internal to ShoreWaves. Threading: immutable once cut; distinct slots of a ShoreTiles
// being filled may be written from distinct threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "host_device.h"
#include "tidewater/detail/lazy_shore_slots.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater {

struct ShoreWaveFields;

/// Where a grid of the model lies.
struct ShoreGrid {
    int resolution = 0;      ///< Texels per side.
    double texel = 1.0;      ///< m.
    glm::dvec2 corner{0.0};  ///< World xz of the grid's outer corner, m.

    bool operator==(const ShoreGrid&) const = default;
};

/// A tile is left out as open sea when, at each of its texels (apron included), every
/// wave's phase residual is within this many radians of 0 ...
inline constexpr double kOpenSeaPhaseTolerance = 1e-3;
/// ... its amplitude factor within this of 1 and its wavevector within this fraction of
/// k0 of k0 D, with no breaking and full steepness. At the deep-water edge of the marched
/// phase (k h = pi) shoaling leaves 0.4 %: the band kept is where depth is under about half
/// the longest wave's length.
inline constexpr double kOpenSeaRelativeTolerance = 0.01;

/// The shared fields' floats per texel (ShoreTiles of the shared layer): depth, breaking,
/// steepness scale and shore distance.
inline constexpr std::size_t kShoreSharedRows = 4;

/// One shared texel's floats (the shared layer's ShoreTiles::texels), by name.
struct ShoreTexelView {
    const float* t = nullptr;

    float depth() const { return t[0]; }
    float breaking() const { return t[1]; }
    float steepness_scale() const { return t[2]; }
    float shore_distance() const { return t[3]; }
};

/// One texel's floats of a run of `waves` waves (a wave layer's ShoreTiles::texels), by name.
struct ShoreWaveTexelView {
    const float* t = nullptr;
    std::size_t waves = 0;

    float phase_residual(std::size_t w) const { return t[w]; }
    float amplitude_factor(std::size_t w) const { return t[waves + w]; }
    float wavevector_x(std::size_t w) const { return t[2 * waves + w]; }
    float wavevector_z(std::size_t w) const { return t[3 * waves + w]; }
};

/// Field row `row` of a texel, as saved bakes name it (shore.json, the tiles' rows): its
/// field, its wave within the run (-1: a shared row) and unit. `waves` is the run's wave
/// count, 0 for the shared layer.
struct ShoreRowName {
    const char* field;
    int wave;
    const char* unit;
};
ShoreRowName shore_row_name(std::size_t row, std::size_t waves);

/// Dry land a tile or more inland (`texel` m a texel): nothing a wave or the waterline's
/// foam reads there, so a tile of such texels is not stored.
inline bool far_dry_land(double depth, double shore_distance, double texel) {
    return depth <= 0.0 && shore_distance <= -static_cast<double>(gpu::kShoreTileTexels) * texel;
}

struct ShoreTiles {
    static constexpr int kTile = static_cast<int>(gpu::kShoreTileTexels);
    static constexpr std::size_t kSide = gpu::kShoreSlotSide;
    static constexpr std::size_t kSlotTexels = gpu::kShoreSlotTexels;

    int resolution = 0;      ///< Texels per side of the whole grid.
    int tiles_per_side = 0;  ///< ceil(resolution / kTile).
    std::size_t stride = 0;  ///< Floats per texel: 4 per wave of a wave layer, kShoreSharedRows shared.
    /// Per tile, rows along +z: the slot that holds it.
    std::vector<std::uint32_t> pages;
    /// Per slot, kSlotTexels texels of `stride` floats each (a wave layer's: its W phase
    /// residuals, W amplitude factors, W wavevector x, W wavevector z; the shared layer's:
    /// depth, breaking, steepness scale and shore distance). Slots 0 and 1: open sea, dry
    /// land. Copies of the tiles share the slots; write through slot_for_writing. Null
    /// where `lazy` holds the slot.
    std::vector<std::shared_ptr<float[]>> slots;
    /// The reader of a saved bake's stored slots (null when every slot is in `slots`),
    /// shared between copies of the tiles.
    std::shared_ptr<const LazyShoreSlots> lazy;

    /// Pages for a grid of `n` texels a side, every tile open sea, no slots yet.
    static ShoreTiles open_grid(int n, std::size_t stride);

    /// Replaces the slots with `count` slots of zeros.
    void assign_slots(std::size_t count);
    /// Slot s's floats (read on demand where `lazy` holds it).
    const float* slot(std::size_t s) const {
        const float* held = slots[s].get();
        return held ? held : lazy->get(s);
    }
    /// Whether slot s's floats are in memory (held, or read and kept by `lazy`): slot(s)
    /// then reads nothing.
    bool in_memory(std::size_t s) const { return slots[s] || lazy->kept(s); }
    /// Slot s's floats copied into `out` (slot_floats of them) without `lazy` keeping them;
    /// false when it cannot be read (zeros written, the error kept: status()).
    bool copy_slot(std::size_t s, float* out) const {
        if (const float* held = slots[s].get()) {
            std::copy_n(held, slot_floats(), out);
            return true;
        }
        return lazy->copy(s, out);
    }
    /// Whether slot s here and slot s of `other` hold the same floats by construction (the
    /// same allocation, or the same reader's slot).
    bool same_slot(std::size_t s, const ShoreTiles& other) const {
        return slots[s] == other.slots[s] && (slots[s] || lazy == other.lazy);
    }
    /// Slot s's floats to write: copied first when another ShoreTiles shares the slot.
    float* slot_for_writing(std::size_t s);
    /// Reads every slot that `lazy` holds and has not read yet; the first error, if any.
    Status read_all() const;
    /// The first error of a slot read on demand; ok when none failed (or none is lazy).
    Status status() const { return lazy ? lazy->status() : Status(); }
    /// Every slot's floats, slot after slot (tests and checks).
    std::vector<float> floats() const;
    /// Floats a slot holds.
    std::size_t slot_floats() const { return kSlotTexels * stride; }

    std::size_t slot_count() const { return slots.size(); }
    /// Tiles whose fields are stored (not open sea or dry land).
    std::size_t stored_tiles() const { return slot_count() - gpu::kShoreFirstStoredSlot; }
    /// The floats of the first of cell (i, j)'s four taps (0 <= i, j <= resolution - 2, or 0
    /// on a grid of one texel); the others follow at +1, +kSide and +kSide + 1 texels.
    const float* cell(int i, int j) const {
        const int ti = i / kTile, tj = j / kTile;
        const std::size_t slot = pages[static_cast<std::size_t>(tj) * static_cast<std::size_t>(tiles_per_side) +
                                       static_cast<std::size_t>(ti)];
        const std::size_t local =
            static_cast<std::size_t>(j - tj * kTile) * kSide + static_cast<std::size_t>(i - ti * kTile);
        return this->slot(slot) + local * stride;
    }
    /// The floats of texel (i, j), 0 <= i, j < resolution, from the slot of its tile.
    const float* texel(int i, int j) const { return cell(i, j); }
    /// Texel (i, j)'s place among the stored slots' texels, in its own tile's slot (stored
    /// slot * kSlotTexels + its place there: a record's index beside the tiles); none where
    /// its tile is not stored.
    std::optional<std::size_t> stored_texel(int i, int j) const {
        const std::uint32_t slot = page(i / kTile, j / kTile);
        if (slot < gpu::kShoreFirstStoredSlot) return std::nullopt;
        return (slot - gpu::kShoreFirstStoredSlot) * kSlotTexels + static_cast<std::size_t>(j % kTile) * kSide +
               static_cast<std::size_t>(i % kTile);
    }
    /// The slot that holds tile (ti, tj).
    std::uint32_t page(int ti, int tj) const {
        return pages[static_cast<std::size_t>(tj) * static_cast<std::size_t>(tiles_per_side) +
                     static_cast<std::size_t>(ti)];
    }
    /// The grid texel behind texel k (0 .. kSlotTexels) of tile `tile`'s slot: the apron's
    /// last row and column repeat the grid's edge where the tile ends there.
    std::size_t grid_index(std::size_t tile, std::size_t k) const {
        const std::size_t m = static_cast<std::size_t>(tiles_per_side);
        const int i = std::min(static_cast<int>(tile % m) * kTile + static_cast<int>(k % kSide), resolution - 1);
        const int j = std::min(static_cast<int>(tile / m) * kTile + static_cast<int>(k / kSide), resolution - 1);
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(resolution) + static_cast<std::size_t>(i);
    }
    /// Calls visit(texel's floats, i, j) for every texel of a stored slot, aprons included,
    /// whose grid texel (i, j) lies in [i0, i1) x [j0, j1), each slot made writable first
    /// (slot_for_writing); tiles of open sea and dry land are left as they are. The tiles
    /// are spread over `threads` workers (0: all), each slot written by one. A visitor
    /// that takes two more is also given the slot and the texel's place in it.
    template <typename Visit>
    void write_texels(int i0, int j0, int i1, int j1, const Visit& visit, unsigned threads = 1) {
        i0 = std::max(i0, 0);
        j0 = std::max(j0, 0);
        i1 = std::min(i1, resolution);
        j1 = std::min(j1, resolution);
        if (i1 <= i0 || j1 <= j0) return;
        // A texel lies in its own tile's slot and in the aprons of the tiles before it.
        const int ti0 = std::max(0, (i0 - 1) / kTile), ti1 = std::min(tiles_per_side - 1, (i1 - 1) / kTile);
        const int tj0 = std::max(0, (j0 - 1) / kTile), tj1 = std::min(tiles_per_side - 1, (j1 - 1) / kTile);
        const std::size_t across = static_cast<std::size_t>(ti1 - ti0 + 1);
        const std::size_t count = across * static_cast<std::size_t>(tj1 - tj0 + 1);
        auto one_tile = [&](std::size_t k) {
            const int ti = ti0 + static_cast<int>(k % across), tj = tj0 + static_cast<int>(k / across);
            const std::size_t tile =
                static_cast<std::size_t>(tj) * static_cast<std::size_t>(tiles_per_side) + static_cast<std::size_t>(ti);
            if (pages[tile] < gpu::kShoreFirstStoredSlot) return;
            float* slot = slot_for_writing(pages[tile]);
            for (std::size_t s = 0; s < kSlotTexels; ++s) {
                const std::size_t g = grid_index(tile, s);
                const int i = static_cast<int>(g % static_cast<std::size_t>(resolution));
                const int j = static_cast<int>(g / static_cast<std::size_t>(resolution));
                if (i < i0 || j < j0 || i >= i1 || j >= j1) continue;
                if constexpr (std::is_invocable_v<const Visit&, float*, int, int, std::uint32_t, std::size_t>)
                    visit(slot + s * stride, i, j, pages[tile], s);
                else
                    visit(slot + s * stride, i, j);
            }
        };
        if (threads == 1)
            for (std::size_t k = 0; k < count; ++k) one_tile(k);
        else
            detail::parallel_for_each(count, threads, one_tile);
    }

    /// Every slot's bytes on the CPU (the pages included).
    std::size_t bytes() const {
        return slots.size() * slot_floats() * sizeof(float) + pages.size() * sizeof(std::uint32_t);
    }
    /// The same slots' bytes on the GPU (shaders/shore_fields.glsl): per texel a vec4 per
    /// wave (a wave layer) or one vec4 (the shared layer), and a uint per page.
    std::uint64_t device_bytes() const { return device_bytes_for(slot_count(), stride, pages.size()); }
    static std::uint64_t device_bytes_for(std::size_t slots, std::size_t floats_per_texel, std::size_t page_count) {
        return static_cast<std::uint64_t>(slots) * kSlotTexels * (floats_per_texel / 4) * 4 * sizeof(float) +
               page_count * sizeof(std::uint32_t);
    }
};

/// The four taps around a world point on a grid cut into `tiles` (grid_taps' cell and
/// weights: bilinear between texel centres, clamped at the edges), read from the cell's slot.
struct ShoreTaps {
    const float *t00, *t10, *t01, *t11;
    double w00, w10, w01, w11;

    double lerp(std::size_t field) const {
        return w00 * static_cast<double>(t00[field]) + w10 * static_cast<double>(t10[field]) +
               w01 * static_cast<double>(t01[field]) + w11 * static_cast<double>(t11[field]);
    }
};
ShoreTaps shore_taps(const ShoreGrid& grid, const ShoreTiles& tiles, glm::dvec2 p);

/// Writes the open-sea slot and the dry-land slot into slots 0 and 1 of `tiles`, which
/// must hold them. A wave layer's (`open_wavevectors` holds its waves' k0 D): the open sea
/// each wave as it is (residual 0, amplitude factor 1, wavevector k0 D), dry land no wave.
/// The shared layer's (no wavevectors, stride kShoreSharedRows): depth and shore distance
/// +kShoreFarValue in the open sea, -kShoreFarValue on dry land, no breaking, full steepness.
void fill_constant_slots(ShoreTiles& tiles, std::span<const glm::dvec2> open_wavevectors);

/// Cuts `fields` into tiles: the shared layer and one wave layer on the fields' grid, both
/// with the same pages. `open_wavevectors` holds each wave's k0 D (rad/m): the open sea's
/// wavevectors, and what a tile must match to be left out as open sea.
struct CutShoreTiles {
    ShoreTiles shared, waves;
};
CutShoreTiles cut_shore_tiles(const ShoreWaveFields& fields, std::span<const glm::dvec2> open_wavevectors);

/// What the fields' depth or shore distance means to a query: kShoreFarValue and beyond
/// (a tile not stored) reads as infinitely deep or far, +-kDeepWater.
double shore_far_to_infinite(double value);

}  // namespace tidewater
