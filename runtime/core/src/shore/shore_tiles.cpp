// Cutting the shore model into tiles (tidewater/detail/shore_tiles.hpp).
#include "tidewater/detail/shore_tiles.hpp"

#include <algorithm>
#include <cmath>

#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/query.hpp"

namespace tidewater {

namespace {

enum class TileKind : unsigned char { stored, open_sea, dry_land };

bool open_sea_texel(const ShoreWaveFields& f, std::span<const glm::dvec2> open, std::size_t k) {
    if (!(f.depth[k] > 0.0f && f.breaking[k] == 0.0f && f.steepness_scale[k] == 1.0f)) return false;
    for (std::size_t w = 0; w < open.size(); ++w) {
        const double k0 = std::hypot(open[w].x, open[w].y);
        if (!(std::abs(static_cast<double>(f.phase_residual[w][k])) <= kOpenSeaPhaseTolerance &&
              std::abs(static_cast<double>(f.amplitude_factor[w][k]) - 1.0) <= kOpenSeaRelativeTolerance &&
              std::abs(static_cast<double>(f.wavevector_x[w][k]) - open[w].x) <= kOpenSeaRelativeTolerance * k0 &&
              std::abs(static_cast<double>(f.wavevector_z[w][k]) - open[w].y) <= kOpenSeaRelativeTolerance * k0))
            return false;
    }
    return true;
}

TileKind classify(const ShoreWaveFields& f, std::span<const glm::dvec2> open, const ShoreTiles& t, std::size_t tile) {
    bool is_open = true, is_dry = true;
    for (std::size_t s = 0; s < ShoreTiles::kSlotTexels && (is_open || is_dry); ++s) {
        const std::size_t k = t.grid_index(tile, s);
        is_open = is_open && open_sea_texel(f, open, k);
        is_dry =
            is_dry && far_dry_land(static_cast<double>(f.depth[k]), static_cast<double>(f.shore_distance[k]), f.texel);
    }
    return is_open ? TileKind::open_sea : is_dry ? TileKind::dry_land : TileKind::stored;
}

/// Writes one texel of the wave layer and of the shared layer.
void write_texel(const ShoreWaveFields& f, std::size_t nw, std::size_t k, float* waves, float* shared) {
    for (std::size_t w = 0; w < nw; ++w) {
        waves[w] = f.phase_residual[w][k];
        waves[nw + w] = f.amplitude_factor[w][k];
        waves[2 * nw + w] = f.wavevector_x[w][k];
        waves[3 * nw + w] = f.wavevector_z[w][k];
    }
    shared[0] = f.depth[k];
    shared[1] = f.breaking[k];
    shared[2] = f.steepness_scale[k];
    shared[3] = f.shore_distance[k];
}

/// The open sea's slot (waves as they are, deep, no shore) or dry land's (no waves).
void fill_constant_slot(float* slot, std::span<const glm::dvec2> open, bool dry, std::size_t stride) {
    const std::size_t nw = open.size();
    const float far = dry ? -gpu::kShoreFarValue : gpu::kShoreFarValue;
    for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s) {
        float* t = slot + s * stride;
        if (nw == 0) {
            t[0] = far;
            t[1] = 0.0f;
            t[2] = 1.0f;
            t[3] = far;
            continue;
        }
        for (std::size_t w = 0; w < nw; ++w) {
            t[w] = 0.0f;
            t[nw + w] = dry ? 0.0f : 1.0f;
            t[2 * nw + w] = dry ? 0.0f : static_cast<float>(open[w].x);
            t[3 * nw + w] = dry ? 0.0f : static_cast<float>(open[w].y);
        }
    }
}

}  // namespace

CutShoreTiles cut_shore_tiles(const ShoreWaveFields& f, std::span<const glm::dvec2> open) {
    const int n = f.resolution;
    const std::size_t nw = open.size();
    CutShoreTiles cut{ShoreTiles::open_grid(n, kShoreSharedRows), ShoreTiles::open_grid(n, 4 * nw)};
    ShoreTiles& t = cut.shared;
    const std::size_t m = static_cast<std::size_t>(t.tiles_per_side);
    std::vector<TileKind> kinds(m * m);
    detail::parallel_for_each(m, 0, [&](std::size_t tj) {
        for (std::size_t ti = 0; ti < m; ++ti) kinds[tj * m + ti] = classify(f, open, t, tj * m + ti);
    });
    // Slots in tile order: the same fields always cut to the same slots.
    std::uint32_t next = gpu::kShoreFirstStoredSlot;
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        if (kinds[k] == TileKind::dry_land) t.pages[k] = gpu::kShoreDrySlot;
        if (kinds[k] == TileKind::stored) t.pages[k] = next++;
    }
    cut.waves.pages = t.pages;
    for (ShoreTiles* layer : {&cut.shared, &cut.waves}) {
        layer->assign_slots(next);
        fill_constant_slots(*layer, layer == &cut.shared ? std::span<const glm::dvec2>() : open);
    }
    detail::parallel_for_each(m * m, 0, [&](std::size_t tile) {
        const std::uint32_t slot = t.pages[tile];
        if (slot < gpu::kShoreFirstStoredSlot) return;
        float* waves = cut.waves.slot_for_writing(slot);
        float* shared = t.slot_for_writing(slot);
        for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s)
            write_texel(f, nw, t.grid_index(tile, s), waves + s * cut.waves.stride, shared + s * t.stride);
    });
    return cut;
}

ShoreTiles ShoreTiles::open_grid(int n, std::size_t stride) {
    ShoreTiles t;
    t.resolution = n;
    t.tiles_per_side = (n + kTile - 1) / kTile;
    t.stride = stride;
    t.pages.assign(static_cast<std::size_t>(t.tiles_per_side) * static_cast<std::size_t>(t.tiles_per_side),
                   gpu::kShoreOpenSlot);
    return t;
}

void ShoreTiles::assign_slots(std::size_t count) {
    slots.assign(count, nullptr);
    for (auto& slot : slots) slot = std::make_shared<float[]>(slot_floats());
}

float* ShoreTiles::slot_for_writing(std::size_t s) {
    std::shared_ptr<float[]>& slot = slots[s];
    if (!slot) {
        // Read on demand until now: the tiles take a copy of their own.
        slot = std::make_shared_for_overwrite<float[]>(slot_floats());
        std::copy_n(lazy->get(s), slot_floats(), slot.get());
    } else if (slot.use_count() > 1) {
        auto copy = std::make_shared_for_overwrite<float[]>(slot_floats());
        std::copy_n(slot.get(), slot_floats(), copy.get());
        slot = std::move(copy);
    }
    return slot.get();
}

Status ShoreTiles::read_all() const {
    if (!lazy) return {};
    detail::parallel_for_each(slots.size(), 0, [&](std::size_t s) {
        if (!slots[s]) (void)lazy->get(s);
    });
    return lazy->status();
}

std::vector<float> ShoreTiles::floats() const {
    std::vector<float> all;
    all.reserve(slots.size() * slot_floats());
    for (std::size_t s = 0; s < slots.size(); ++s) all.insert(all.end(), slot(s), slot(s) + slot_floats());
    return all;
}

ShoreTaps shore_taps(const ShoreGrid& grid, const ShoreTiles& tiles, glm::dvec2 p) {
    const int n = grid.resolution;
    const detail::GridTaps taps = detail::grid_taps(grid.corner, grid.texel, n, p);
    const int i = static_cast<int>(taps.k00 % static_cast<std::size_t>(n));
    const int j = static_cast<int>(taps.k00 / static_cast<std::size_t>(n));
    const std::size_t stride = tiles.stride, row = ShoreTiles::kSide * stride;
    ShoreTaps t{};
    t.t00 = tiles.cell(i, j);
    t.t10 = t.t00 + (taps.k10 != taps.k00 ? stride : 0);
    t.t01 = t.t00 + (taps.k01 != taps.k00 ? row : 0);
    t.t11 = t.t01 + (taps.k11 != taps.k01 ? stride : 0);
    t.w00 = taps.w00;
    t.w10 = taps.w10;
    t.w01 = taps.w01;
    t.w11 = taps.w11;
    return t;
}

void fill_constant_slots(ShoreTiles& tiles, std::span<const glm::dvec2> open) {
    fill_constant_slot(tiles.slot_for_writing(gpu::kShoreOpenSlot), open, false, tiles.stride);
    fill_constant_slot(tiles.slot_for_writing(gpu::kShoreDrySlot), open, true, tiles.stride);
}

ShoreRowName shore_row_name(std::size_t row, std::size_t waves) {
    static constexpr std::pair<const char*, const char*> per_wave[] = {
        {"phase_residual", "rad"}, {"amplitude_factor", "1"}, {"wavevector_x", "rad/m"}, {"wavevector_z", "rad/m"}};
    static constexpr std::pair<const char*, const char*> shared[] = {
        {"depth", "m"}, {"breaking", "1"}, {"steepness_scale", "1"}, {"shore_distance", "m"}};
    if (waves == 0) return {shared[row].first, -1, shared[row].second};
    return {per_wave[row / waves].first, static_cast<int>(row % waves), per_wave[row / waves].second};
}

double shore_far_to_infinite(double value) {
    constexpr double far = 0.5 * static_cast<double>(gpu::kShoreFarValue);
    return value >= far ? kDeepWater : value <= -far ? -kDeepWater : value;
}

}  // namespace tidewater
