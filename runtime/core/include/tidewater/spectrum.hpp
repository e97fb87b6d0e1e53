// Wind-sea spectra and a deterministic spectrum-to-waves sampler.
//
// Pierson-Moskowitz: S(w) = a g^2 w^-5 exp(-5/4 (wp/w)^4), a = 8.1e-3,
//                    wp = 0.877 g / U (fully developed sea for wind speed U at 10 m).
// JONSWAP:           S(w) = PM-shape(a, wp) * gamma^r, r = exp(-(w-wp)^2 / (2 s^2 wp^2)),
//                    s = 0.07 (w <= wp) or 0.09, a = 0.076 (U^2/(F g))^0.22,
//                    wp = 22 (g^2/(U F))^(1/3)   (Hasselmann et al. 1973).
// Units: S in m^2 s/rad, w in rad/s, U in m/s, F (fetch) in m.
// Threading: pure functions.
#pragma once

#include <cstdint>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/waves.hpp"

namespace tidewater {

enum class SpectrumKind { pierson_moskowitz, jonswap };

struct SpectrumSpec {
    SpectrumKind kind = SpectrumKind::jonswap;
    double wind_speed = 10.0;         ///< U10, m/s, in (0, 60].
    double fetch = 100000.0;          ///< m, JONSWAP only, in [1e3, 1e7].
    double peak_enhancement = 3.3;    ///< JONSWAP gamma, in [1, 10].
    double mean_direction_deg = 0.0;  ///< Mean direction of travel, degrees from +x toward +z.
    double spreading = 10.0;          ///< s in cos^(2s)((theta - mean)/2), in [0, 100]; 0 = uniform.
    int wave_count = 32;              ///< In [1, kMaxWaves].
    std::uint64_t seed = 1;           ///< Same seed, same waves, on every platform.
    double steepness = 0.6;           ///< Target sum(Q*k*A), in [0, 1]; Q is equal across waves.
};

/// Spectral density S(omega), m^2 s / rad.
double spectral_density(const SpectrumSpec& spec, double omega);
/// Peak angular frequency, rad/s.
double peak_omega(const SpectrumSpec& spec);
/// Significant wave height 4*sqrt(m0) of the continuous spectrum, m.
double spectrum_significant_wave_height(const SpectrumSpec& spec);

/// Checks the ranges above; `context` names the source in messages.
Status validate(const SpectrumSpec& spec, const std::string& context);

/// Samples `wave_count` waves: frequencies from equal-energy bins (a seeded
/// jitter inside each bin), directions drawn from the spreading function,
/// random phases, amplitude sqrt(2 * bin energy). The set's significant wave
/// height matches the spectrum's within 1% (the bins cover 99.8% of m0).
Result<std::vector<WaveSpec>> generate_waves(const SpectrumSpec& spec, const std::string& context);

}  // namespace tidewater
