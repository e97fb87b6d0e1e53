// What the march of a run's waves leaves for the cap and the foam, kept until the cap:
// per stored texel and wave, the march's share and amplitude factor (MarchedAmplitudes);
// per texel of the run's grid, the marched energy summed over the waves (MarchedEnergy).
// Both are held in blocks made where a wave's march first leaves something, so that they
// take memory where the waves feel the bottom, not over every stored tile: a run's long
// waves store most tiles of a large world, its short ones few. The blocks are shared
// between copies and copied when written (a re-bake after an edit copies what it
// changes). Internal to the shore bake.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "shore/shore_rows.hpp"
#include "tidewater/detail/shore_tiles.hpp"

namespace tidewater::detail {

/// A run's marched energy and its breaking part per texel of its grid, summed over its
/// waves as each one's march finishes, in tiles of the grid. Threading: add() from one
/// thread at a time; the reads once every add is done.
class MarchedEnergy {
  public:
    /// Sums over a grid of `resolution` texels a side, in quanta of `quantum` m^2.
    MarchedEnergy(int resolution, double quantum)
        : resolution_(resolution),
          tiles_per_side_((resolution + kTile - 1) / kTile),
          quantum_(quantum),
          tiles_(static_cast<std::size_t>(tiles_per_side_) * static_cast<std::size_t>(tiles_per_side_)) {}

    double quantum() const { return quantum_; }

    /// Adds `quanta` to grid texel k's energy, and to its breaking part when `broken`:
    /// integers, saturating, so that the sums do not depend on the order of the adds.
    void add(std::size_t k, std::uint32_t quanta, bool broken) {
        const std::size_t n = static_cast<std::size_t>(resolution_);
        const int i = static_cast<int>(k % n), j = static_cast<int>(k / n);
        Tile& tile = writable(tile_of(i, j));
        const std::size_t at = texel_in_tile(i, j);
        saturating_add(tile.energy[at], quanta);
        if (broken) saturating_add(tile.breaking[at], quanta);
    }

    /// Sets texel (i, j)'s sums, in quanta.
    void assign(int i, int j, std::uint32_t energy, std::uint32_t breaking) {
        const std::size_t t = tile_of(i, j);
        if (!tiles_[t] && energy == 0 && breaking == 0) return;
        Tile& tile = writable(t);
        tile.energy[texel_in_tile(i, j)] = energy;
        tile.breaking[texel_in_tile(i, j)] = breaking;
    }

    /// `quanta` added to `sum` as add() does: saturating.
    static void saturating_add(std::uint32_t& sum, std::uint32_t quanta) {
        sum = static_cast<std::uint32_t>(std::min<std::uint64_t>(std::uint64_t{sum} + quanta, 0xFFFFFFFFu));
    }

    /// Texel (i, j)'s sums in m^2 (0 where no wave left energy).
    DiffractedEnergy at(int i, int j) const {
        const Tile* tile = tiles_[tile_of(i, j)].get();
        if (!tile) return {};
        const std::size_t k = texel_in_tile(i, j);
        return {quantum_ * static_cast<double>(tile->energy[k]), quantum_ * static_cast<double>(tile->breaking[k])};
    }

    /// Bytes held by the tiles made so far.
    std::size_t bytes() const {
        return sizeof(Tile) * static_cast<std::size_t>(std::count_if(tiles_.begin(), tiles_.end(),
                                                                     [](const auto& t) { return t != nullptr; }));
    }

  private:
    static constexpr int kTile = ShoreTiles::kTile;
    static constexpr std::size_t kTileTexels = static_cast<std::size_t>(kTile) * static_cast<std::size_t>(kTile);
    struct Tile {
        std::array<std::uint32_t, kTileTexels> energy{}, breaking{};
    };

    std::size_t tile_of(int i, int j) const {
        return static_cast<std::size_t>(j / kTile) * static_cast<std::size_t>(tiles_per_side_) +
               static_cast<std::size_t>(i / kTile);
    }
    static std::size_t texel_in_tile(int i, int j) {
        return static_cast<std::size_t>(j % kTile) * static_cast<std::size_t>(kTile) +
               static_cast<std::size_t>(i % kTile);
    }
    Tile& writable(std::size_t t) {
        std::shared_ptr<Tile>& tile = tiles_[t];
        if (!tile)
            tile = std::make_shared<Tile>();
        else if (tile.use_count() > 1)
            tile = std::make_shared<Tile>(*tile);
        return *tile;
    }

    int resolution_;
    int tiles_per_side_;
    double quantum_;
    std::vector<std::shared_ptr<Tile>> tiles_;
};

/// One run's marched energy and its grid, as the foam reads them.
struct EnergyView {
    const ShoreGrid* grid = nullptr;
    const MarchedEnergy* energy = nullptr;
};

/// The runs' marched energy at world xz `p`, texel (i, j) of `grid`: read where a run lies
/// on that grid, sampled bilinearly elsewhere.
inline DiffractedEnergy marched_energy_at(std::span<const EnergyView> runs, const ShoreGrid& grid, int i, int j,
                                          glm::dvec2 p) {
    DiffractedEnergy sum;
    for (const EnergyView& r : runs) {
        const ShoreGrid& g = *r.grid;
        const int n = g.resolution;
        if (g == grid) {
            const DiffractedEnergy e = r.energy->at(i, j);
            sum.marched += e.marched;
            sum.breaking += e.breaking;
            continue;
        }
        const glm::dvec2 f = (p - g.corner) / g.texel - 0.5;
        const int a = std::clamp(static_cast<int>(std::floor(f.x)), 0, n - 2);
        const int b = std::clamp(static_cast<int>(std::floor(f.y)), 0, n - 2);
        const double u = std::clamp(f.x - a, 0.0, 1.0), v = std::clamp(f.y - b, 0.0, 1.0);
        const DiffractedEnergy e00 = r.energy->at(a, b), e01 = r.energy->at(a, b + 1), e10 = r.energy->at(a + 1, b),
                               e11 = r.energy->at(a + 1, b + 1);
        auto lerp = [&](double DiffractedEnergy::*part) {
            return (1 - u) * ((1 - v) * (e00.*part) + v * (e01.*part)) + u * ((1 - v) * (e10.*part) + v * (e11.*part));
        };
        sum.marched += lerp(&DiffractedEnergy::marched);
        sum.breaking += lerp(&DiffractedEnergy::breaking);
    }
    return sum;
}

/// Per stored texel of a run's tiles and wave of the run, the march's share of the wave's
/// amplitude (0..255; 0 where the march did not hold), its amplitude factor in half
/// precision (2^-11 relative) and, for edits (`reach`), whether the march reached the
/// texel (its share may still be 0, by the wave's angle) and whether the wave is broken
/// there, in blocks of a stored slot and a wave. The bake's cap alone reads the shares and
/// amplitudes: a record made without `reach` keeps no more (reached() and broken() are then
/// false). Threading: distinct waves may be set from distinct threads; the reads once every
/// set is done.
class MarchedAmplitudes {
  public:
    MarchedAmplitudes(std::size_t stored_slots, std::size_t waves, bool reach = true)
        : waves_(waves), blocks_(stored_slots * waves), flags_(reach ? stored_slots * waves : 0) {}

    /// Stored texel `at` (stored slot * kSlotTexels + texel in the slot), wave w. Nothing
    /// is kept where the march did not reach.
    void set(std::size_t at, std::size_t w, std::uint8_t share, float amplitude, bool reached = true,
             bool broken = false) {
        const std::size_t b = block_of(at, w);
        std::shared_ptr<Block>& block = blocks_[b];
        if (!block && !reached) return;
        Block& values = writable(block);
        const std::size_t k = at % ShoreTiles::kSlotTexels;
        values.share[k] = reached ? share : 0;
        values.amplitude[k] = glm::packHalf1x16(reached ? amplitude : 0.0f);
        if (!flags_.empty())
            writable(flags_[b])[k] =
                static_cast<std::uint8_t>((reached ? kReached : 0) | (reached && broken ? kBroken : 0));
    }
    std::uint8_t share(std::size_t at, std::size_t w) const {
        const Block* block = blocks_[block_of(at, w)].get();
        return block ? block->share[at % ShoreTiles::kSlotTexels] : 0;
    }
    float amplitude(std::size_t at, std::size_t w) const {
        const Block* block = blocks_[block_of(at, w)].get();
        return block ? glm::unpackHalf1x16(block->amplitude[at % ShoreTiles::kSlotTexels]) : 0.0f;
    }
    /// An amplitude as the record holds it (half precision).
    static float held(float amplitude) { return glm::unpackHalf1x16(glm::packHalf1x16(amplitude)); }
    /// How far a held amplitude may lie from the one set: half the half precision's step
    /// at its value (11 significant bits; 2^-24 apart under the least normal).
    static double rounding(float amplitude) {
        int exponent = 0;
        std::frexp(amplitude, &exponent);
        return amplitude == 0.0f ? 0.0 : std::ldexp(1.0, std::max(exponent - 12, -25));
    }
    bool reached(std::size_t at, std::size_t w) const { return (flags(at, w) & kReached) != 0; }
    bool broken(std::size_t at, std::size_t w) const { return (flags(at, w) & kBroken) != 0; }
    /// Whether the record keeps where the march reached and broke (made with `reach`): one
    /// an edit reads, which keeps a block wherever the march reached, share or none.
    bool keeps_reach() const { return !flags_.empty(); }

    /// Bytes held by the blocks made so far.
    std::size_t bytes() const {
        auto made = [](const auto& blocks) {
            return static_cast<std::size_t>(
                std::count_if(blocks.begin(), blocks.end(), [](const auto& b) { return b != nullptr; }));
        };
        return sizeof(Block) * made(blocks_) + sizeof(Flags) * made(flags_);
    }

  private:
    static constexpr std::uint8_t kReached = 1, kBroken = 2;
    struct Block {
        std::array<std::uint8_t, ShoreTiles::kSlotTexels> share{};
        std::array<std::uint16_t, ShoreTiles::kSlotTexels> amplitude{};
    };
    using Flags = std::array<std::uint8_t, ShoreTiles::kSlotTexels>;
    /// The block to write: made, or copied first when a copy of the record shares it.
    template <typename T>
    static T& writable(std::shared_ptr<T>& block) {
        if (!block)
            block = std::make_shared<T>();
        else if (block.use_count() > 1)
            block = std::make_shared<T>(*block);
        return *block;
    }
    std::uint8_t flags(std::size_t at, std::size_t w) const {
        if (flags_.empty()) return 0;
        const Flags* block = flags_[block_of(at, w)].get();
        return block ? (*block)[at % ShoreTiles::kSlotTexels] : 0;
    }
    std::size_t block_of(std::size_t at, std::size_t w) const { return (at / ShoreTiles::kSlotTexels) * waves_ + w; }

    std::size_t waves_;
    std::vector<std::shared_ptr<Block>> blocks_;
    std::vector<std::shared_ptr<Flags>> flags_;  ///< with `reach`, beside blocks_
};

/// A wave's amplitude factor at a texel with the march's `march` blended in at `share`
/// (0..255) over the rays' capped `rays`; the rays' alone where the march has no share or
/// the texel is dry (depth h).
inline float march_blend(std::uint8_t share, float march, float rays, double h) {
    if (!(share > 0 && h > 0.0)) return rays;
    const float s = static_cast<float>(share) / 255.0f;
    return s * march + (1.0f - s) * rays;
}

/// The rays' capped amplitude under `blended` (march_blend's result with `share` and
/// `march`); none where the march held it whole (share 255), which leaves no trace of it.
inline std::optional<float> rays_under_blend(std::uint8_t share, float march, float blended, double h) {
    if (!(share > 0 && h > 0.0)) return blended;
    if (share == 255) return std::nullopt;
    const float s = static_cast<float>(share) / 255.0f;
    return (blended - s * march) / (1.0f - s);
}

/// Per stored texel of the shared tiles (the model's grid), the cap's ratio (cap_ratio)
/// the shared rows were made with: where after an edit only the march moves, the foam is
/// made again from it (shared_foam) without the rays' rows. In blocks of a slot, shared
/// between copies and copied when written. Threading: distinct slots may be set from
/// distinct threads.
class CapRatios {
  public:
    /// `stored_slots` slots of ratios in one allocation, each shared until written.
    explicit CapRatios(std::size_t stored_slots = 0) {
        if (stored_slots == 0) return;
        const auto all = std::make_shared<Block[]>(stored_slots);
        blocks_.reserve(stored_slots);
        for (std::size_t s = 0; s < stored_slots; ++s) blocks_.emplace_back(all, all.get() + s);
    }
    /// Stored texel `at` (stored slot * kSlotTexels + texel in the slot), written in place:
    /// the bake's, before any copy is made.
    void fill(std::size_t at, float ratio) {
        (*blocks_[at / ShoreTiles::kSlotTexels])[at % ShoreTiles::kSlotTexels] = ratio;
    }
    /// The same, the slot copied first unless this alone holds it.
    void set(std::size_t at, float ratio) {
        std::shared_ptr<Block>& block = blocks_[at / ShoreTiles::kSlotTexels];
        if (block.use_count() > 1) block = std::make_shared<Block>(*block);
        (*block)[at % ShoreTiles::kSlotTexels] = ratio;
    }
    float at(std::size_t at) const { return (*blocks_[at / ShoreTiles::kSlotTexels])[at % ShoreTiles::kSlotTexels]; }
    std::size_t slots() const { return blocks_.size(); }

  private:
    using Block = std::array<float, ShoreTiles::kSlotTexels>;
    std::vector<std::shared_ptr<Block>> blocks_;
};

}  // namespace tidewater::detail
