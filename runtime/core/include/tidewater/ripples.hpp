// Ripples: multi-octave gradient noise as a normal-detail term.
//
//   r(p, t) = sum_{i=1..octaves} (amplitude / i) * noise(p * i / wavelength + t * speed * D / wavelength)
//
// noise() is 2D gradient noise on an integer-hashed lattice, so the GLSL twin
// reproduces it bit for bit in integer arithmetic. Units: metres, seconds.
// Threading: RippleField is immutable and safe to share.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>

#include "tidewater/result.hpp"

namespace tidewater {

struct RippleSpec {
    double amplitude = 0.0;      ///< m, in [0, 1]; 0 disables ripples.
    double wavelength = 0.5;     ///< Base octave feature size, m, in [0.01, 100].
    int octaves = 3;             ///< In [1, 8].
    double speed = 0.3;          ///< Drift speed of the base octave, m/s, in [0, 20].
    double direction_deg = 0.0;  ///< Drift direction, degrees from +x toward +z.
    std::uint32_t seed = 7;
};

Status validate(const RippleSpec& spec, const std::string& context);

struct RippleSample {
    double height = 0.0;    ///< m
    glm::dvec2 slope{0.0};  ///< d height / dx, d height / dz.
};

class RippleField {
  public:
    RippleField() = default;
    explicit RippleField(const RippleSpec& spec) : spec_(spec) {}

    const RippleSpec& spec() const { return spec_; }
    bool enabled() const { return spec_.amplitude > 0.0; }

    /// Height and analytic slope at world position p (x, z) and time t.
    RippleSample sample(glm::dvec2 p, double time) const;

  private:
    RippleSpec spec_{};
};

/// Single-octave gradient noise in [-1, 1] with its analytic gradient (lattice units).
struct NoiseSample {
    double value = 0.0;
    glm::dvec2 gradient{0.0};
};
NoiseSample gradient_noise(glm::dvec2 p, std::uint32_t seed);

}  // namespace tidewater
