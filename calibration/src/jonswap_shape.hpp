// The JONSWAP spectrum's shape (private): one formula for the density and for the
// Ceres fit, where T is double or a Ceres Jet.
#pragma once

#include <cmath>

namespace tidewater::calibration::detail {

/// f^-5 exp(-1.25 (Tp f)^-4) gamma^r, r = exp(-(f - fp)^2 / (2 sigma^2 fp^2)), with
/// sigma 0.07 below the peak and 0.09 above it (`below_peak` says which; the caller
/// decides it on plain values so that a Jet never branches).
template <typename T>
T jonswap_shape(double f, const T& tp, const T& gamma, bool below_peak) {
    using std::exp;
    using std::log;
    const double sigma = below_peak ? 0.07 : 0.09;
    const T fp = 1.0 / tp;
    const T x = (f - fp) / (sigma * fp);
    const T tf = tp * f;
    return std::pow(f, -5.0) * exp(-1.25 / (tf * tf * tf * tf)) * exp(exp(-0.5 * x * x) * log(gamma));
}

}  // namespace tidewater::calibration::detail
