// The Eulerian solve (private): which rest position x0 has its particle at the query
// point p now? One Newton solver for every number type and every kind of water; its
// GLSL twin is solve_rest_offset in shaders/water_point.glsl.
//
// With e = x0 - p it solves F(e) = e + d(p + e) = 0. J = I - M (M = sum Q A k D D^T sin)
// is symmetric and positive definite while the surface does not fold.
// - A point stops at the first evaluation whose residual is under the tolerance, so its
//   answer does not depend on its batch neighbours or thread.
// - The sums give M for waves that are constant across a step. Near a shore a wave's
//   amplitude, direction and phase gradient change within a wavelength, and that M alone
//   slows Newton to linear convergence. A secant correction C (SecantCorrection) learns
//   what M misses from each step's change of F, so J = I - M + C. Over the open sea M is
//   exact and C is left out (sums_jacobian_exact).
// - Near the waterline the waves change within a texel and a step can overshoot: where
//   |F| grew, the next try is halfway back to the last better point.
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

/// The correction C to the sums' Jacobian that the steps teach (Dennis and Walker's
/// structured secant update, in the rank-one form of Broyden's "good" method): after a
/// step de that changed F by dF, C takes the smallest change that makes
/// (J_mean + C) de = dF, J_mean being the sums' Jacobian averaged over the step's two ends
/// (so that C learns only what the sums lack, not their own change along the step). Steps
/// under a tenth of the tolerance teach nothing: their dF is mostly rounding.
template <typename T>
struct SecantCorrection {
    using Ops = NumberOps<T>;
    T xx = T(0.0), xz = T(0.0), zx = T(0.0), zz = T(0.0);  ///< C, row-major
    T ex = T(0.0), ez = T(0.0), fx = T(0.0), fz = T(0.0);  ///< the last evaluation's e and F
    T jxx = T(0.0), jxz = T(0.0), jzz = T(0.0);            ///< and its sums' Jacobian

    /// Learns from the step from the last evaluation to (ex1, ez1), where F = (fx1, fz1)
    /// and the sums' Jacobian is f's; then remembers this evaluation.
    void learn(const SurfaceFrame<T>& f, const T& ex1, const T& ez1, const T& fx1, const T& fz1, const T& min_step2) {
        const T half(0.5), one(1.0), zero(0.0);
        const T dex = ex1 - ex, dez = ez1 - ez;
        const T de2 = dex * dex + dez * dez;
        const auto teaches = de2 > min_step2;
        const T inv = Ops::select(teaches, one / Ops::select(teaches, de2, one), zero);
        const T mxx = half * (f.jxx + jxx), mxz = half * (f.jxz + jxz), mzz = half * (f.jzz + jzz);
        const T rx = ((fx1 - fx) - Ops::mul_add(mxx + xx, dex, (mxz + xz) * dez)) * inv;
        const T rz = ((fz1 - fz) - Ops::mul_add(mxz + zx, dex, (mzz + zz) * dez)) * inv;
        xx = Ops::mul_add(rx, dex, xx);
        xz = Ops::mul_add(rx, dez, xz);
        zx = Ops::mul_add(rz, dex, zx);
        zz = Ops::mul_add(rz, dez, zz);
        remember(f, ex1, ez1, fx1, fz1);
    }
    void remember(const SurfaceFrame<T>& f, const T& ex1, const T& ez1, const T& fx1, const T& fz1) {
        ex = ex1;
        ez = ez1;
        fx = fx1;
        fz = fz1;
        jxx = f.jxx;
        jxz = f.jxz;
        jzz = f.jzz;
    }
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

/// Whether W's sums give the exact Jacobian of its map (W::kSumsJacobianExact, as over the
/// open sea, whose waves are the same everywhere): its steps need no secant correction.
template <typename W>
constexpr bool sums_jacobian_exact() {
    if constexpr (requires { W::kSumsJacobianExact; }) {
        return W::kSumsJacobianExact;
    } else {
        return false;
    }
}

/// Solves for the rest offset of each lane of `water`, the water at rest offsets from
/// the query points.
template <bool kVelocity, typename T, EulerianWater<T> Water>
NewtonResult<T> solve_rest_offset(Water& water, double tolerance, double radius) {
    using Ops = NumberOps<T>;
    using Mask = typename Ops::Mask;
    const T zero(0.0), one(1.0), half(0.5);
    const T tol2 = constant<T>(tolerance * tolerance), radius2 = constant<T>(radius * radius);
    const T min_step2 = constant<T>(0.01 * tolerance * tolerance);
    T ex(0.0), ez(0.0), last_ex(0.0), last_ez(0.0), last_f2 = constant<T>(3.0e38);
    SecantCorrection<T> c;
    Mask active = zero == zero;
    NewtonResult<T> r;
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        const SurfaceSums<T> s = water.template evaluate<kVelocity>(ex, ez);
        const SurfaceFrame<T> f = surface_frame(s);
        r.iterations = Ops::select(active, r.iterations + one, r.iterations);
        const T fx = ex + s.dx, fz = ez + s.dz;
        T step_x, step_z;
        if constexpr (sums_jacobian_exact<Water>()) {
            const T inv_det = one / f.det;
            step_x = (f.jxz * fz - f.jzz * fx) * inv_det;
            step_z = (f.jxz * fx - f.jxx * fz) * inv_det;
        } else {
            if (it == 0) {
                c.remember(f, ex, ez, fx, fz);
            } else {
                c.learn(f, ex, ez, fx, fz, min_step2);
            }
            const T jxx = f.jxx + c.xx, jxz = f.jxz + c.xz, jzx = f.jxz + c.zx, jzz = f.jzz + c.zz;
            const T inv_det = one / (jxx * jzz - jxz * jzx);
            step_x = (jxz * fz - jzz * fx) * inv_det;
            step_z = (jzx * fx - jxx * fz) * inv_det;
        }
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
