#include "water/shore_order.hpp"

#include <algorithm>
#include <cmath>

#include "tidewater/detail/shore_waves.hpp"

namespace tidewater::detail {

namespace {

/// Texels per tile side: 4, or more on fine grids so that there are at most 256 tiles
/// per side (the counting sort's buckets stay small).
int tile_texels(int resolution) {
    return std::max(4, (resolution + 255) / 256);
}

std::size_t tile_of(double coordinate, double corner, double texel, int tile, int tiles) {
    const double t = (coordinate - corner) / (texel * tile);
    // NaN fails both comparisons and lands on tile 0.
    if (!(t >= 0.0)) return 0;
    if (t >= static_cast<double>(tiles)) return static_cast<std::size_t>(tiles - 1);
    return static_cast<std::size_t>(t);
}

}  // namespace

std::vector<std::uint32_t> shore_tile_order(const ShoreWaves& shore, std::span<const glm::dvec2> points) {
    const int tile = tile_texels(shore.resolution());
    const int tiles = (shore.resolution() + tile - 1) / tile;
    const std::size_t side = static_cast<std::size_t>(tiles);
    std::vector<std::uint32_t> key(points.size());
    std::vector<std::uint32_t> start(side * side + 1, 0);
    for (std::size_t k = 0; k < points.size(); ++k) {
        const std::size_t i = tile_of(points[k].x, shore.corner().x, shore.texel(), tile, tiles);
        const std::size_t j = tile_of(points[k].y, shore.corner().y, shore.texel(), tile, tiles);
        key[k] = static_cast<std::uint32_t>(j * side + i);
        ++start[key[k] + 1];
    }
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    std::vector<std::uint32_t> order(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) order[start[key[k]]++] = static_cast<std::uint32_t>(k);
    return order;
}

}  // namespace tidewater::detail
