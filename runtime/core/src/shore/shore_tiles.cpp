// Cutting the shore model into tiles (tidewater/detail/shore_tiles.hpp).
#include "tidewater/detail/shore_tiles.hpp"

#include <algorithm>
#include <cmath>

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
        is_dry = is_dry && far_dry_land(f.depth[k], f.shore_distance[k], f.texel);
    }
    return is_open ? TileKind::open_sea : is_dry ? TileKind::dry_land : TileKind::stored;
}

/// Writes one texel in the query layout (ShoreTiles::texels).
void write_texel(const ShoreWaveFields& f, std::size_t nw, std::size_t k, float* t) {
    for (std::size_t w = 0; w < nw; ++w) {
        t[w] = f.phase_residual[w][k];
        t[nw + w] = f.amplitude_factor[w][k];
        t[2 * nw + w] = f.wavevector_x[w][k];
        t[3 * nw + w] = f.wavevector_z[w][k];
    }
    t[4 * nw] = f.depth[k];
    t[4 * nw + 1] = f.breaking[k];
    t[4 * nw + 2] = f.steepness_scale[k];
    t[4 * nw + 3] = f.shore_distance[k];
}

/// The open sea's slot (waves as they are, deep, no shore) or dry land's (no waves).
void fill_constant_slot(float* slot, std::span<const glm::dvec2> open, bool dry, std::size_t stride) {
    const std::size_t nw = open.size();
    for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s) {
        float* t = slot + s * stride;
        for (std::size_t w = 0; w < nw; ++w) {
            t[w] = 0.0f;
            t[nw + w] = dry ? 0.0f : 1.0f;
            t[2 * nw + w] = dry ? 0.0f : static_cast<float>(open[w].x);
            t[3 * nw + w] = dry ? 0.0f : static_cast<float>(open[w].y);
        }
        const float far = dry ? -gpu::kShoreFarValue : gpu::kShoreFarValue;
        t[4 * nw] = far;
        t[4 * nw + 1] = 0.0f;
        t[4 * nw + 2] = 1.0f;
        t[4 * nw + 3] = far;
    }
}

}  // namespace

ShoreTiles cut_shore_tiles(const ShoreWaveFields& f, std::span<const glm::dvec2> open) {
    ShoreTiles t;
    const int n = f.resolution;
    const std::size_t nw = open.size();
    t.resolution = n;
    t.tiles_per_side = (n + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    t.stride = ShoreWaves::query_texel_stride(nw);
    const std::size_t m = static_cast<std::size_t>(t.tiles_per_side);
    std::vector<TileKind> kinds(m * m);
    detail::parallel_for_each(m, 0, [&](std::size_t tj) {
        for (std::size_t ti = 0; ti < m; ++ti) kinds[tj * m + ti] = classify(f, open, t, tj * m + ti);
    });
    // Slots in tile order: the same fields always cut to the same slots.
    t.pages.assign(m * m, gpu::kShoreOpenSlot);
    std::uint32_t next = gpu::kShoreFirstStoredSlot;
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        if (kinds[k] == TileKind::dry_land) t.pages[k] = gpu::kShoreDrySlot;
        if (kinds[k] == TileKind::stored) t.pages[k] = next++;
    }
    const std::size_t slot_floats = ShoreTiles::kSlotTexels * t.stride;
    t.texels.assign(static_cast<std::size_t>(next) * slot_floats, 0.0f);
    fill_constant_slots(t, open);
    detail::parallel_for_each(m * m, 0, [&](std::size_t tile) {
        const std::uint32_t slot = t.pages[tile];
        if (slot < gpu::kShoreFirstStoredSlot) return;
        float* out = t.texels.data() + slot * slot_floats;
        for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s)
            write_texel(f, nw, t.grid_index(tile, s), out + s * t.stride);
    });
    return t;
}

void fill_constant_slots(ShoreTiles& tiles, std::span<const glm::dvec2> open) {
    const std::size_t slot_floats = ShoreTiles::kSlotTexels * tiles.stride;
    fill_constant_slot(tiles.texels.data() + gpu::kShoreOpenSlot * slot_floats, open, false, tiles.stride);
    fill_constant_slot(tiles.texels.data() + gpu::kShoreDrySlot * slot_floats, open, true, tiles.stride);
}

ShoreRowName shore_row_name(std::size_t row, std::size_t waves) {
    static constexpr std::pair<const char*, const char*> per_wave[] = {
        {"phase_residual", "rad"}, {"amplitude_factor", "1"}, {"wavevector_x", "rad/m"}, {"wavevector_z", "rad/m"}};
    static constexpr std::pair<const char*, const char*> shared[] = {
        {"depth", "m"}, {"breaking", "1"}, {"steepness_scale", "1"}, {"shore_distance", "m"}};
    if (row < 4 * waves)
        return {per_wave[row / waves].first, static_cast<int>(row % waves), per_wave[row / waves].second};
    return {shared[row - 4 * waves].first, -1, shared[row - 4 * waves].second};
}

double shore_far_to_infinite(double value) {
    constexpr double far = 0.5 * static_cast<double>(gpu::kShoreFarValue);
    return value >= far ? kDeepWater : value <= -far ? -kDeepWater : value;
}

}  // namespace tidewater
