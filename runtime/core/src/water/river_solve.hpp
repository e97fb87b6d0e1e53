// Solving points in a river or its plume (private), once over the number type: the SIMD
// kernels and the double reference instantiate it. A river point sees the river's
// surface and waves; a plume point sees the still water it runs into (a lake's or the
// ocean's waves, with their shore model) with the river's waves fading out. Both carry
// the river's current at the point, added to the particles' orbital velocity.
#pragma once

#include <algorithm>
#include <cstddef>
#include <glm/vec2.hpp>

#include "kernel/kernel_waves.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/newton.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/query.hpp"
#include "water/open_sea_water.hpp"
#include "water/point_lanes.hpp"
#include "water/prepared_waves.hpp"
#include "water/river_water.hpp"
#include "water/shore_water.hpp"

namespace tidewater::detail {

namespace river_solve_impl {

/// Writes the first `used` lanes of a solve of `water`: the surface, with the river's
/// current at each point added to the orbital velocity, and the foam its particles remember.
template <typename T, typename Water>
void write_points(const NewtonResult<T>& r, Water& water, double level, double whitecap_jacobian, const RiverSample* at,
                  const double* breaking, const double* shore_distance, std::size_t used, SurfacePoint* out) {
    const PointLanes<T> lanes(r);
    const LagLanes<T> lags(water.lagged(r.ex, r.ez));
    for (std::size_t l = 0; l < used; ++l) {
        SurfacePoint& o = out[l];
        lanes.fill(l, level, o);
        o.velocity += glm::dvec3(at[l].flow_x, 0.0, at[l].flow_z);
        o.depth = at[l].depth;
        o.shore_distance = shore_distance ? shore_far_to_infinite(shore_distance[l]) : kDeepWater;
        o.wet = surface_wet(o.height, at[l].surface, at[l].depth);
        o.foam = surface_foam(breaking ? breaking[l] : 0.0, lanes.jacobian[l], lags.lane(l), whitecap_jacobian);
    }
}

}  // namespace river_solve_impl

/// Solves `used` points (1 to the lane count) of one river or one plume.
template <typename T>
void solve_river_batch(const RiverInput<typename NumberOps<T>::Scalar>& in, const glm::dvec2* points, std::size_t used,
                       SurfacePoint* out) {
    using Ops = NumberOps<T>;
    using Scalar = typename Ops::Scalar;
    constexpr std::size_t kLanes = Ops::kLanes;
    alignas(64) double px[kLanes], pz[kLanes];
    alignas(64) Scalar river_base[kMaxWaves * kLanes], still_base[kMaxWaves * kLanes];
    RiverSample at[kLanes];
    const bool plume = in.still_waves != nullptr;
    for (std::size_t l = 0; l < kLanes; ++l) {
        // Spare lanes repeat the last point; lanes never interact.
        const glm::dvec2 p = points[l < used ? l : used - 1];
        px[l] = p.x;
        pz[l] = p.y;
        at[l] = sample_river(*in.river, p);
        // The river's phases run in channel coordinates.
        base_phases(*in.river_waves, at[l].s, at[l].n, river_base + l, kLanes);
        if (plume) base_phases(*in.still_waves, p.x, p.y, still_base + l, kLanes);
    }
    RiverWater<T> river(*in.river_waves, *in.river, px, pz, river_base);
    if (!plume) {
        const auto r = solve_rest_offset<true, T>(river, in.river_waves->tolerance, in.river_waves->radius);
        river_solve_impl::write_points(r, river, in.river_waves->level, in.river_waves->whitecap_jacobian, at, nullptr,
                                       nullptr, used, out);
        return;
    }
    const double max_offset = in.river_waves->max_offset + in.still_waves->max_offset;
    const double tolerance = newton_tolerance(max_offset), radius = newton_radius(max_offset);
    if (in.still_shore != nullptr) {
        ShoreWater<T> still(*in.still_waves, *in.still_shore, px, pz, still_base);
        PlumeWater<T, ShoreWater<T>> water(river, still);
        const auto r = solve_rest_offset<true, T>(water, tolerance, radius);
        double breaking[kLanes], distance[kLanes];
        store_lanes(still.breaking, breaking);
        store_lanes(still.shore_distance_at_point, distance);
        river_solve_impl::write_points(r, water, in.still_waves->level, in.still_waves->whitecap_jacobian, at, breaking,
                                       distance, used, out);
    } else {
        OpenSeaWater<T> still(*in.still_waves, still_base);
        PlumeWater<T, OpenSeaWater<T>> water(river, still);
        const auto r = solve_rest_offset<true, T>(water, tolerance, radius);
        river_solve_impl::write_points(r, water, in.still_waves->level, in.still_waves->whitecap_jacobian, at, nullptr,
                                       nullptr, used, out);
    }
}

}  // namespace tidewater::detail
