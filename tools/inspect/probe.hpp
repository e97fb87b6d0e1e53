// A probe: the height at one point over time and its spectrum (no VTK here).
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::inspect {

struct ProbeSeries {
    glm::dvec2 at{0.0};                    ///< x, z, m.
    std::vector<double> time, height;      ///< s, m (world y of the surface).
    std::vector<double> frequency, power;  ///< Hz, m^2/Hz (one-sided, Hann window, zero-padded x8).
    double dominant_period =
        0.0;  ///< s, of the strongest spectral peak (parabolic refinement); 0 where the height never changes.
};

/// Samples the surface at `at` over `times`, which must be evenly spaced (a t0:t1:dt
/// range with at least 16 steps).
Result<ProbeSeries> probe(const Scene& scene, glm::dvec2 at, const std::vector<double>& times);

}  // namespace tidewater::inspect
