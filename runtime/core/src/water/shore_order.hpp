// Query order for water near a shore (private). Each point reads the shore fields of
// its cell (about 100 floats per texel with 24 waves); in the caller's order,
// scattered points miss the cache on every batch. Solving them tile by tile keeps a
// tile's texels in cache while its points are solved. Lanes never interact, so the
// order changes no result.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <span>
#include <vector>

namespace tidewater {
class ShoreWaves;
}

namespace tidewater::detail {

/// Below this many points a call keeps its own order: sorting would cost more than
/// the misses it saves.
inline constexpr std::size_t kShoreOrderMinPoints = 4096;

/// A permutation of the points' indices grouped by shore tile (a few texels square,
/// at most 65536 tiles), stable within a tile. Points off the grid (or NaN) go to the
/// nearest edge tile, like the sampling does.
std::vector<std::uint32_t> shore_tile_order(const ShoreWaves& shore, std::span<const glm::dvec2> points);

}  // namespace tidewater::detail
