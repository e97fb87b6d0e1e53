// Linear water-wave dispersion at finite depth: omega^2 = g k tanh(k h).
// Units: rad/s, rad/m, metres. Threading: pure functions.
#pragma once

namespace tidewater {

/// Wavenumber k (rad/m) of a wave of angular frequency `omega` in water of depth `depth` (> 0).
/// Newton's method from the shallow/deep-water estimates; relative accuracy 1e-12.
double wavenumber_at_depth(double omega, double depth);

/// Group velocity c_g = (omega / k) * (1 + 2 k h / sinh(2 k h)) / 2, m/s (depth > 0).
double group_velocity(double k, double depth);

/// Linear shoaling coefficient sqrt(c_g,deep / c_g(h)) for a wave of frequency `omega`.
double shoaling_coefficient(double omega, double depth);

}  // namespace tidewater
