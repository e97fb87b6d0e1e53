// A solved batch's surface, lane by lane in double (private): what every result writer
// (open water, shores, rivers) copies into SurfacePoints.
#pragma once

#include <array>
#include <cstddef>

#include "tidewater/detail/newton.hpp"
#include "tidewater/query.hpp"

namespace tidewater::detail {

/// lanes[l] = lane l of b.
template <typename T, typename V>
void store_lanes(const T& b, V* lanes) {
    using Ops = NumberOps<T>;
    alignas(64) typename Ops::Scalar tmp[Ops::kLanes];
    Ops::store(b, tmp);
    for (std::size_t l = 0; l < Ops::kLanes; ++l) lanes[l] = static_cast<V>(tmp[l]);
}

template <typename T>
struct PointLanes {
    static constexpr std::size_t kLanes = NumberOps<T>::kLanes;
    double eta[kLanes], nx[kLanes], ny[kLanes], nz[kLanes], vx[kLanes], vy[kLanes], vz[kLanes];
    double jacobian[kLanes], dx[kLanes], dz[kLanes], iterations[kLanes], converged[kLanes];

    explicit PointLanes(const NewtonResult<T>& r) {
        const PointState<T> p = point_state(r);
        store_lanes(p.eta, eta);
        store_lanes(p.nx, nx);
        store_lanes(p.ny, ny);
        store_lanes(p.nz, nz);
        store_lanes(r.sums.vx, vx);
        store_lanes(r.sums.vy, vy);
        store_lanes(r.sums.vz, vz);
        store_lanes(p.jacobian, jacobian);
        store_lanes(p.disp_x, dx);
        store_lanes(p.disp_z, dz);
        store_lanes(r.iterations, iterations);
        store_lanes(r.converged, converged);
    }

    /// Lane l's height (level + eta), normal, displacement, orbital velocity, Jacobian and
    /// solve counts into `o`; the writer adds what its water knows (depth, shore, current).
    void fill(std::size_t l, double level, SurfacePoint& o) const {
        o.height = level + eta[l];
        o.normal = {nx[l], ny[l], nz[l]};
        o.displacement = {dx[l], dz[l]};
        o.velocity = {vx[l], vy[l], vz[l]};
        o.jacobian = jacobian[l];
        o.iterations = static_cast<int>(iterations[l]);
        o.converged = converged[l] != 0.0;
    }
};

/// The lagged Jacobians of a batch (LaggedCompression), lane by lane in double.
template <typename T>
struct LagLanes {
    static constexpr std::size_t kLanes = NumberOps<T>::kLanes;
    double det[kFoamLags][kLanes];

    explicit LagLanes(const LaggedCompression<T>& c) {
        const auto dets = lagged_jacobians(c);
        for (std::size_t g = 0; g < kFoamLags; ++g) store_lanes(dets[g], det[g]);
    }

    std::array<double, kFoamLags> lane(std::size_t l) const {
        std::array<double, kFoamLags> out;
        for (std::size_t g = 0; g < kFoamLags; ++g) out[g] = det[g][l];
        return out;
    }
};

}  // namespace tidewater::detail
