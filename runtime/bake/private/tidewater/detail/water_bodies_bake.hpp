// The lakes' and rivers' bake (internal to Tidewater::bake): lake extents, a river's
// falling surface, carved bed and stream-function current (water_bodies.hpp holds what
// it makes). Threading: reentrant; cancellable through BodiesBakeOptions::cancel.
#pragma once

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// Finds the lakes' extents and bakes the rivers of `scene` over its terrain's shape (any
/// cuts it carries are replaced by the rivers'). Errors name the scene and the body's
/// JSON path.
Result<WaterBodiesBake> bake_water_bodies(const Scene& scene, const BodiesBakeOptions& options);

}  // namespace tidewater::detail
