// The shoreline bake in tiles (tiled_shore.hpp): the same steps as bake_shore
// (shore_bake.cpp), each over one tile's window of the whole grid.
#include "tidewater/detail/tiled_shore.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "contour.hpp"
#include "distance_field.hpp"
#include "shore_geometry.hpp"
#include "shoreline_steps.hpp"

namespace tidewater::tiled {

namespace {

/// Tile t's cells: those whose lower-left texel is in the tile (the grid's last row and
/// column of texels start no cell).
detail::CellWindow tile_cells(const ShoreTiling& tiling, int t) {
    const int i0 = tiling.first_i(t), j0 = tiling.first_j(t), n = tiling.resolution;
    return {i0, j0, std::min(i0 + tiling.block(), n - 1), std::min(j0 + tiling.block(), n - 1)};
}

Error bad_tile(int tile, const std::string& why) {
    return Error{ErrorCode::invalid_argument, fmt::format("tile {}: {}", tile, why)};
}

}  // namespace

Result<ShoreTiling> ShoreTiling::over(const Terrain& terrain, int resolution, int tiles) {
    if (tiles < 1 || resolution < 8 || resolution > 8192 || resolution % (kBlockMultiple * tiles) != 0)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("tiled bake: {} tiles a side over {} texels: the resolution (8 to 8192) must be a "
                                 "multiple of {} times the tiles a side",
                                 tiles, resolution, kBlockMultiple)};
    ShoreTiling t;
    t.resolution = resolution;
    t.tiles = tiles;
    // As bake_shore places its grid over the terrain's extent.
    const double half = terrain.extent_half_size();
    t.texel = 2.0 * half / resolution;
    t.corner = terrain.extent_center() - glm::dvec2(half);
    return t;
}

ShoreField ShoreTiling::grid() const {
    ShoreField g;
    g.corner = corner;
    g.texel = texel;
    g.resolution = resolution;
    return g;
}

Result<TileContour> extract_tile_contour(const Terrain& terrain, double water_level, const ShoreTiling& tiling,
                                         int tile, unsigned threads) {
    if (tile < 0 || tile >= tiling.count()) return bad_tile(tile, fmt::format("not one of {}", tiling.count()));
    const detail::CellWindow cells = tile_cells(tiling, tile);
    const detail::TexelRect texels{cells.i0, cells.j0, cells.i1 - cells.i0 + 1, cells.j1 - cells.j0 + 1};
    auto heights = detail::window_heights(terrain, water_level, tiling.grid(), texels, threads);
    if (!heights) return heights.error();
    TileContour out;
    out.tile = tile;
    out.mixed_cells = detail::mixed_cells(heights->depth, cells, threads);
    out.cells = detail::contour_cells(heights->above, cells, threads);
    return out;
}

Status check_tile_contour(const ShoreTiling& tiling, const TileContour& contour) {
    if (contour.tile < 0 || contour.tile >= tiling.count())
        return bad_tile(contour.tile, fmt::format("not one of {}", tiling.count()));
    const detail::CellWindow w = tile_cells(tiling, contour.tile);
    const std::size_t cells = static_cast<std::size_t>(w.i1 - w.i0) * static_cast<std::size_t>(w.j1 - w.j0);
    // A cell holds at most two pieces (a saddle); a crossing cell is a mixed one.
    if (contour.mixed_cells > cells || contour.cells.size() > 2 * contour.mixed_cells)
        return bad_tile(contour.tile, fmt::format("{} pieces in {} mixed cells of {}", contour.cells.size(),
                                                  contour.mixed_cells, cells));
    for (std::size_t k = 0; k < contour.cells.size(); ++k) {
        const detail::ContourCell& c = contour.cells[k];
        const bool inside = c.i >= w.i0 && c.i < w.i1 && c.j >= w.j0 && c.j < w.j1;
        const bool edges = c.from_edge >= 0 && c.from_edge < 4 && c.to_edge >= 0 && c.to_edge < 4;
        auto in_cell = [&](glm::dvec2 p) {
            return std::isfinite(p.x) && std::isfinite(p.y) && p.x >= c.i && p.x <= c.i + 1 && p.y >= c.j &&
                   p.y <= c.j + 1;
        };
        const bool sorted = k == 0 || std::pair(contour.cells[k - 1].j, contour.cells[k - 1].i) <= std::pair(c.j, c.i);
        if (!inside || !edges || !in_cell(c.from) || !in_cell(c.to) || !sorted)
            return bad_tile(contour.tile,
                            fmt::format("piece {} (cell {}, {}) is not one of its contour's", k, c.i, c.j));
    }
    return {};
}

Result<ShoreField> stitch_shoreline(const ShoreTiling& tiling, std::vector<TileContour> contours,
                                    double simplify_tolerance, unsigned threads) {
    if (!std::isfinite(simplify_tolerance) || simplify_tolerance < 0.0)
        return Error{ErrorCode::invalid_argument, "bake: simplify_tolerance must be finite and >= 0"};
    std::vector<char> seen(static_cast<std::size_t>(tiling.count()), 0);
    std::size_t mixed = 0, pieces = 0;
    for (const TileContour& c : contours) {
        if (auto st = check_tile_contour(tiling, c); !st) return st.error();
        if (seen[static_cast<std::size_t>(c.tile)]++) return bad_tile(c.tile, "given twice");
        mixed += c.mixed_cells;
        pieces += c.cells.size();
    }
    for (int t = 0; t < tiling.count(); ++t)
        if (!seen[static_cast<std::size_t>(t)]) return bad_tile(t, "its contour is missing");
    const std::size_t n = static_cast<std::size_t>(tiling.resolution);
    if (auto st = detail::check_mixed_cells(mixed, n * n); !st) return st.error();
    // Every cell in the whole grid's order, (j, i): each tile's are sorted, and a cell is one tile's.
    std::vector<detail::ContourCell> cells;
    cells.reserve(pieces);
    for (TileContour& c : contours) cells.insert(cells.end(), c.cells.begin(), c.cells.end());
    contours.clear();
    std::stable_sort(cells.begin(), cells.end(), [](const detail::ContourCell& a, const detail::ContourCell& b) {
        return a.j != b.j ? a.j < b.j : a.i < b.i;
    });
    ShoreField field = tiling.grid();
    field.simplify_tolerance = simplify_tolerance > 0.0 ? simplify_tolerance : 0.5 * field.texel;
    auto shore = detail::shoreline_from_cells(std::move(cells), tiling.resolution, field.corner, field.texel,
                                              field.simplify_tolerance, threads);
    if (!shore) return shore.error();
    field.polygons = shore->polygons;
    field.holes = shore->holes;
    field.shorelines = std::move(shore->lines);
    field.segment_count = detail::ShoreDistance::build(field.shorelines)->segment_count();
    return field;
}

Result<TileDistances> bake_tile_distances(const Terrain& terrain, double water_level, const ShoreTiling& tiling,
                                          int tile, const ShoreField& stitched, unsigned threads) {
    if (tile < 0 || tile >= tiling.count()) return bad_tile(tile, fmt::format("not one of {}", tiling.count()));
    const int b = tiling.block();
    const detail::TexelRect rect{tiling.first_i(tile), tiling.first_j(tile), b, b};
    auto heights = detail::window_heights(terrain, water_level, tiling.grid(), rect, threads);
    if (!heights) return heights.error();
    ShoreField field = tiling.grid();
    field.depth.write() = std::move(heights->depth);
    const std::size_t count = static_cast<std::size_t>(b) * static_cast<std::size_t>(b);
    const auto distance = detail::ShoreDistance::build(stitched.shorelines);
    if (distance->segment_count() == 0) {
        // No shoreline: all water or all land, by the whole grid's first texel (as bake_shore).
        auto first = detail::window_heights(terrain, water_level, tiling.grid(), {0, 0, 1, 1}, threads);
        if (!first) return first.error();
        const double half = 0.5 * tiling.texel * tiling.resolution;
        const float far = static_cast<float>((first->above[0] < 0.0 ? 1.0 : -1.0) * 2.0 * std::sqrt(2.0) * half);
        field.signed_distance.write().assign(count, far);
        field.gradient.write().assign(count, SharedDirections::kNone);
    } else {
        field.signed_distance.write().assign(count, 0.0f);
        field.gradient.write().assign(count, SharedDirections::kNone);
        detail::fill_distance_window(*distance, field, {rect.i0, rect.j0, b}, threads, {}, {});
    }
    TileDistances out;
    out.tile = tile;
    out.signed_distance = field.signed_distance.values();
    out.gradient_x.resize(count);
    out.gradient_z.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const glm::vec2 g = field.gradient[k];
        out.gradient_x[k] = g.x;
        out.gradient_z[k] = g.y;
    }
    out.depth = field.depth.values();
    return out;
}

Result<ShoreField> assemble_shore_field(const ShoreTiling& tiling, ShoreField stitched,
                                        const std::function<Result<TileDistances>(int tile)>& tile) {
    const std::size_t n = static_cast<std::size_t>(tiling.resolution), b = static_cast<std::size_t>(tiling.block());
    const ShoreField grid = tiling.grid();
    if (stitched.resolution != grid.resolution || stitched.texel != grid.texel || stitched.corner != grid.corner)
        return Error{ErrorCode::invalid_argument, "tiled bake: the shoreline was stitched for another grid"};
    std::vector<float>* grids[] = {&stitched.signed_distance.write(), &stitched.depth.write()};
    for (std::vector<float>* g : grids) g->assign(n * n, 0.0f);
    std::vector<std::uint16_t>& gradient = stitched.gradient.write();
    gradient.assign(n * n, SharedDirections::kNone);
    for (int t = 0; t < tiling.count(); ++t) {
        auto got = tile(t);
        if (!got) return got.error();
        if (got->tile != t) return bad_tile(t, fmt::format("got tile {} in its place", got->tile));
        const std::vector<float>* from[] = {&got->signed_distance, &got->depth, &got->gradient_x, &got->gradient_z};
        for (const std::vector<float>* f : from)
            if (f->size() != b * b) return bad_tile(t, fmt::format("{} values, not {}", f->size(), b * b));
        for (std::size_t row = 0; row < b; ++row) {
            const std::size_t at =
                (static_cast<std::size_t>(tiling.first_j(t)) + row) * n + static_cast<std::size_t>(tiling.first_i(t));
            for (int g = 0; g < 2; ++g) std::copy_n(from[g]->data() + row * b, b, grids[g]->data() + at);
            for (std::size_t i = 0; i < b; ++i)
                gradient[at + i] = SharedDirections::encode({static_cast<double>(got->gradient_x[row * b + i]),
                                                             static_cast<double>(got->gradient_z[row * b + i])});
        }
    }
    return stitched;
}

}  // namespace tidewater::tiled
