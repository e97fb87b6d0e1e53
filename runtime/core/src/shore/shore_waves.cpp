#include "tidewater/detail/shore_waves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <utility>
#include <vector>

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

Status check_grid(const ShoreGrid& g, const std::string& what) {
    if (g.resolution < 2 || g.resolution > 65536)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: {} resolution {} is out of range (2 to 65536)", what, g.resolution)};
    if (!(g.texel > 0.0) || !std::isfinite(g.texel) || !std::isfinite(g.corner.x) || !std::isfinite(g.corner.y))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: {} texel size and corner must be finite (texel > 0)", what)};
    return {};
}

/// Fails unless `t` cuts a grid of `n` texels into pages that name its slots of `stride`
/// finite floats.
Status check_tiles(const ShoreTiles& t, int n, std::size_t stride, const std::string& what) {
    const int m = (n + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    if (t.resolution != n || t.tiles_per_side != m ||
        t.pages.size() != static_cast<std::size_t>(m) * static_cast<std::size_t>(m))
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("shore tiles: {} has {} pages for a {}² grid, expected {}²", what, t.pages.size(), n, m)};
    const bool held = std::all_of(t.slots.begin(), t.slots.end(), [](const auto& slot) { return slot != nullptr; });
    const bool lazy =
        t.lazy && t.lazy->slot_count() == t.slot_count() && t.slots[gpu::kShoreOpenSlot] && t.slots[gpu::kShoreDrySlot];
    if (t.stride != stride || stride == 0 || t.slot_count() < gpu::kShoreFirstStoredSlot || !(held || lazy))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: {} slots do not hold {} floats a texel", what, stride)};
    const std::size_t slots = t.slot_count();
    for (std::size_t k = 0; k < t.pages.size(); ++k)
        if (t.pages[k] >= slots)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore tiles: {} tile {} names slot {} of {}", what, k, t.pages[k], slots)};
    // Slots read on demand are checked by their reader (a saved bake's decode is finite).
    for (const auto& slot : t.slots)
        if (slot && !std::all_of(slot.get(), slot.get() + t.slot_floats(), [](float v) { return std::isfinite(v); }))
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore tiles: {} has a value that is not finite", what)};
    return {};
}

/// The fine texels of one coarse tile: a fine slot in memory read in place, one that a saved
/// bake holds on disk copied once for the tile and not kept, so that the coarse level of a
/// model larger than the renderer's budget does not bring the whole model into memory.
class FineTexels {
  public:
    explicit FineTexels(const ShoreTiles& fine) : fine_(fine) {}
    /// The slot that holds fine texel (i, j).
    std::size_t slot_of(int i, int j) const { return fine_.page(i / ShoreTiles::kTile, j / ShoreTiles::kTile); }
    /// Asked row by row (j never decreasing): the copies of a row of fine tiles go when the
    /// next row starts, so that at most a row of them is held, however coarse the level.
    const float* texel(int i, int j) {
        const int ti = i / ShoreTiles::kTile, tj = j / ShoreTiles::kTile;
        if (tj != row_) {
            copies_.clear();
            row_ = tj;
        }
        const std::size_t local = static_cast<std::size_t>(j - tj * ShoreTiles::kTile) * ShoreTiles::kSide +
                                  static_cast<std::size_t>(i - ti * ShoreTiles::kTile);
        return floats(fine_.page(ti, tj)) + local * fine_.stride;
    }

  private:
    const float* floats(std::size_t slot) {
        if (slot < gpu::kShoreFirstStoredSlot || fine_.in_memory(slot)) return fine_.slot(slot);
        for (const auto& [s, copy] : copies_)
            if (s == slot) return copy.get();
        auto copy = std::make_unique_for_overwrite<float[]>(fine_.slot_floats());
        fine_.copy_slot(slot, copy.get());  // a failure reads as zeros, its error kept (ShoreTiles::status)
        copies_.emplace_back(slot, std::move(copy));
        return copies_.back().second.get();
    }

    const ShoreTiles& fine_;
    int row_ = -1;  // the row of fine tiles the copies are of
    std::vector<std::pair<std::size_t, std::unique_ptr<float[]>>> copies_;
};

/// `fine` on every `stride`-th texel of its grid: the pages (coarse_pages), each stored
/// slot's texels copied from the fine texel under it, and the constant slots. With
/// `before` (`before.fine` coarsened at this stride into `before.coarse`, laid out as
/// these), a coarse slot whose every texel comes from a fine slot `fine` shares with
/// `before.fine` is `before.coarse`'s, shared, not made again.
struct CoarseningBefore {
    const ShoreTiles *fine = nullptr, *coarse = nullptr;
};
ShoreTiles coarsened_tiles(const ShoreTiles& fine, int stride, std::span<const glm::dvec2> open,
                           CoarseningBefore before = {}) {
    ShoreTiles c = coarse_pages(fine, stride);
    const std::size_t floats = c.stride;
    const bool reuse = before.fine && before.coarse && before.fine->pages == fine.pages &&
                       before.fine->stride == fine.stride && before.coarse->pages == c.pages;
    if (reuse) {
        c.slots = before.coarse->slots;
    } else {
        c.assign_slots(slots_named(c));
        fill_constant_slots(c, open);
    }
    const auto packed = static_cast<std::size_t>(c.resolution);
    // The fine texel under coarse grid texel g.
    auto fine_i = [&](std::size_t g) { return static_cast<int>(g % packed) * stride; };
    auto fine_j = [&](std::size_t g) { return static_cast<int>(g / packed) * stride; };
    detail::parallel_for_each(c.pages.size(), 0, [&](std::size_t tile) {
        const std::uint32_t slot = c.pages[tile];
        if (slot < gpu::kShoreFirstStoredSlot) return;
        FineTexels texels(fine);
        if (reuse) {
            bool shared = true;
            for (std::size_t s = 0; s < ShoreTiles::kSlotTexels && shared; ++s) {
                const std::size_t g = c.grid_index(tile, s);
                shared = fine.same_slot(texels.slot_of(fine_i(g), fine_j(g)), *before.fine);
            }
            if (shared) return;
        }
        float* out = c.slot_for_writing(slot);
        for (std::size_t s = 0; s < ShoreTiles::kSlotTexels; ++s) {
            const std::size_t g = c.grid_index(tile, s);
            const float* in = texels.texel(fine_i(g), fine_j(g));
            std::copy(in, in + floats, out + s * floats);
        }
    });
    return c;
}

/// `grid` on every `stride`-th texel, its first texel centre kept.
ShoreGrid coarsened_grid(const ShoreGrid& g, int stride) {
    const double texel = g.texel * stride;
    return {(g.resolution - 1) / stride + 1, texel, g.corner + glm::dvec2(0.5 * g.texel - 0.5 * texel)};
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
    CutShoreTiles cut = cut_shore_tiles(fields, open);
    const ShoreGrid grid{fields.resolution, fields.texel, fields.corner};
    auto layers = std::make_shared<Layers>();
    if (wave_count > 0) layers->push_back({grid, 0, wave_count, std::move(cut.waves)});
    return std::shared_ptr<const ShoreWaves>(made(grid, std::move(cut.shared), std::move(layers), std::move(open)));
}

Result<std::shared_ptr<const ShoreWaves>> ShoreWaves::from_tiles(const ShoreGrid& grid, ShoreTiles shared,
                                                                 std::vector<ShoreWaveLayer> layers,
                                                                 std::span<const Wave> waves) {
    if (auto st = check_grid(grid, "the shared grid's"); !st) return st.error();
    if (auto st = check_tiles(shared, grid.resolution, kShoreSharedRows, "the shared layer"); !st) return st.error();
    if (layers.size() > gpu::kShoreMaxLayers)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: {} runs of waves, at most {}", layers.size(), gpu::kShoreMaxLayers)};
    std::size_t next = 0;
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const ShoreWaveLayer& layer = layers[l];
        const std::string what = fmt::format("wave run {}", l);
        if (layer.first != next || layer.count == 0 || layer.count > waves.size() - next)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore tiles: {} holds waves {} to {}, expected a run from wave {} of {}", what,
                                     layer.first, layer.first + layer.count, next, waves.size())};
        next += layer.count;
        if (auto st = check_grid(layer.grid, what + "'s"); !st) return st.error();
        if (auto st = check_tiles(layer.tiles, layer.grid.resolution, 4 * layer.count, what); !st) return st.error();
    }
    if (next != waves.size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore tiles: the runs hold {} waves, the set {}", next, waves.size())};
    auto open = open_wavevectors(waves);
    fill_constant_slots(shared, {});
    for (ShoreWaveLayer& layer : layers)
        fill_constant_slots(layer.tiles, std::span<const glm::dvec2>(open).subspan(layer.first, layer.count));
    return std::shared_ptr<const ShoreWaves>(
        made(grid, std::move(shared), std::make_shared<const Layers>(std::move(layers)), std::move(open)));
}

std::shared_ptr<ShoreWaves> ShoreWaves::made(const ShoreGrid& grid, ShoreTiles shared,
                                             std::shared_ptr<const Layers> layers, std::vector<glm::dvec2> open) {
    auto out = std::make_shared<ShoreWaves>();
    out->grid_ = grid;
    out->shared_ = std::move(shared);
    out->layers_ = std::move(layers);
    auto all_open = [](const ShoreTiles& t) {
        return std::all_of(t.pages.begin(), t.pages.end(),
                           [](std::uint32_t slot) { return slot == gpu::kShoreOpenSlot; });
    };
    out->trivial_ = all_open(out->shared_) && std::all_of(out->layers_->begin(), out->layers_->end(),
                                                          [&](const ShoreWaveLayer& l) { return all_open(l.tiles); });
    out->open_wavevectors_ = std::move(open);
    return out;
}

std::shared_ptr<const ShoreWaves> ShoreWaves::coarsened(int stride, const ShoreWaves* before,
                                                        const ShoreWaves* before_coarse) const {
    if (stride <= 1) return made(grid_, shared_, layers_, open_wavevectors_);
    const bool reuse = before && before_coarse && before->layers_->size() == layers_->size() &&
                       before_coarse->layers_->size() == layers_->size() && before->grid_ == grid_;
    auto layers = std::make_shared<Layers>();
    for (std::size_t k = 0; k < layers_->size(); ++k) {
        const ShoreWaveLayer& l = (*layers_)[k];
        const bool same_run = reuse && (*before->layers_)[k].grid == l.grid && (*before->layers_)[k].count == l.count;
        layers->push_back(
            {coarsened_grid(l.grid, stride), l.first, l.count,
             coarsened_tiles(l.tiles, stride, std::span<const glm::dvec2>(open_wavevectors_).subspan(l.first, l.count),
                             same_run
                                 ? CoarseningBefore{&(*before->layers_)[k].tiles, &(*before_coarse->layers_)[k].tiles}
                                 : CoarseningBefore{})});
    }
    return made(
        coarsened_grid(grid_, stride),
        coarsened_tiles(shared_, stride, {},
                        reuse ? CoarseningBefore{&before->shared_, &before_coarse->shared_} : CoarseningBefore{}),
        std::move(layers), open_wavevectors_);
}

std::uint64_t ShoreWaves::coarsened_device_bytes(int stride) const {
    if (stride <= 1) return device_bytes();
    auto bytes = [&](const ShoreTiles& t) {
        const ShoreTiles c = coarse_pages(t, stride);
        return ShoreTiles::device_bytes_for(slots_named(c), c.stride, c.pages.size());
    };
    std::uint64_t total = bytes(shared_);
    for (const ShoreWaveLayer& l : *layers_) total += bytes(l.tiles);
    return total;
}

std::size_t ShoreWaves::bytes() const {
    std::size_t total = shared_.bytes();
    for (const ShoreWaveLayer& l : *layers_) total += l.tiles.bytes();
    return total;
}

std::uint64_t ShoreWaves::device_bytes() const {
    std::uint64_t total = shared_.device_bytes();
    for (const ShoreWaveLayer& l : *layers_) total += l.tiles.device_bytes();
    return total;
}

Status ShoreWaves::read_all() const {
    if (auto st = shared_.read_all(); !st) return st;
    for (const ShoreWaveLayer& l : *layers_)
        if (auto st = l.tiles.read_all(); !st) return st;
    return {};
}

Status ShoreWaves::status() const {
    if (auto st = shared_.status(); !st) return st;
    for (const ShoreWaveLayer& l : *layers_)
        if (auto st = l.tiles.status(); !st) return st;
    return {};
}

std::size_t ShoreWaves::stored_tiles() const {
    std::size_t total = shared_.stored_tiles();
    for (const ShoreWaveLayer& l : *layers_) total += l.tiles.stored_tiles();
    return total;
}

std::shared_ptr<const ShoreWaves> ShoreWaves::with_depths(int i0, int j0, int w, int h,
                                                          std::span<const float> depths) const {
    ShoreTiles t = shared_;
    t.write_texels(i0, j0, i0 + w, j0 + h, [&](float* texel, int i, int j) {
        texel[0] =
            depths[static_cast<std::size_t>(j - j0) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i - i0)];
    });
    return made(grid_, std::move(t), layers_, open_wavevectors_);
}

std::shared_ptr<const ShoreWaves> ShoreWaves::with_tiles(ShoreTiles shared, std::vector<ShoreTiles> runs) const {
    auto layers = std::make_shared<Layers>(*layers_);
    for (std::size_t r = 0; r < layers->size() && r < runs.size(); ++r) (*layers)[r].tiles = std::move(runs[r]);
    return made(grid_, std::move(shared), std::move(layers), open_wavevectors_);
}

LocalShore ShoreWaves::sample(glm::dvec2 p, std::span<LocalWave> waves) const {
    const ShoreTaps shared = shore_taps(grid_, shared_, p);
    LocalShore s;
    s.depth = shared.lerp(0);
    s.breaking = shared.lerp(1);
    s.steepness_scale = shared.lerp(2);
    s.shore_distance = shared.lerp(3);
    for (const ShoreWaveLayer& layer : *layers_) {
        if (layer.first >= waves.size()) break;
        const ShoreTaps taps = shore_taps(layer.grid, layer.tiles, p);
        const std::size_t nw = layer.count;
        for (std::size_t w = 0; w < nw && layer.first + w < waves.size(); ++w) {
            LocalWave& out = waves[layer.first + w];
            out.phase_residual = taps.lerp(w);
            out.amplitude_factor = s.depth > 0.0 ? taps.lerp(nw + w) : 0.0;
            out.wavevector = {taps.lerp(2 * nw + w), taps.lerp(3 * nw + w)};
        }
    }
    return s;
}

}  // namespace tidewater
