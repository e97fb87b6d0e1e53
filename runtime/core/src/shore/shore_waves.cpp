#include "tidewater/detail/shore_waves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {

namespace {

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
    stride = std::max(stride, 1);
    const int n = grid_.resolution, packed = (n - 1) / stride + 1;
    const std::size_t nw = wave_count(), count = static_cast<std::size_t>(packed) * static_cast<std::size_t>(packed);
    ShoreWaveFields c;
    c.resolution = packed;
    c.texel = grid_.texel * stride;
    c.corner = grid_.corner + glm::dvec2(0.5 * grid_.texel - 0.5 * c.texel);
    c.phase_residual.assign(nw, std::vector<float>(count));
    c.amplitude_factor.assign(nw, std::vector<float>(count));
    c.wavevector_x.assign(nw, std::vector<float>(count));
    c.wavevector_z.assign(nw, std::vector<float>(count));
    c.depth.resize(count);
    c.breaking.resize(count);
    c.steepness_scale.resize(count);
    c.shore_distance.resize(count);
    for (int j = 0; j < packed; ++j)
        for (int i = 0; i < packed; ++i) {
            const std::size_t k =
                static_cast<std::size_t>(j) * static_cast<std::size_t>(packed) + static_cast<std::size_t>(i);
            const ShoreTexelView t = texel_values(i * stride, j * stride);
            for (std::size_t w = 0; w < nw; ++w) {
                c.phase_residual[w][k] = t.phase_residual(w);
                c.amplitude_factor[w][k] = t.amplitude_factor(w);
                c.wavevector_x[w][k] = t.wavevector_x(w);
                c.wavevector_z[w][k] = t.wavevector_z(w);
            }
            c.depth[k] = t.depth();
            c.breaking[k] = t.breaking();
            c.steepness_scale[k] = t.steepness_scale();
            c.shore_distance[k] = t.shore_distance();
        }
    auto open = open_wavevectors_;
    ShoreTiles tiles = cut_shore_tiles(c, open);
    return made({c.resolution, c.texel, c.corner}, std::move(tiles), std::move(open));
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
