// Where an edited heightmap differs from the one it was edited from (private): the bake
// re-bakes its shore only there (shore_land_edit.hpp) and the renderer uploads only
// those texels of its height texture. Threading: pure functions.
#pragma once

#include <glm/vec2.hpp>
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

/// World xz from lo to hi, m (either may be infinite).
struct WorldRect {
    glm::dvec2 lo{0.0}, hi{0.0};
};

/// Where an edited terrain's heights may differ from the one it was edited from: nullopt
/// when they are not the same heightmap (anything may have changed); an empty optional
/// inside when no pixel changed; else the world rect the changed pixels reach.
using HeightmapChange = std::optional<std::optional<WorldRect>>;

/// Where heights over `map` change when the pixels in `pixels` do: their bilinear support,
/// reaching to infinity beyond an edge whose pixels changed (the edge value carries on
/// and fades to the seabed there).
WorldRect pixels_reach(const HeightmapTerrain& map, const PixelRect& pixels);

}  // namespace tidewater::detail
