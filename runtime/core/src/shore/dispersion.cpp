#include "tidewater/dispersion.hpp"

#include <algorithm>
#include <cmath>

#include "tidewater/constants.hpp"

namespace tidewater {

double wavenumber_at_depth(double omega, double depth) {
    const double k_deep = omega * omega / kGravity;
    const double k_shallow = omega / std::sqrt(kGravity * depth);
    // Start from the larger of the two limits: f(k) = g k tanh(kh) - w^2 is increasing and
    // convex enough there for Newton to converge monotonically.
    double k = std::max(k_deep, k_shallow);
    for (int i = 0; i < 60; ++i) {
        const double th = std::tanh(k * depth);
        const double f = kGravity * k * th - omega * omega;
        const double df = kGravity * (th + k * depth * (1.0 - th * th));
        const double step = f / df;
        k -= step;
        if (std::abs(step) < 1e-13 * k) break;
    }
    return k;
}

double group_velocity(double k, double depth) {
    const double kh = k * depth;
    const double omega = std::sqrt(kGravity * k * std::tanh(kh));
    const double n = kh > 20.0 ? 0.5 : 0.5 * (1.0 + 2.0 * kh / std::sinh(2.0 * kh));
    return n * omega / k;
}

double shoaling_coefficient(double omega, double depth) {
    const double k_deep = omega * omega / kGravity;
    const double cg_deep = 0.5 * omega / k_deep;
    return std::sqrt(cg_deep / group_velocity(wavenumber_at_depth(omega, depth), depth));
}

}  // namespace tidewater
