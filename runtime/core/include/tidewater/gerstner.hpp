// Lagrangian evaluation of a Gerstner wave set: where the water particle that
// rests at x0 is at time t, with analytic derivatives.
//
// For wave i with direction D, wavenumber k, amplitude A, steepness Q:
//   theta = k D.x0 - omega t + phase
//   x = x0 + sum Q A D cos(theta),   y = sum A sin(theta)
// Units: metres, seconds. Threading: pure functions, safe from any thread.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "tidewater/waves.hpp"

namespace tidewater {

/// The state of the surface particle whose rest position is x0.
struct LagrangianSample {
    glm::dvec3 displacement{0.0};      ///< (dx, eta, dz): from the rest position, m.
    glm::dvec3 normal{0.0, 1.0, 0.0};  ///< Unit surface normal.
    glm::dvec3 velocity{0.0};          ///< Particle velocity, m/s.
    double jacobian = 1.0;             ///< det of d(x,z)/d(x0,z0): 1 flat, -> 0 where the surface folds.
    /// d(x,z)/d(x0,z0) entries: [[jxx, jxz], [jxz, jzz]] (the map is symmetric).
    double jxx = 1.0, jxz = 0.0, jzz = 1.0;
    /// d eta / d x0 and d eta / d z0.
    glm::dvec2 slope{0.0};
};

/// Phase offsets -omega*t + phase for every wave, reduced to [-pi, pi) in double so that
/// large t loses no accuracy.
void phase_offsets_at(const WaveSet& set, double time, std::span<double> out);

/// Evaluates the set at rest position `rest` (x0, z0) and time `time`.
LagrangianSample evaluate_lagrangian(const WaveSet& set, glm::dvec2 rest, double time);

/// Reduces an angle to [-pi, pi).
double wrap_angle(double radians);

}  // namespace tidewater
