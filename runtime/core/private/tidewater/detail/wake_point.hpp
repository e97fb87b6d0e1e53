// The water a disturbance makes: the single wake formula every part of Tidewater uses
// (queries, the inspector, the renderer through its GLSL twin shaders/wake_point.glsl).
// A wake is one more set of waves in the one evaluation (water_point.hpp): each
// disturbance adds a local Gerstner wave whose wavevector, amplitude and phase this
// header gives.
//
// A disturbance is a pressure pulse of strength P (the integral of p / rho over its
// patch, m^4/s^2) applied for a moment dt, of Gaussian shape p ~ exp(-pi^2 r^2 / b^2)
// with width b (its source size, m). On deep water its impulse P dt spreads as the
// Cauchy-Poisson response (Lamb 1932, art. 255, by stationary phase): at distance r and
// age tau the local wavenumber is k = g tau^2 / (4 r^2), the phase -g tau^2 / (4 r) = -k r
// (crests run outward at the group speed r / tau), the angular frequency g tau / (2 r),
// and the elevation
//     eta = P dt k^(3/2) F(k) / (sqrt(2) pi sqrt(g) r) sin(phase),
//     F(k) = exp(-k^2 b^2 / (4 pi^2))   (the patch's transform: waves shorter than it fade).
// Two regularisations keep the near field finite where stationary phase does not hold:
// r is measured as sqrt(r^2 + (b / 2 pi)^2), and the amplitude rises as
// 1 - exp(-phase^2 / 4) over the first radian of phase.
//
// A chain of disturbances (a boat's track) is integrated segment by segment: between
// two points the strength, the response and the phase are taken as linear in emission
// time, whose integral is the mean weighted response at the mean phase times
// sinc(dphase / 2) times the segment's duration. The sum over a boat's track is then
// Kelvin's wake: 19.47 degree cusps, transverse waves of 2 pi U^2 / g on the track.
//
// Written once over the number type T (double, SIMD batches, Jets), as water_point.hpp.
// Units: metres, seconds, radians. Threading: pure functions.
#pragma once

#include <cmath>

#include "host_device.h"
#include "tidewater/constants.hpp"
#include "tidewater/detail/water_point.hpp"

namespace tidewater::detail {

/// The wave a unit pulse (P dt = 1 m^4/s) shows at one point.
template <typename T>
struct WakeWave {
    T kx, kz;  ///< local wavevector, pointing away from the disturbance, rad/m
    T a;       ///< amplitude per unit impulse, m per m^4/s
    T omega;   ///< local angular frequency, rad/s
    T theta;   ///< phase, rad (eta = a sin(theta))
};

/// The unit pulse's wave at offset (dx, dz) (m) from a disturbance of source size `size`
/// (m) made `age` seconds ago. Nothing before it is made (age <= 0).
template <typename T>
WakeWave<T> wake_wave(const T& dx, const T& dz, const T& age, const T& size) {
    using Ops = NumberOps<T>;
    const double inv_two_pi = 1.0 / (2.0 * kPi);
    const T spread = size * constant<T>(inv_two_pi);
    const T r2 = dx * dx + dz * dz + spread * spread;
    const T inv_r = Ops::inv_sqrt(Ops::select(r2 > T(0.0), r2, T(1.0)));
    const T tau = Ops::select(age > T(0.0), age, T(0.0));
    const T k = constant<T>(0.25 * kGravity) * tau * tau * inv_r * inv_r;
    WakeWave<T> w;
    w.theta = T(0.0) - constant<T>(0.25 * kGravity) * tau * tau * inv_r;
    w.omega = constant<T>(0.5 * kGravity) * tau * inv_r;
    const T filter = Ops::exp(T(0.0) - k * k * spread * spread);
    const T near = T(1.0) - Ops::exp(constant<T>(-0.25) * w.theta * w.theta);
    const double norm = 1.0 / (std::sqrt(2.0) * kPi * std::sqrt(kGravity));
    w.a = constant<T>(norm) * k * Ops::sqrt(k) * filter * near * inv_r;
    w.kx = k * dx * inv_r;
    w.kz = k * dz * inv_r;
    return w;
}

/// A Gerstner wave of steepness `q` for a disturbance's wave carrying `impulse` (m^4/s),
/// with Q k A held to at most kWakeFoldLimit so that a wake never folds the surface.
template <typename T>
WaveTerm<T> wake_term(const WakeWave<T>& w, const T& impulse, const T& q) {
    using Ops = NumberOps<T>;
    const T a = impulse * w.a;
    const T k = Ops::sqrt(w.kx * w.kx + w.kz * w.kz);
    const T qka = q * k * a;
    const T limit = constant<T>(static_cast<double>(gpu::kWakeFoldLimit));
    const T q_held = Ops::select(qka > limit, limit / Ops::select(k * a > T(0.0), k * a, T(1.0)), q);
    return wave_term(w.kx, w.kz, a, q_held, w.omega);
}

/// sin(x) / x, 1 at 0.
template <typename T>
T sinc(const T& x) {
    using Ops = NumberOps<T>;
    T s, c;
    Ops::sin_cos(x, s, c);
    const T small = x * x;
    return Ops::select(small > constant<T>(1e-8), s / Ops::select(small > constant<T>(1e-8), x, T(1.0)),
                       T(1.0) - small * constant<T>(1.0 / 6.0));
}

/// Adds the segment of a chain between two disturbances (a, b), as seen from the field
/// point: their unit-pulse waves `wa`, `wb`, strengths `pa`, `pb` (m^4/s^2), steepness
/// `qa`, `qb`, and the segment's duration (s, the difference of their emission times).
template <bool kVelocity = true, typename T>
void add_wake_segment(SurfaceSums<T>& s, const WakeWave<T>& wa, const WakeWave<T>& wb, const T& pa, const T& pb,
                      const T& qa, const T& qb, const T& duration) {
    const T half(0.5);
    WakeWave<T> mean;
    mean.kx = half * (wa.kx + wb.kx);
    mean.kz = half * (wa.kz + wb.kz);
    mean.omega = half * (wa.omega + wb.omega);
    mean.theta = half * (wa.theta + wb.theta);
    // The weighted mean response: trapezoid weights, the strength carried into a.
    mean.a = half * (pa * wa.a + pb * wb.a);
    const T impulse = duration * sinc(half * (wb.theta - wa.theta));
    add_wave<kVelocity>(s, wake_term(mean, impulse, half * (qa + qb)), mean.theta);
}

/// Adds a lone disturbance (a splash) of impulse `impulse` (m^4/s) and steepness `q`.
template <bool kVelocity = true, typename T>
void add_wake_point(SurfaceSums<T>& s, const WakeWave<T>& w, const T& impulse, const T& q) {
    add_wave<kVelocity>(s, wake_term(w, impulse, q), w.theta);
}

/// Foam from a disturbance's turbulence `turbulence` (0..1 when made) at distance `d`
/// (m) from it (or from its segment), `age` seconds later: it decays over
/// kWakeFoamLifetime and spreads from the source's width by turbulent diffusion.
template <typename T>
T wake_foam(const T& d, const T& age, const T& size, const T& turbulence) {
    using Ops = NumberOps<T>;
    const T tau = Ops::select(age > T(0.0), age, T(0.0));
    const T width = constant<T>(0.5) * size + constant<T>(static_cast<double>(gpu::kWakeFoamSpread)) * Ops::sqrt(tau);
    const T x = d / width;
    return turbulence * Ops::exp(T(0.0) - tau * constant<T>(1.0 / static_cast<double>(gpu::kWakeFoamLifetime)) - x * x);
}

}  // namespace tidewater::detail
