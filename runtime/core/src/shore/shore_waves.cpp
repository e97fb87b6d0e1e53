#include "tidewater/detail/shore_waves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {

namespace {

/// The pages of the model on every `stride`-th texel, slots numbered in tile order (no
/// texels yet): a coarse tile whose texels all come from open-sea (dry-land) tiles holds
/// exactly the open sea's (dry land's) values and is not stored.
ShoreTiles coarse_pages(const ShoreTiles& fine, int stride) {
    ShoreTiles c;
    c.resolution = (fine.resolution - 1) / stride + 1;
    c.tiles_per_side = (c.resolution + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    c.stride = fine.stride;
    const int m = c.tiles_per_side;
    c.pages.assign(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), gpu::kShoreOpenSlot);
    std::uint32_t next = gpu::kShoreFirstStoredSlot;
    const int last = static_cast<int>(ShoreTiles::kSide) - 1;
    for (int cj = 0; cj < m; ++cj)
        for (int ci = 0; ci < m; ++ci) {
            // The fine tiles under the coarse slot's texels, its apron included.
            const int i0 = ci * ShoreTiles::kTile * stride / ShoreTiles::kTile;
            const int j0 = cj * ShoreTiles::kTile * stride / ShoreTiles::kTile;
            const int i1 = std::min(ci * ShoreTiles::kTile + last, c.resolution - 1) * stride / ShoreTiles::kTile;
            const int j1 = std::min(cj * ShoreTiles::kTile + last, c.resolution - 1) * stride / ShoreTiles::kTile;
            bool open = true, dry = true;
            for (int tj = j0; tj <= j1; ++tj)
                for (int ti = i0; ti <= i1; ++ti) {
                    const std::uint32_t page = fine.page(ti, tj);
                    open = open && page == gpu::kShoreOpenSlot;
                    dry = dry && page == gpu::kShoreDrySlot;
                }
            c.pages[static_cast<std::size_t>(cj) * static_cast<std::size_t>(m) + static_cast<std::size_t>(ci)] =
                open  ? gpu::kShoreOpenSlot
                : dry ? gpu::kShoreDrySlot
                      : next++;
        }
    return c;
}

std::size_t slots_named(const ShoreTiles& t) {
    std::uint32_t most = gpu::kShoreFirstStoredSlot - 1;
    for (std::uint32_t page : t.pages) most = std::max(most, page);
    return static_cast<std::size_t>(most) + 1;
}

std::vector<glm::dvec2> open_wavevectors(std::span<const Wave> waves) {
    std::vector<glm::dvec2> out;
    out.reserve(waves.size());
    for (const Wave& w : waves) out.push_back(w.k * glm::dvec2(w.dir_x, w.dir_z));
    return out;
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> ShoreWaves::from_fields(ShoreWaveFields fields, std::span<const Wave> waves) {
    const std::size_t wave_count = waves.size();
    const int n = fields.resolution;
    if (n < 2 || n > 8192)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore fields: resolution {} is out of range (2 to 8192)", n)};
    if (!(fields.texel > 0.0) || !std::isfinite(fields.texel) || !std::isfinite(fields.corner.x) ||
        !std::isfinite(fields.corner.y))
        return Error{ErrorCode::invalid_argument, "shore fields: the texel size and corner must be finite (texel > 0)"};
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    auto check = [&](const std::vector<float>& grid, const std::string& name) -> Status {
        if (grid.size() != count)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore fields: {} has {} values, expected {}x{}", name, grid.size(), n, n)};
        for (float v : grid)
            if (!std::isfinite(v))
                return Error{ErrorCode::invalid_argument, fmt::format("shore fields: {} has a non-finite value", name)};
        return {};
    };
    const std::pair<const std::vector<std::vector<float>>*, const char*> per_wave[] = {
        {&fields.phase_residual, "phase_residual"},
        {&fields.amplitude_factor, "amplitude_factor"},
        {&fields.wavevector_x, "wavevector_x"},
        {&fields.wavevector_z, "wavevector_z"}};
    for (const auto& [grids, name] : per_wave) {
        if (grids->size() != wave_count)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore fields: {} {} fields for {} waves", grids->size(), name, wave_count)};
        for (std::size_t w = 0; w < grids->size(); ++w)
            if (auto st = check((*grids)[w], fmt::format("wave {} {}", w, name)); !st) return st.error();
    }
    const std::pair<const std::vector<float>*, const char*> shared[] = {{&fields.depth, "depth"},
                                                                        {&fields.shore_distance, "shore_distance"},
                                                                        {&fields.breaking, "breaking"},
                                                                        {&fields.steepness_scale, "steepness_scale"}};
    for (const auto& [grid, name] : shared)
        if (auto st = check(*grid, name); !st) return st.error();
    auto open = open_wavevectors(waves);
    ShoreTiles tiles = cut_shore_tiles(fields, open);
    return std::shared_ptr<const ShoreWaves>(
        made({fields.resolution, fields.texel, fields.corner}, std::move(tiles), std::move(open)));
}

Result<std::shared_ptr<const ShoreWaves>> ShoreWaves::from_tiles(const ShoreGrid& grid, ShoreTiles tiles,
                                                                 std::span<const Wave> waves) {
    const int n = grid.resolution;
    if (n < 2 || n > 65536)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: resolution {} is out of range (2 to 65536)", n)};
    if (!(grid.texel > 0.0) || !std::isfinite(grid.texel) || !std::isfinite(grid.corner.x) ||
        !std::isfinite(grid.corner.y))
        return Error{ErrorCode::invalid_argument, "shore tiles: the texel size and corner must be finite (texel > 0)"};
    const int m = (n + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    if (tiles.resolution != n || tiles.tiles_per_side != m ||
        tiles.pages.size() != static_cast<std::size_t>(m) * static_cast<std::size_t>(m))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: {} pages for a {}² grid, expected {}²", tiles.pages.size(), n, m)};
    if (tiles.stride != query_texel_stride(waves.size()) ||
        tiles.texels.size() % (tiles.stride * ShoreTiles::kSlotTexels) != 0 ||
        tiles.slot_count() < gpu::kShoreFirstStoredSlot)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: the slots do not hold {} waves", waves.size())};
    const std::size_t slots = tiles.slot_count();
    for (std::size_t k = 0; k < tiles.pages.size(); ++k)
        if (tiles.pages[k] >= slots)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore tiles: tile {} names slot {} of {}", k, tiles.pages[k], slots)};
    for (float v : tiles.texels)
        if (!std::isfinite(v)) return Error{ErrorCode::invalid_argument, "shore tiles: a stored value is not finite"};
    auto open = open_wavevectors(waves);
    fill_constant_slots(tiles, open);
    return std::shared_ptr<const ShoreWaves>(made(grid, std::move(tiles), std::move(open)));
}

std::shared_ptr<ShoreWaves> ShoreWaves::made(const ShoreGrid& grid, ShoreTiles tiles, std::vector<glm::dvec2> open) {
    auto out = std::make_shared<ShoreWaves>();
    out->grid_ = grid;
    out->tiles_ = std::move(tiles);
    out->trivial_ = std::all_of(out->tiles_.pages.begin(), out->tiles_.pages.end(),
                                [](std::uint32_t slot) { return slot == gpu::kShoreOpenSlot; });
    out->open_wavevectors_ = std::move(open);
    return out;
}

std::shared_ptr<const ShoreWaves> ShoreWaves::coarsened(int stride) const {
    if (stride <= 1) return made(grid_, tiles_, open_wavevectors_);
    ShoreTiles c = coarse_pages(tiles_, stride);
    const std::size_t floats = c.stride, slot_floats = ShoreTiles::kSlotTexels * floats;
    c.texels.assign(slots_named(c) * slot_floats, 0.0f);
    fill_constant_slots(c, open_wavevectors_);
    const auto packed = static_cast<std::size_t>(c.resolution);
    detail::parallel_for_each(c.pages.size(), 0, [&](std::size_t tile) {
        const std::uint32_t slot = c.pages[tile];
        if (slot < gpu::kShoreFirstStoredSlot) return;
        float* out = c.texels.data() + slot * slot_floats;
        for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s) {
            const std::size_t g = c.grid_index(tile, s);
            const float* in =
                tiles_.texel(static_cast<int>(g % packed) * stride, static_cast<int>(g / packed) * stride);
            std::copy(in, in + floats, out + s * floats);
        }
    });
    const double texel = grid_.texel * stride;
    return made({c.resolution, texel, grid_.corner + glm::dvec2(0.5 * grid_.texel - 0.5 * texel)}, std::move(c),
                open_wavevectors_);
}

std::uint64_t ShoreWaves::coarsened_device_bytes(int stride) const {
    if (stride <= 1) return tiles_.device_bytes();
    const ShoreTiles c = coarse_pages(tiles_, stride);
    return ShoreTiles::device_bytes_for(slots_named(c), c.stride, c.pages.size());
}

std::shared_ptr<const ShoreWaves> ShoreWaves::with_depths(int i0, int j0, int w, int h,
                                                          std::span<const float> depths) const {
    ShoreTiles t = tiles_;
    const int n = grid_.resolution, m = t.tiles_per_side, kTile = ShoreTiles::kTile;
    const std::size_t depth_row = 4 * wave_count(), slot_floats = ShoreTiles::kSlotTexels * t.stride;
    // A texel lies in its own tile's slot and in the aprons of the tiles before it.
    for (int tj = std::max(0, (j0 - 1) / kTile); tj <= std::min(m - 1, (j0 + h - 1) / kTile); ++tj)
        for (int ti = std::max(0, (i0 - 1) / kTile); ti <= std::min(m - 1, (i0 + w - 1) / kTile); ++ti) {
            const std::size_t tile =
                static_cast<std::size_t>(tj) * static_cast<std::size_t>(m) + static_cast<std::size_t>(ti);
            if (t.pages[tile] < gpu::kShoreFirstStoredSlot) continue;
            float* slot = t.texels.data() + t.pages[tile] * slot_floats;
            for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s) {
                const std::size_t g = t.grid_index(tile, s);
                const int i = static_cast<int>(g % static_cast<std::size_t>(n)) - i0;
                const int j = static_cast<int>(g / static_cast<std::size_t>(n)) - j0;
                if (i < 0 || j < 0 || i >= w || j >= h) continue;
                slot[s * t.stride + depth_row] =
                    depths[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i)];
            }
        }
    return made(grid_, std::move(t), open_wavevectors_);
}

LocalShore ShoreWaves::sample(glm::dvec2 p, std::span<LocalWave> waves) const {
    // The taps of grid_taps, read from the cell's slot.
    const int n = grid_.resolution;
    const detail::GridTaps taps = detail::grid_taps(grid_.corner, grid_.texel, n, p);
    const int i = static_cast<int>(taps.k00 % static_cast<std::size_t>(n));
    const int j = static_cast<int>(taps.k00 / static_cast<std::size_t>(n));
    const float* t00 = tiles_.cell(i, j);
    const std::size_t stride = tiles_.stride, row = ShoreTiles::kSide * stride;
    const float* t10 = t00 + (taps.k10 != taps.k00 ? stride : 0);
    const float* t01 = t00 + (taps.k01 != taps.k00 ? row : 0);
    const float* t11 = t01 + (taps.k11 != taps.k01 ? stride : 0);
    auto lerp = [&](std::size_t field) {
        return taps.w00 * static_cast<double>(t00[field]) + taps.w10 * static_cast<double>(t10[field]) +
               taps.w01 * static_cast<double>(t01[field]) + taps.w11 * static_cast<double>(t11[field]);
    };
    const std::size_t nw = wave_count();
    LocalShore s;
    s.depth = lerp(4 * nw);
    s.breaking = lerp(4 * nw + 1);
    s.steepness_scale = lerp(4 * nw + 2);
    s.shore_distance = lerp(4 * nw + 3);
    for (std::size_t w = 0; w < waves.size() && w < nw; ++w) {
        waves[w].phase_residual = lerp(w);
        waves[w].amplitude_factor = s.depth > 0.0 ? lerp(nw + w) : 0.0;
        waves[w].wavevector = {lerp(2 * nw + w), lerp(3 * nw + w)};
    }
    return s;
}

}  // namespace tidewater
