// What a river evaluation needs from the scene (private); BodyFinder says which
// evaluation answers a point.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>

#include "kernel/kernel_waves.hpp"
#include "tidewater/detail/body_finder.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater::detail {

/// What a river evaluation (key.kind == river) needs at clock time `time`: the river's
/// waves prepared in its channel frame and, for a plume or mouth, the still water's.
/// The input points into `river_waves` and `still_waves`, which must outlive it.
template <typename Scalar>
RiverInput<Scalar> prepare_river_input(const Scene& scene, const WaterBodiesBake& bodies, const EvaluationKey& key,
                                       double time, PreparedWaves<Scalar>& river_waves,
                                       PreparedWaves<Scalar>& still_waves);

}  // namespace tidewater::detail
