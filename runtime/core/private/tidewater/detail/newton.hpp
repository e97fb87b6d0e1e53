// The Eulerian solve (private): which rest position x0 has its particle at the query
// point p now? One Newton solver for every number type and every kind of water; its
// GLSL twin is solve_rest_offset in shaders/water_point.glsl.
//
// With e = x0 - p it solves F(e) = e + d(p + e) = 0. J = I - M (M = sum Q A k D D^T sin)
// is symmetric and positive definite while the surface does not fold.
// - A point stops at the first evaluation whose residual is under the tolerance, so its
//   answer does not depend on its batch neighbours or thread.
// - Newton treats the local waves as constant across a step. Near the waterline they
//   change within a texel and a step can overshoot: where |F| grew, the next try is
//   halfway back to the last better point.
// - The rest position is within sum(Q A) of the point: a wild step is pulled back inside.
// - Results carry the last (tiny) step to first order: height + slope . step.
#pragma once

#include <algorithm>
#include <concepts>

#include "host_device.h"
#include "tidewater/detail/water_point.hpp"

namespace tidewater::detail {

inline constexpr int kMaxNewtonIterations = gpu::kMaxNewtonIterations;

/// The residual accepted as converged for waves whose sum(Q A) is `max_offset`, m.
inline double newton_tolerance(double max_offset) {
    return std::max(static_cast<double>(gpu::kNewtonToleranceFloor),
                    static_cast<double>(gpu::kNewtonToleranceScale) * max_offset);
}
/// The radius the rest offset is kept within: sum(Q A) with a little slack, m.
inline double newton_radius(double max_offset) {
    return max_offset * static_cast<double>(gpu::kNewtonRadiusSlack) + static_cast<double>(gpu::kNewtonRadiusFloor);
}

template <typename T>
struct NewtonResult {
    SurfaceSums<T> sums;                 ///< at the point's last evaluation
    T step_x = T(0.0), step_z = T(0.0);  ///< the Newton step from that evaluation
    T ex = T(0.0), ez = T(0.0);          ///< the rest offset of that evaluation
    T iterations = T(0.0);               ///< evaluations used
    T converged = T(0.0);                ///< 1 where the residual met the tolerance
};

template <typename T>
SurfaceSums<T> select_sums(typename NumberOps<T>::Mask m, const SurfaceSums<T>& a, const SurfaceSums<T>& b) {
    using Ops = NumberOps<T>;
    SurfaceSums<T> s;
    s.dx = Ops::select(m, a.dx, b.dx);
    s.dz = Ops::select(m, a.dz, b.dz);
    s.eta = Ops::select(m, a.eta, b.eta);
    s.mxx = Ops::select(m, a.mxx, b.mxx);
    s.mxz = Ops::select(m, a.mxz, b.mxz);
    s.mzz = Ops::select(m, a.mzz, b.mzz);
    s.sx = Ops::select(m, a.sx, b.sx);
    s.sz = Ops::select(m, a.sz, b.sz);
    s.vx = Ops::select(m, a.vx, b.vx);
    s.vy = Ops::select(m, a.vy, b.vy);
    s.vz = Ops::select(m, a.vz, b.vz);
    return s;
}

/// What the solver needs of a water (open sea, shore, river, wakes, a Jet model): its
/// sums at rest offsets (ex, ez) from the query points, with or without the particle
/// velocity, and record(mask), which keeps whatever else it sampled for the lanes in
/// `mask` (those that finished at this evaluation).
template <typename W, typename T>
concept EulerianWater = requires(W& water, const T& ex, const T& ez, const typename NumberOps<T>::Mask& finished) {
    { water.template evaluate<false>(ex, ez) } -> std::same_as<SurfaceSums<T>>;
    { water.template evaluate<true>(ex, ez) } -> std::same_as<SurfaceSums<T>>;
    water.record(finished);
};

/// Solves for the rest offset of each lane of `water`, the water at rest offsets from
/// the query points.
template <bool kVelocity, typename T, EulerianWater<T> Water>
NewtonResult<T> solve_rest_offset(Water& water, double tolerance, double radius) {
    using Ops = NumberOps<T>;
    using Mask = typename Ops::Mask;
    const T zero(0.0), one(1.0), half(0.5);
    const T tol2 = constant<T>(tolerance * tolerance), radius2 = constant<T>(radius * radius);
    T ex(0.0), ez(0.0), last_ex(0.0), last_ez(0.0), last_f2 = constant<T>(3.0e38);
    Mask active = zero == zero;
    NewtonResult<T> r;
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        const SurfaceSums<T> s = water.template evaluate<kVelocity>(ex, ez);
        const SurfaceFrame<T> f = surface_frame(s);
        r.iterations = Ops::select(active, r.iterations + one, r.iterations);
        const T fx = ex + s.dx, fz = ez + s.dz;
        const T inv_det = one / f.det;
        const T step_x = (f.jxz * fz - f.jzz * fx) * inv_det;
        const T step_z = (f.jxz * fx - f.jxx * fz) * inv_det;
        const T f2 = fx * fx + fz * fz;
        const Mask converged = f2 <= tol2;
        const Mask finish = active && converged;
        const Mask record = it + 1 == kMaxNewtonIterations ? active : finish;
        if (Ops::any(record)) {
            r.sums = select_sums<T>(record, s, r.sums);
            r.step_x = Ops::select(record, step_x, r.step_x);
            r.step_z = Ops::select(record, step_z, r.step_z);
            r.ex = Ops::select(record, ex, r.ex);
            r.ez = Ops::select(record, ez, r.ez);
            r.converged = Ops::select(finish, one, r.converged);
            water.record(record);
        }
        const Mask moving = active && !converged;
        const Mask grew = f2 > last_f2;
        const Mask advance = moving && !grew;
        last_ex = Ops::select(advance, ex, last_ex);
        last_ez = Ops::select(advance, ez, last_ez);
        last_f2 = Ops::select(advance, f2, last_f2);
        T nx = Ops::select(grew, half * (ex + last_ex), ex + step_x);
        T nz = Ops::select(grew, half * (ez + last_ez), ez + step_z);
        const T r2 = nx * nx + nz * nz;
        const T shrink = Ops::select(r2 > radius2, Ops::sqrt(radius2 / Ops::select(r2 > zero, r2, one)), one);
        nx = nx * shrink;
        nz = nz * shrink;
        ex = Ops::select(moving, nx, ex);
        ez = Ops::select(moving, nz, ez);
        active = moving;
        if (!Ops::any(active)) break;
    }
    return r;
}

}  // namespace tidewater::detail

namespace tidewater::detail {

/// A solved point's surface: the height (eta, without the level) and rest offset carried
/// along the last step, the unit normal and the Jacobian determinant.
template <typename T>
struct PointState {
    T eta, nx, ny, nz, jacobian, disp_x, disp_z;
};

template <typename T>
PointState<T> point_state(const NewtonResult<T>& r) {
    using Ops = NumberOps<T>;
    const SurfaceFrame<T> f = surface_frame(r.sums);
    PointState<T> p;
    p.eta = Ops::mul_add(r.sums.sx, r.step_x, Ops::mul_add(r.sums.sz, r.step_z, r.sums.eta));
    const T inv_len = T(1.0) / Ops::sqrt(f.nx * f.nx + f.ny * f.ny + f.nz * f.nz);
    p.nx = f.nx * inv_len;
    p.ny = f.ny * inv_len;
    p.nz = f.nz * inv_len;
    p.jacobian = f.det;
    // The particle at the point rests at p + e + step: its displacement is -(e + step).
    p.disp_x = T(0.0) - (r.ex + r.step_x);
    p.disp_z = T(0.0) - (r.ez + r.step_z);
    return p;
}

}  // namespace tidewater::detail
