#include "tidewater/detail/shore_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numbers>

#include "contour.hpp"
#include "distance_field.hpp"
#include "host_device.h"
#include "shore/shore_edit_region.hpp"
#include "shore_geometry.hpp"
#include "shoreline_steps.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/detail/reference.hpp"

namespace tidewater {

namespace {

/// More shoreline than this is not a coast but noise (millions of one-texel islands).
constexpr std::size_t kMaxShoreSegments = 4'000'000;
constexpr std::size_t kMaxShoreLines = 200'000;

template <typename RowWork>
void parallel_rows(int rows, unsigned threads, const RowWork& work) {
    detail::parallel_for_each(static_cast<std::size_t>(rows), threads,
                              [&](std::size_t j) { work(static_cast<int>(j)); });
}

/// Seconds since the last call (or construction): one stage of the bake.
class StageClock {
  public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }

  private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// `field`'s shoreline from its contour's `cells` (sorted by (j, i); kept with it for
/// update_shore): chained, simplified and classified.
Status set_shoreline(ShoreField& field, std::vector<detail::ContourCell> cells, unsigned threads) {
    field.contour = std::make_shared<const std::vector<detail::ContourCell>>(cells);
    auto shoreline = detail::shoreline_from_cells(std::move(cells), field.resolution, field.corner, field.texel,
                                                  field.simplify_tolerance, threads);
    if (!shoreline) return shoreline.error();
    detail::ClassifiedShore shore = std::move(shoreline).value();
    field.polygons = shore.polygons;
    field.holes = shore.holes;
    field.shorelines = std::move(shore.lines);
    return {};
}

}  // namespace

namespace detail {

Result<WindowHeights> window_heights(const Terrain& terrain, double water_level, const ShoreField& grid,
                                     const TexelRect& r, unsigned threads) {
    WindowHeights out;
    const std::size_t count = static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
    out.above.resize(count);
    out.depth.resize(count);
    std::atomic<bool> finite{true};
    std::atomic<std::size_t> bad_index{0};
    parallel_rows(r.height, threads, [&](int row) {
        for (int col = 0; col < r.width; ++col) {
            const std::size_t k =
                static_cast<std::size_t>(row) * static_cast<std::size_t>(r.width) + static_cast<std::size_t>(col);
            // Texel centres from the whole grid's indices: a tile's are the whole grid's, bit for bit.
            const double h = terrain.height_at(grid.texel_center(r.i0 + col, r.j0 + row));
            if (!std::isfinite(h) && finite.exchange(false)) bad_index = k;
            out.above[k] = h - water_level;
            out.depth[k] = static_cast<float>(water_level - h);
        }
    });
    if (!finite) {
        const auto k = bad_index.load();
        const std::size_t w = static_cast<std::size_t>(r.width);
        const glm::dvec2 p = grid.texel_center(r.i0 + static_cast<int>(k % w), r.j0 + static_cast<int>(k / w));
        return Error{ErrorCode::invalid_argument,
                     fmt::format("bake: the terrain height is not finite at x = {:.2f}, z = {:.2f} m", p.x, p.y)};
    }
    return out;
}

std::size_t mixed_cells(const std::vector<float>& depth, const CellWindow& w, unsigned threads) {
    const std::size_t width = static_cast<std::size_t>(w.i1 - w.i0 + 1);
    std::atomic<std::size_t> mixed{0};
    parallel_rows(w.j1 - w.j0, threads, [&](int r) {
        std::size_t row_mixed = 0;
        const float* below = depth.data() + static_cast<std::size_t>(r) * width;
        const float* above_row = below + width;
        for (std::size_t i = 0; i + 1 < width; ++i) {
            const bool a = below[i] <= 0, b = below[i + 1] <= 0, c = above_row[i] <= 0, d = above_row[i + 1] <= 0;
            row_mixed += !(a == b && b == c && c == d);
        }
        mixed += row_mixed;
    });
    return mixed;
}

Status check_mixed_cells(std::size_t mixed, std::size_t count) {
    // A coast crosses O(n) cells; O(n^2) crossings is noise.
    const std::size_t mixed_limit = std::max<std::size_t>(50'000, count / 8);
    if (mixed <= mixed_limit) return {};
    return Error{
        ErrorCode::invalid_argument,
        fmt::format("bake: the shoreline crosses {} of {} cells at this resolution (at most {}): the terrain is "
                    "too noisy at the water level, like thousands of one-texel islands; smooth it or lower the "
                    "resolution",
                    mixed, count, mixed_limit)};
}

Result<ClassifiedShore> shoreline_from_cells(std::vector<ContourCell> cells, int n, glm::dvec2 corner, double texel,
                                             double tolerance, unsigned threads) {
    std::vector<ContourChain> chains = chain_contour_cells(std::move(cells), n);
    std::size_t raw_segments = 0;
    for (const auto& c : chains) raw_segments += c.points.size();
    if (raw_segments > kMaxShoreSegments || chains.size() > kMaxShoreLines) {
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("bake: the shoreline has {} pieces and {} segments at this resolution (at most {} and {}): "
                        "the terrain is too noisy at the water level; smooth it or lower the resolution",
                        chains.size(), raw_segments, kMaxShoreLines, kMaxShoreSegments)};
    }
    // In world units.
    std::vector<ShoreLine> lines;
    lines.reserve(chains.size());
    for (auto& c : chains) {
        ShoreLine line;
        line.closed = c.closed;
        line.points.reserve(c.points.size());
        for (const auto& g : c.points) line.points.push_back(corner + texel * (g + glm::dvec2(0.5)));
        lines.push_back(std::move(line));
    }
    // Cut at the shore tiles' edges on this grid: an edit changes the simplified line only
    // in the tiles it touches.
    const SimplifyLattice lattice{corner, static_cast<double>(gpu::kShoreTileTexels) * texel};
    return simplify_and_classify(std::move(lines), tolerance, lattice, threads);
}

}  // namespace detail

namespace {

/// A turn in SharedDirections' steps.
constexpr double kDirectionSteps = 65535.0;

/// Every code's unit vector, made once: decoding is a look-up.
const std::array<glm::vec2, 65536>& direction_table() {
    static const auto table = [] {
        std::array<glm::vec2, 65536> t{};
        for (std::size_t c = 0; c + 1 < t.size(); ++c) {
            const double angle = 2.0 * std::numbers::pi * static_cast<double>(c) / kDirectionSteps;
            t[c] = glm::vec2(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
        }
        t[SharedDirections::kNone] = glm::vec2(0.0f);
        return t;
    }();
    return table;
}

}  // namespace

std::uint16_t SharedDirections::encode(glm::dvec2 v) {
    if (!(v.x * v.x + v.y * v.y >= 0.25)) return kNone;
    double turns = std::atan2(v.y, v.x) / (2.0 * std::numbers::pi);
    if (turns < 0.0) turns += 1.0;
    const auto code = static_cast<std::uint32_t>(std::lround(turns * kDirectionSteps));
    return static_cast<std::uint16_t>(code % static_cast<std::uint32_t>(kDirectionSteps));
}

glm::vec2 SharedDirections::decode(std::uint16_t code) {
    return direction_table()[code];
}

double ShoreField::sample(const SharedFloats& grid, glm::dvec2 p) const {
    if (resolution < 2) return resolution == 1 ? static_cast<double>(grid[0]) : 0.0;
    return detail::grid_taps(corner, texel, resolution, p)(grid.values());
}

glm::dvec2 ShoreField::gradient_at(glm::dvec2 p) const {
    if (resolution < 2) return resolution == 1 ? glm::dvec2(gradient[0]) : glm::dvec2(0.0);
    const detail::GridTaps t = detail::grid_taps(corner, texel, resolution, p);
    return t.w00 * glm::dvec2(gradient[t.k00]) + t.w10 * glm::dvec2(gradient[t.k10]) +
           t.w01 * glm::dvec2(gradient[t.k01]) + t.w11 * glm::dvec2(gradient[t.k11]);
}

Result<ShoreField> bake_shore(const Terrain& terrain, double water_level, const BakeOptions& options) {
    if (options.resolution < 8 || options.resolution > 8192) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("bake: resolution {} is out of range (8 to 8192)", options.resolution)};
    }
    if (!std::isfinite(water_level)) return Error{ErrorCode::invalid_argument, "bake: the water level is not finite"};
    if (!std::isfinite(options.simplify_tolerance) || options.simplify_tolerance < 0.0) {
        return Error{ErrorCode::invalid_argument, "bake: simplify_tolerance must be finite and >= 0"};
    }
    const int n = options.resolution;
    const unsigned threads = options.threads;
    auto report = [&](double f) {
        if (options.progress) options.progress(f);
    };
    const auto cancelled = [] { return Error{ErrorCode::cancelled, "bake: cancelled"}; };

    ShoreField field;
    field.resolution = n;
    if (options.region && !(options.region->half_size > 0.0 && std::isfinite(options.region->half_size) &&
                            std::isfinite(options.region->center.x) && std::isfinite(options.region->center.y)))
        return Error{ErrorCode::invalid_argument,
                     "bake: the region must have a finite centre and a finite half-size > 0"};
    const double half = options.region ? options.region->half_size : terrain.extent_half_size();
    field.texel = 2.0 * half / n;
    field.corner = (options.region ? options.region->center : terrain.extent_center()) - glm::dvec2(half);
    field.simplify_tolerance = options.simplify_tolerance > 0.0 ? options.simplify_tolerance : 0.5 * field.texel;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    StageClock clock;

    // Terrain height relative to the water level at every texel centre.
    auto heights = detail::window_heights(terrain, water_level, field, {0, 0, n, n}, threads);
    if (!heights) return heights.error();
    std::vector<double> above = std::move(heights->above);
    field.depth.write() = std::move(heights->depth);
    if (options.cancel.stop_requested()) return cancelled();
    report(0.1);

    // Count before building anything.
    const std::size_t mixed = detail::mixed_cells(field.depth.values(), {0, 0, n - 1, n - 1}, threads);
    if (auto st = detail::check_mixed_cells(mixed, count); !st) return st.error();
    field.timings.heights = clock.lap();
    // The contour at the water level.
    std::vector<detail::ContourCell> cells = detail::contour_cells(above, {0, 0, n - 1, n - 1}, threads);
    field.timings.contour = clock.lap();
    if (options.cancel.stop_requested()) return cancelled();
    if (auto st = set_shoreline(field, std::move(cells), threads); !st) return st.error();
    field.timings.simplify = clock.lap();
    if (options.cancel.stop_requested()) return cancelled();
    report(0.3);

    field.signed_distance.write().assign(count, 0.0f);
    field.gradient.write().assign(count, SharedDirections::kNone);
    const auto distance = detail::ShoreDistance::build(field.shorelines);
    field.segment_count = distance->segment_count();
    field.timings.tree = clock.lap();
    if (field.segment_count == 0) {
        // No shoreline: all water or all land. The distance is the domain diagonal, signed.
        const bool water = above[0] < 0.0;
        const float far = static_cast<float>((water ? 1.0 : -1.0) * 2.0 * std::sqrt(2.0) * half);
        std::fill(field.signed_distance.write().begin(), field.signed_distance.write().end(), far);
        report(1.0);
        return field;
    }
    detail::fill_distance_field(
        *distance, field, threads, [&](double f) { report(0.3 + 0.7 * f); }, options.cancel);
    if (options.cancel.stop_requested()) return cancelled();
    field.timings.distance = clock.lap();
    report(1.0);
    return field;
}

namespace {

/// Every segment of `lines` as its two ends (x0, z0, x1, z1), sorted.
std::vector<std::array<double, 4>> sorted_segments(const std::vector<ShoreLine>& lines) {
    std::vector<std::array<double, 4>> out;
    for (const ShoreLine& line : lines) {
        const std::size_t n = line.points.size();
        for (std::size_t k = 0; k + 1 < n + (line.closed ? 1 : 0); ++k) {
            const glm::dvec2 a = line.points[k], b = line.points[(k + 1) % n];
            out.push_back({a.x, a.y, b.x, b.y});
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

Result<std::optional<ShoreField>> update_shore(const ShoreField& before, const Terrain& terrain, double water_level,
                                               const detail::WorldRect& changed, unsigned threads) {
    if (!before.contour || before.segment_count == 0 || before.resolution < 2) return std::optional<ShoreField>{};
    const int n = before.resolution;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    StageClock clock;
    ShoreField field = before;
    field.timings = {};
    const detail::TexelRange t = detail::texels_in(n, before.texel, before.corner, changed);
    if (t.empty()) return std::optional<ShoreField>{std::move(field)};
    // The cells that read a changed texel, and the texels they read.
    const detail::CellWindow cells{std::max(0, t.i0 - 1), std::max(0, t.j0 - 1), std::min(n - 1, t.i1 + 1),
                                   std::min(n - 1, t.j1 + 1)};
    const detail::TexelRect window{cells.i0, cells.j0, cells.i1 - cells.i0 + 1, cells.j1 - cells.j0 + 1};
    auto heights = detail::window_heights(terrain, water_level, field, window, threads);
    if (!heights) return heights.error();
    {
        std::vector<float>& depth = field.depth.write();
        const auto width = static_cast<std::size_t>(window.width);
        for (int row = 0; row < window.height; ++row)
            std::copy_n(heights->depth.data() + static_cast<std::size_t>(row) * width, width,
                        depth.data() + field.index(window.i0, window.j0 + row));
    }
    const std::size_t mixed = detail::mixed_cells(field.depth.values(), {0, 0, n - 1, n - 1}, threads);
    if (auto st = detail::check_mixed_cells(mixed, count); !st) return st.error();
    field.timings.heights = clock.lap();
    // The contour: the kept cells outside the window and the window's made again, in
    // (j, i) order (a cell's pieces all come from one of the two, in their own order).
    std::vector<detail::ContourCell> merged;
    merged.reserve(before.contour->size() + 64);
    for (const detail::ContourCell& c : *before.contour)
        if (!(c.i >= cells.i0 && c.i < cells.i1 && c.j >= cells.j0 && c.j < cells.j1)) merged.push_back(c);
    const std::vector<detail::ContourCell> fresh = detail::contour_cells(heights->above, cells, threads);
    merged.insert(merged.end(), fresh.begin(), fresh.end());
    std::stable_sort(merged.begin(), merged.end(), [](const detail::ContourCell& a, const detail::ContourCell& b) {
        return a.j < b.j || (a.j == b.j && a.i < b.i);
    });
    field.timings.contour = clock.lap();
    if (auto st = set_shoreline(field, std::move(merged), threads); !st) return st.error();
    field.timings.simplify = clock.lap();
    const auto distance = detail::ShoreDistance::build(field.shorelines);
    field.segment_count = distance->segment_count();
    if (field.segment_count == 0) return std::optional<ShoreField>{};  // all water or all land now
    field.timings.tree = clock.lap();

    // The segments of one shoreline and not the other, and what they span.
    const auto old_segments = sorted_segments(before.shorelines), new_segments = sorted_segments(field.shorelines);
    std::vector<std::array<double, 4>> moved;
    std::set_symmetric_difference(old_segments.begin(), old_segments.end(), new_segments.begin(), new_segments.end(),
                                  std::back_inserter(moved));
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const auto& s : moved) {
        lo = glm::min(lo, glm::min(glm::dvec2(s[0], s[1]), glm::dvec2(s[2], s[3])));
        hi = glm::max(hi, glm::max(glm::dvec2(s[0], s[1]), glm::dvec2(s[2], s[3])));
    }
    // The blocks filled again: those holding a changed texel (its depth, so its sign, may
    // have moved), and those with a texel whose distance reaches the moved segments (a
    // texel nearer every moved segment than its own nearest keeps that one, and its value).
    const int per_side = (n + detail::kDistanceRootBlock - 1) / detail::kDistanceRootBlock;
    std::vector<char> refill(static_cast<std::size_t>(per_side) * static_cast<std::size_t>(per_side), 0);
    const std::vector<float>& old_distance = before.signed_distance.values();
    detail::parallel_for_each(static_cast<std::size_t>(per_side), threads, [&](std::size_t rj) {
        const int j0 = static_cast<int>(rj) * detail::kDistanceRootBlock,
                  j1 = std::min(n, j0 + detail::kDistanceRootBlock);
        for (int ri = 0; ri < per_side; ++ri) {
            const int i0 = ri * detail::kDistanceRootBlock, i1 = std::min(n, i0 + detail::kDistanceRootBlock);
            char& r = refill[rj * static_cast<std::size_t>(per_side) + static_cast<std::size_t>(ri)];
            if (i0 <= t.i1 && t.i0 < i1 && j0 <= t.j1 && t.j0 < j1) {
                r = 1;
                continue;
            }
            if (moved.empty()) continue;
            float farthest = 0.0f;
            for (int j = j0; j < j1; ++j)
                for (int i = i0; i < i1; ++i) farthest = std::max(farthest, std::abs(old_distance[field.index(i, j)]));
            const glm::dvec2 a = field.texel_center(i0, j0), b = field.texel_center(i1 - 1, j1 - 1);
            const glm::dvec2 gap = glm::max(glm::dvec2(0.0), glm::max(lo - b, a - hi));
            r = static_cast<double>(farthest) * (1.0 + 1e-6) + 1e-6 * field.texel >= glm::length(gap) ? 1 : 0;
        }
    });
    std::vector<std::size_t> roots;
    for (std::size_t k = 0; k < refill.size(); ++k)
        if (refill[k]) roots.push_back(k);
    detail::fill_distance_roots(*distance, field, roots, threads);
    field.timings.distance = clock.lap();
    return std::optional<ShoreField>{std::move(field)};
}

namespace reference {

double brute_force_shore_distance(const ShoreField& field, glm::dvec2 p) {
    double best = 1e300;
    for (const ShoreLine& line : field.shorelines) {
        const std::size_t n = line.points.size();
        const std::size_t count = line.closed ? n : n - 1;
        for (std::size_t k = 0; k < count; ++k) {
            const glm::dvec2 a = line.points[k], b = line.points[(k + 1) % n];
            const glm::dvec2 ab = b - a, ap = p - a;
            const double len2 = ab.x * ab.x + ab.y * ab.y;
            const double t = len2 > 0.0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / len2, 0.0, 1.0) : 0.0;
            const glm::dvec2 d = ap - t * ab;
            best = std::min(best, d.x * d.x + d.y * d.y);
        }
    }
    return std::sqrt(best);
}

}  // namespace reference

}  // namespace tidewater
