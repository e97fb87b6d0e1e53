// The SIMD Eulerian query kernel. Included once per instruction set by
// kernel_<isa>.cpp, each compiled with its own flags and defining
// TIDEWATER_KERNEL_NS, so no inline function is shared between ISAs.
//
// Lanes hold different query points. For each point p it solves
//   F(e) = e + d(p + e) = 0,   x0 = p + e   (e: rest position minus p)
// by Newton's method: J = I + dd/dx0 is symmetric 2x2 and positive definite
// while sum(Q k A) < 1. Phases k*D.p are formed and reduced in double, once;
// the iterations only add k*D.e (|e| <= sum(Q A)) in float, so float keeps
// micro-radian phase accuracy anywhere in the world. A lane stops (and its
// results freeze) at the first evaluation whose residual is under tolerance,
// so a point's answer does not depend on its batch neighbours or thread.
#pragma once

#ifndef TIDEWATER_KERNEL_NS
#error "define TIDEWATER_KERNEL_NS before including eulerian_kernel_impl.hpp"
#endif

#include <xsimd/xsimd.hpp>

#include <cstddef>

#include "kernel/kernel_waves.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::detail::TIDEWATER_KERNEL_NS {

using Arch = xsimd::default_arch;
using FloatBatch = xsimd::batch<float, Arch>;
using Mask = xsimd::batch_bool<float, Arch>;
inline constexpr std::size_t kLanes = FloatBatch::size;

/// Round-to-nearest without libm: adding 1.5 * 2^52 pushes the fraction out.
inline double round_to_integer(double v) {
    constexpr double kShift = 6755399441055744.0;
    return (v + kShift) - kShift;
}

/// Per-lane results of one batch, before conversion to the caller's layout.
struct BatchResult {
    alignas(64) float height[kLanes];
    alignas(64) float nx[kLanes];
    alignas(64) float ny[kLanes];
    alignas(64) float nz[kLanes];
    alignas(64) float vx[kLanes];
    alignas(64) float vy[kLanes];
    alignas(64) float vz[kLanes];
    alignas(64) float jacobian[kLanes];
    alignas(64) float disp_x[kLanes];
    alignas(64) float disp_z[kLanes];
    alignas(64) float iterations[kLanes];
    alignas(64) float converged[kLanes];
};

template <bool kFull>
void solve_batch(const KernelWaves& w, const double* px, const double* pz, BatchResult& out) {
    const std::size_t n = w.count;
    alignas(64) float base[kMaxWaves * kLanes];
    constexpr double kInvTwoPi = 1.0 / kTwoPi;
    for (std::size_t i = 0; i < n; ++i) {
        const double kx = w.kx[i], kz = w.kz[i], off = w.offset[i];
        for (std::size_t l = 0; l < kLanes; ++l) {
            double t = kx * px[l] + kz * pz[l] + off;
            t -= kTwoPi * round_to_integer(t * kInvTwoPi);
            base[i * kLanes + l] = static_cast<float>(t);
        }
    }

    const FloatBatch zero(0.0f), one(1.0f);
    const FloatBatch tol2(w.tolerance * w.tolerance);
    const FloatBatch radius2(w.max_offset * w.max_offset);
    FloatBatch ex(0.0f), ez(0.0f), iterations(0.0f);
    Mask active = zero == zero;
    FloatBatch r_h(0.0f), r_nx(0.0f), r_ny(1.0f), r_nz(0.0f), r_vx(0.0f), r_vy(0.0f), r_vz(0.0f),
        r_jac(1.0f), r_dx(0.0f), r_dz(0.0f), r_conv(0.0f);

    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        FloatBatch dx(0.0f), dz(0.0f), mxx(0.0f), mxz(0.0f), mzz(0.0f);
        FloatBatch eta(0.0f), sx(0.0f), sz(0.0f), vx(0.0f), vy(0.0f), vz(0.0f);
        for (std::size_t i = 0; i < n; ++i) {
            const FloatBatch theta = xsimd::fma(FloatBatch(w.kxf[i]), ex,
                                                xsimd::fma(FloatBatch(w.kzf[i]), ez,
                                                           FloatBatch::load_aligned(base + i * kLanes)));
            const auto sc = xsimd::sincos(theta);
            const FloatBatch& s = sc.first;
            const FloatBatch& c = sc.second;
            dx = xsimd::fma(FloatBatch(w.qa_x[i]), c, dx);
            dz = xsimd::fma(FloatBatch(w.qa_z[i]), c, dz);
            mxx = xsimd::fma(FloatBatch(w.qak_xx[i]), s, mxx);
            mxz = xsimd::fma(FloatBatch(w.qak_xz[i]), s, mxz);
            mzz = xsimd::fma(FloatBatch(w.qak_zz[i]), s, mzz);
            eta = xsimd::fma(FloatBatch(w.a[i]), s, eta);
            sx = xsimd::fma(FloatBatch(w.ak_x[i]), c, sx);
            sz = xsimd::fma(FloatBatch(w.ak_z[i]), c, sz);
            if constexpr (kFull) {
                vx = xsimd::fma(FloatBatch(w.qaw_x[i]), s, vx);
                vz = xsimd::fma(FloatBatch(w.qaw_z[i]), s, vz);
                vy = xsimd::fnma(FloatBatch(w.aw[i]), c, vy);
            }
        }
        iterations = xsimd::select(active, iterations + one, iterations);

        const FloatBatch fx = ex + dx, fz = ez + dz;
        const FloatBatch jxx = one - mxx, jxz = zero - mxz, jzz = one - mzz;
        const FloatBatch det = jxx * jzz - jxz * jxz;
        const FloatBatch inv_det = one / det;
        const FloatBatch step_x = (jxz * fz - jzz * fx) * inv_det;
        const FloatBatch step_z = (jxz * fx - jxx * fz) * inv_det;
        const Mask converged = (fx * fx + fz * fz) <= tol2;
        const Mask finish = active && converged;
        const bool last = it + 1 == kMaxNewtonIterations;
        const Mask record = last ? active : finish;

        if (xsimd::any(record)) {
            // The last step is tiny: first-order corrections carry the values to x0 + step.
            r_h = xsimd::select(record, eta + sx * step_x + sz * step_z, r_h);
            r_dx = xsimd::select(record, zero - (ex + step_x), r_dx);
            r_dz = xsimd::select(record, zero - (ez + step_z), r_dz);
            r_conv = xsimd::select(finish, one, r_conv);
            if constexpr (kFull) {
                // Normal = Tz x Tx with Tx = (jxx, sx, jxz), Tz = (jxz, sz, jzz).
                const FloatBatch nx = sz * jxz - jzz * sx;
                const FloatBatch ny = det;
                const FloatBatch nz = jxz * sx - sz * jxx;
                const FloatBatch inv_len = one / xsimd::sqrt(nx * nx + ny * ny + nz * nz);
                r_nx = xsimd::select(record, nx * inv_len, r_nx);
                r_ny = xsimd::select(record, ny * inv_len, r_ny);
                r_nz = xsimd::select(record, nz * inv_len, r_nz);
                r_vx = xsimd::select(record, vx, r_vx);
                r_vy = xsimd::select(record, vy, r_vy);
                r_vz = xsimd::select(record, vz, r_vz);
                r_jac = xsimd::select(record, det, r_jac);
            }
        }

        const Mask moving = active && !converged;
        ex = xsimd::select(moving, ex + step_x, ex);
        ez = xsimd::select(moving, ez + step_z, ez);
        // The rest position is within sum(Q*A) of the point: pull a wild step back inside.
        const FloatBatch r2 = ex * ex + ez * ez;
        const FloatBatch shrink = xsimd::select(r2 > radius2, xsimd::sqrt(radius2 / r2), one);
        ex *= shrink;
        ez *= shrink;
        active = moving;
        if (!xsimd::any(active)) break;
    }

    r_h.store_aligned(out.height);
    r_dx.store_aligned(out.disp_x);
    r_dz.store_aligned(out.disp_z);
    iterations.store_aligned(out.iterations);
    r_conv.store_aligned(out.converged);
    if constexpr (kFull) {
        r_nx.store_aligned(out.nx);
        r_ny.store_aligned(out.ny);
        r_nz.store_aligned(out.nz);
        r_vx.store_aligned(out.vx);
        r_vy.store_aligned(out.vy);
        r_vz.store_aligned(out.vz);
        r_jac.store_aligned(out.jacobian);
    }
}

template <bool kFull>
void solve_points(const KernelWaves& w, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
                  double* heights) {
    alignas(64) double px[kLanes];
    alignas(64) double pz[kLanes];
    BatchResult r;
    for (std::size_t start = 0; start < n; start += kLanes) {
        const std::size_t used = n - start < kLanes ? n - start : kLanes;
        for (std::size_t l = 0; l < kLanes; ++l) {
            // Spare lanes repeat the last point; lanes never interact.
            const glm::dvec2& p = points[start + (l < used ? l : used - 1)];
            px[l] = p.x;
            pz[l] = p.y;
        }
        solve_batch<kFull>(w, px, pz, r);
        for (std::size_t l = 0; l < used; ++l) {
            const double h = w.level + static_cast<double>(r.height[l]);
            if constexpr (kFull) {
                SurfacePoint& o = full[start + l];
                o.height = h;
                o.normal = {r.nx[l], r.ny[l], r.nz[l]};
                o.displacement = {r.disp_x[l], r.disp_z[l]};
                o.velocity = {r.vx[l], r.vy[l], r.vz[l]};
                o.jacobian = static_cast<double>(r.jacobian[l]);
                o.iterations = static_cast<int>(r.iterations[l]);
                o.converged = r.converged[l] != 0.0f;
            } else {
                heights[start + l] = h;
            }
        }
    }
}

void solve(const KernelWaves& w, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
                  double* heights) {
    if (full != nullptr) {
        solve_points<true>(w, points, n, full, nullptr);
    } else {
        solve_points<false>(w, points, n, nullptr, heights);
    }
}

}  // namespace tidewater::detail::TIDEWATER_KERNEL_NS
