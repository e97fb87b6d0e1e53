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

/// The grid index of texel (a, b) of tile (ti, tj)'s slot: the apron's last row and
/// column repeat the grid's edge where the tile ends there.
std::size_t grid_index(int n, int ti, int tj, std::size_t a, std::size_t b) {
    const int i = std::min(ti * ShoreTiles::kTile + static_cast<int>(a), n - 1);
    const int j = std::min(tj * ShoreTiles::kTile + static_cast<int>(b), n - 1);
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
}

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

/// Dry land a tile or more inland: nothing a wave or the waterline's foam reads.
bool far_dry_texel(const ShoreWaveFields& f, double inland, std::size_t k) {
    return f.depth[k] <= 0.0f && static_cast<double>(f.shore_distance[k]) <= -inland;
}

TileKind classify(const ShoreWaveFields& f, std::span<const glm::dvec2> open, int ti, int tj) {
    const int n = f.resolution;
    const double inland = ShoreTiles::kTile * f.texel;
    bool is_open = true, is_dry = true;
    for (std::size_t b = 0; b < ShoreTiles::kSide && (is_open || is_dry); ++b)
        for (std::size_t a = 0; a < ShoreTiles::kSide && (is_open || is_dry); ++a) {
            const std::size_t k = grid_index(n, ti, tj, a, b);
            is_open = is_open && open_sea_texel(f, open, k);
            is_dry = is_dry && far_dry_texel(f, inland, k);
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
        for (std::size_t ti = 0; ti < m; ++ti)
            kinds[tj * m + ti] = classify(f, open, static_cast<int>(ti), static_cast<int>(tj));
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
    detail::parallel_for_each(m, 0, [&](std::size_t tj) {
        for (std::size_t ti = 0; ti < m; ++ti) {
            const std::uint32_t slot = t.pages[tj * m + ti];
            if (slot < gpu::kShoreFirstStoredSlot) continue;
            float* out = t.texels.data() + slot * slot_floats;
            for (std::size_t b = 0; b < ShoreTiles::kSide; ++b)
                for (std::size_t a = 0; a < ShoreTiles::kSide; ++a)
                    write_texel(f, nw, grid_index(n, static_cast<int>(ti), static_cast<int>(tj), a, b),
                                out + (b * ShoreTiles::kSide + a) * t.stride);
        }
    });
    return t;
}

void fill_constant_slots(ShoreTiles& tiles, std::span<const glm::dvec2> open) {
    const std::size_t slot_floats = ShoreTiles::kSlotTexels * tiles.stride;
    fill_constant_slot(tiles.texels.data() + gpu::kShoreOpenSlot * slot_floats, open, false, tiles.stride);
    fill_constant_slot(tiles.texels.data() + gpu::kShoreDrySlot * slot_floats, open, true, tiles.stride);
}

double shore_far_to_infinite(double value) {
    constexpr double far = 0.5 * static_cast<double>(gpu::kShoreFarValue);
    return value >= far ? kDeepWater : value <= -far ? -kDeepWater : value;
}

}  // namespace tidewater
