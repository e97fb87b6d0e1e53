// Where an edited heightmap differs from the one it was edited from (private): the bake
// re-bakes its shore only there (shore_land_edit.hpp) and the renderer uploads only
// those texels of its height texture. Threading: pure functions.
#pragma once

#include <optional>

#include "tidewater/terrain.hpp"

namespace tidewater::detail {

/// The pixels from (i0, j0) to (i1, j1), inclusive.
struct PixelRect {
    int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
};

/// The pixels of `after`'s heightmap that differ from `before`'s when the two are the
/// same heightmap (size, centre, height range, pixel count and cut objects), perhaps in
/// another image: an empty optional inside when no pixel differs. nullopt when they are
/// not the same heightmap (or not heightmaps): anything may have changed.
std::optional<std::optional<PixelRect>> changed_pixels(const Terrain& before, const Terrain& after);

}  // namespace tidewater::detail
