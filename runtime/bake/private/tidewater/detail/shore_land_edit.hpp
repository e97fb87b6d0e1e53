// A terrain edit on dry land, re-baked where it is (private to Tidewater::bake). When an
// edit changes the ground's height only where it is dry before and after, with no water
// within a texel, the waves are marched over the same water and the shoreline has the
// same contour: the distance field and the shore model keep every value but the ground's
// height under the edit, bit for bit what a full bake gives. An editor's strokes on the
// hills re-bake in the time it takes to copy the fields, not to march every wave.
#pragma once

#include <memory>
#include <optional>

#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::detail {

struct LandEdit {
    std::shared_ptr<const ShoreField> shoreline;
    std::shared_ptr<const ShoreWaves> model;
};

/// `shoreline` and `model` (non-null, baked over `before` at `water_level`) for `after`,
/// when the two terrains' heights differ (`change`: heightmap_change of the two: a
/// heightmap's pixels, a river's channel) only where the ground stays dry on every grid, a
/// texel or more from water. Otherwise nullopt: the caller bakes in full.
std::optional<LandEdit> rebake_land_edit(const HeightmapChange& change, const Terrain& before, const Terrain& after,
                                         double water_level, const std::shared_ptr<const ShoreField>& shoreline,
                                         const std::shared_ptr<const ShoreWaves>& model);

}  // namespace tidewater::detail
