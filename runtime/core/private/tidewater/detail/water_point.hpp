// The water at one rest position: the single Gerstner evaluation every part of
// Tidewater uses (queries, bakes, the inspector, calibration). Its GLSL twin is
// shaders/water_point.glsl; shared constants live in shaders/host_device.h.
//
// Written once over the number type T:
//   double                     the scalar reference and one-off evaluations;
//   xsimd::batch<float, Arch>  the SIMD query kernel (lanes are query points);
//   ceres::Jet<double, N>      calibration (derivatives by automatic differentiation).
// Number-type operations go through NumberOps<T>, which the SIMD kernel
// specialises for its batches.
//
// For wave i with local wavevector K = k D (rad/m), amplitude A (m), steepness Q and
// angular frequency omega, at phase theta:
//   displacement  (Q A D cos, A sin)          horizontal and vertical, m
//   d(disp)/dx0   Q A k D D^T sin              gradient of the horizontal map
//   slope         A K cos                      d eta / d x0
//   velocity      (Q A omega D sin, -A omega cos)
// A body, a shore, a river current or a wake changes what K, A, Q and theta are at
// a point (or adds a term to the sums); it never writes these sums again.
// Units: metres, seconds, radians. Threading: pure functions.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "host_device.h"

namespace tidewater::detail {

/// Number-type operations the templates need. The primary template serves double
/// and Ceres Jets (found by argument-dependent lookup); SIMD batches specialise it.
template <typename T>
struct NumberOps {
    using Mask = bool;
    using Scalar = T;  ///< one lane's type
    static constexpr std::size_t kLanes = 1;
    static T load(const Scalar* p) { return *p; }
    static void store(const T& v, Scalar* p) { *p = v; }
    static T mul_add(const T& a, const T& b, const T& c) { return a * b + c; }
    static void sin_cos(const T& x, T& s, T& c) {
        using std::cos;
        using std::sin;
        s = sin(x);
        c = cos(x);
    }
    static T sqrt(const T& x) {
        using std::sqrt;
        return sqrt(x);
    }
    static T exp(const T& x) {
        using std::exp;
        return exp(x);
    }
    /// The nearest integer (ties to even).
    static T round(const T& x) {
        using std::nearbyint;
        return nearbyint(x);
    }
    /// 1 / sqrt(x) for x > 0.
    static T inv_sqrt(const T& x) { return T(1.0) / sqrt(x); }
    /// Copies `count` consecutive floats from each lane's source into lane-major `dst`:
    /// dst[f * kLanes + lane] = src[lane][f].
    static void interleave(const float* const* src, std::size_t count, Scalar* dst) {
        for (std::size_t f = 0; f < count; ++f) dst[f] = Scalar(src[0][f]);
    }
    static T select(Mask m, const T& a, const T& b) { return m ? a : b; }
    static bool any(Mask m) { return m; }
    static bool all(Mask m) { return m; }
};

/// A constant of the number type T (rounded once to T's lane type).
template <typename T>
T constant(double v) {
    return T(static_cast<typename NumberOps<T>::Scalar>(v));
}

/// One wave's coefficients at a point: the products the sums need, formed once.
template <typename T>
struct WaveTerm {
    T a;                       ///< A: elevation
    T ak_x, ak_z;              ///< A K: slope
    T qa_x, qa_z;              ///< Q A D: horizontal displacement
    T qak_xx, qak_xz, qak_zz;  ///< Q A k D D^T: displacement gradient
    T qaw_x, qaw_z, aw;        ///< Q A omega D, A omega: particle velocity
};

/// Squares of wavevectors and directions under this are taken for zero (1/m^2): far
/// above float's subnormals, far below any wave's (k = 1e-15 rad/m).
inline constexpr double kVanishingSquare = 1e-30;

/// The coefficients of a wave with local wavevector (kx, kz), amplitude `a`, steepness
/// `q` and angular frequency `omega`. A zero amplitude gives an exactly zero term, even
/// where the wavevector is zero (dry land) or vanishing.
template <typename T>
WaveTerm<T> wave_term(const T& kx, const T& kz, const T& a, const T& q, const T& omega) {
    using Ops = NumberOps<T>;
    const T k2 = kx * kx + kz * kz;
    // 1/k where it exists; a vanishing wavevector only occurs with zero amplitude (a
    // wake's newest point), and its square may be subnormal, which the SIMD kernels'
    // inverse square root estimate takes for zero: infinity times a zero amplitude.
    const T inv_k = Ops::inv_sqrt(Ops::select(k2 > constant<T>(kVanishingSquare), k2, T(1.0)));
    const T qa = q * a;
    const T dx = kx * inv_k, dz = kz * inv_k;
    WaveTerm<T> w;
    w.a = a;
    w.ak_x = a * kx;
    w.ak_z = a * kz;
    w.qa_x = qa * dx;
    w.qa_z = qa * dz;
    w.qak_xx = qa * kx * dx;
    w.qak_xz = qa * kx * dz;
    w.qak_zz = qa * kz * dz;
    w.qaw_x = qa * omega * dx;
    w.qaw_z = qa * omega * dz;
    w.aw = a * omega;
    return w;
}

/// The sums of one evaluation, at rest position x0.
template <typename T>
struct SurfaceSums {
    T dx = T(0.0), dz = T(0.0), eta = T(0.0);    ///< displacement, m
    T mxx = T(0.0), mxz = T(0.0), mzz = T(0.0);  ///< sum Q A k D D^T sin: I - (these) is the map's Jacobian
    T sx = T(0.0), sz = T(0.0);                  ///< d eta / d x0
    T vx = T(0.0), vy = T(0.0), vz = T(0.0);     ///< particle velocity, m/s
};

/// Adds one wave at phase theta (given as its sine and cosine). `kVelocity` false skips
/// the velocity sums (heights-only queries).
template <bool kVelocity = true, typename T>
void add_wave(SurfaceSums<T>& s, const WaveTerm<T>& w, const T& sin_theta, const T& cos_theta) {
    using Ops = NumberOps<T>;
    s.dx = Ops::mul_add(w.qa_x, cos_theta, s.dx);
    s.dz = Ops::mul_add(w.qa_z, cos_theta, s.dz);
    s.eta = Ops::mul_add(w.a, sin_theta, s.eta);
    s.mxx = Ops::mul_add(w.qak_xx, sin_theta, s.mxx);
    s.mxz = Ops::mul_add(w.qak_xz, sin_theta, s.mxz);
    s.mzz = Ops::mul_add(w.qak_zz, sin_theta, s.mzz);
    s.sx = Ops::mul_add(w.ak_x, cos_theta, s.sx);
    s.sz = Ops::mul_add(w.ak_z, cos_theta, s.sz);
    if constexpr (kVelocity) {
        s.vx = Ops::mul_add(w.qaw_x, sin_theta, s.vx);
        s.vz = Ops::mul_add(w.qaw_z, sin_theta, s.vz);
        s.vy = s.vy - w.aw * cos_theta;  // d theta / dt = -omega
    }
}

/// s += w * b: the sums of a second water, scaled (waves fading in as another body's fade out).
template <typename T>
void add_scaled(SurfaceSums<T>& s, const SurfaceSums<T>& b, const T& w) {
    using Ops = NumberOps<T>;
    s.dx = Ops::mul_add(w, b.dx, s.dx);
    s.dz = Ops::mul_add(w, b.dz, s.dz);
    s.eta = Ops::mul_add(w, b.eta, s.eta);
    s.mxx = Ops::mul_add(w, b.mxx, s.mxx);
    s.mxz = Ops::mul_add(w, b.mxz, s.mxz);
    s.mzz = Ops::mul_add(w, b.mzz, s.mzz);
    s.sx = Ops::mul_add(w, b.sx, s.sx);
    s.sz = Ops::mul_add(w, b.sz, s.sz);
    s.vx = Ops::mul_add(w, b.vx, s.vx);
    s.vy = Ops::mul_add(w, b.vy, s.vy);
    s.vz = Ops::mul_add(w, b.vz, s.vz);
}

/// Adds one wave at phase `theta`.
template <bool kVelocity = true, typename T>
void add_wave(SurfaceSums<T>& s, const WaveTerm<T>& w, const T& theta) {
    T sn, cs;
    NumberOps<T>::sin_cos(theta, sn, cs);
    add_wave<kVelocity>(s, w, sn, cs);
}

/// The compression a particle's crest had earlier: the sums m of the horizontal map's
/// gradient kFoamLags times, tau_l = l * kFoamLagStep seconds ago (l = 1..kFoamLags), at
/// the same rest position. Gerstner rest positions label water particles, and a shore or
/// a body reshapes a wave's phase field but keeps its frequency, so tau ago each wave's
/// phase was theta + omega tau: the lagged sums need no more sines than the wave's own.
/// (Not for rivers, whose waves ride the current: their particles do not keep their rest
/// positions.) Whitecap foam lingers by these (tidewater/detail/surface_foam.hpp).
inline constexpr std::size_t kFoamLags = gpu::kFoamLags;

template <typename T>
struct LaggedCompression {
    std::array<T, kFoamLags> mxx, mxz, mzz;
    LaggedCompression() {
        mxx.fill(T(0.0));
        mxz.fill(T(0.0));
        mzz.fill(T(0.0));
    }
};

/// Adds one wave at phase `theta` to the lagged sums; lag_sin[l] and lag_cos[l] are the
/// sine and cosine of omega tau_l (l = 0 for the first lag), so that
/// sin(theta + omega tau_l) = sin theta cos(omega tau_l) + cos theta sin(omega tau_l).
/// (The GLSL twin turns (sin, cos) theta lag by lag by omega kFoamLagStep instead, from
/// GpuWave.lag_turn: the same phases, with two values a wave on the GPU, not eight.)
/// Here theta is given as its sine and cosine.
template <typename T, typename Scalar>
void add_wave_lags(LaggedCompression<T>& c, const WaveTerm<T>& w, const T& sin_theta, const T& cos_theta,
                   const Scalar* lag_sin, const Scalar* lag_cos) {
    using Ops = NumberOps<T>;
    for (std::size_t l = 0; l < kFoamLags; ++l) {
        const T s = Ops::mul_add(sin_theta, T(lag_cos[l]), cos_theta * T(lag_sin[l]));
        c.mxx[l] = Ops::mul_add(w.qak_xx, s, c.mxx[l]);
        c.mxz[l] = Ops::mul_add(w.qak_xz, s, c.mxz[l]);
        c.mzz[l] = Ops::mul_add(w.qak_zz, s, c.mzz[l]);
    }
}

template <typename T, typename Scalar>
void add_wave_lags(LaggedCompression<T>& c, const WaveTerm<T>& w, const T& theta, const Scalar* lag_sin,
                   const Scalar* lag_cos) {
    T sin_theta, cos_theta;
    NumberOps<T>::sin_cos(theta, sin_theta, cos_theta);
    add_wave_lags(c, w, sin_theta, cos_theta, lag_sin, lag_cos);
}

/// c += w * b (a second water's waves, scaled, as add_scaled).
template <typename T>
void add_scaled(LaggedCompression<T>& c, const LaggedCompression<T>& b, const T& w) {
    using Ops = NumberOps<T>;
    for (std::size_t l = 0; l < kFoamLags; ++l) {
        c.mxx[l] = Ops::mul_add(w, b.mxx[l], c.mxx[l]);
        c.mxz[l] = Ops::mul_add(w, b.mxz[l], c.mxz[l]);
        c.mzz[l] = Ops::mul_add(w, b.mzz[l], c.mzz[l]);
    }
}

/// The horizontal map's Jacobian determinant at each lag.
template <typename T>
std::array<T, kFoamLags> lagged_jacobians(const LaggedCompression<T>& c) {
    std::array<T, kFoamLags> det;
    for (std::size_t l = 0; l < kFoamLags; ++l) {
        const T jxx = T(1.0) - c.mxx[l], jzz = T(1.0) - c.mzz[l];
        det[l] = jxx * jzz - c.mxz[l] * c.mxz[l];
    }
    return det;
}

/// What follows from the sums: the horizontal map's Jacobian [[jxx, jxz], [jxz, jzz]]
/// (symmetric), its determinant and the unnormalised normal Tz x Tx, with the
/// tangents Tx = (jxx, sx, jxz) and Tz = (jxz, sz, jzz) of the displaced surface.
template <typename T>
struct SurfaceFrame {
    T jxx, jxz, jzz, det;
    T nx, ny, nz;
};

template <typename T>
SurfaceFrame<T> surface_frame(const SurfaceSums<T>& s) {
    SurfaceFrame<T> f;
    f.jxx = T(1.0) - s.mxx;
    f.jxz = T(0.0) - s.mxz;
    f.jzz = T(1.0) - s.mzz;
    f.det = f.jxx * f.jzz - f.jxz * f.jxz;
    f.nx = s.sz * f.jxz - f.jzz * s.sx;
    f.ny = f.det;
    f.nz = f.jxz * s.sx - s.sz * f.jxx;
    return f;
}

}  // namespace tidewater::detail
