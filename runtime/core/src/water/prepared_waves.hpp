// A body's open-sea waves at one instant, laid out for evaluation (private).
#pragma once

#include <cstddef>
#include <vector>

#include "tidewater/detail/water_point.hpp"
#include "tidewater/water_body.hpp"
#include "tidewater/waves.hpp"
#include "tidewater/whitecaps.hpp"

namespace tidewater::detail {

/// `Scalar` is float for the SIMD kernel and double for the reference. Phases that need
/// the full range (k D.p for large p) are formed in double; what multiplies the small
/// rest offset e (|e| <= sum(Q A)) is Scalar, which keeps micro-radians anywhere.
template <typename Scalar>
struct PreparedWaves {
    std::size_t count = 0;
    std::vector<double> kx, kz;                       ///< k D, rad/m, for the phase at the query point
    std::vector<double> offset;                       ///< phase - omega t, reduced to [-pi, pi)
    std::vector<Scalar> kx_s, kz_s;                   ///< k D for the rest offset
    std::vector<WaveTerm<Scalar>> open_sea;           ///< each wave's coefficients in open water
    std::vector<Scalar> amplitude, steepness, omega;  ///< what a shore reshapes
    /// sin and cos of omega tau_l for wave i's lag l at [i * kFoamLags + l] (add_wave_lags)
    std::vector<Scalar> lag_sin, lag_cos;
    double max_offset = 0.0;  ///< sum(Q A): the rest position lies within this of the point, m
    double tolerance = 0.0;   ///< newton_tolerance(max_offset), m
    double radius = 0.0;      ///< newton_radius(max_offset), m
    double level = 0.0;       ///< rest water level added to heights, m
    double whitecap_jacobian = kDefaultWhitecapJacobian;  ///< the body's J*, where its crest foam turns on
    double bank_ramp_depth = 0.0;  ///< a river's: the depth its waves die out over (river_bank_ramp_depth), m
};

template <typename Scalar>
PreparedWaves<Scalar> prepare_waves(const WaveSet& set, double local_time, double level);

/// A body's waves at clock time `time`: its local time, level and whitecap Jacobian.
template <typename Scalar>
PreparedWaves<Scalar> prepare_body_waves(const WaterBody& body, double time);

/// A river's waves: wavevectors in its channel frame (k_s along downstream, k_n across,
/// left > 0) and phases that ride its mean speed U: offset = phase - (omega + k_s U) t,
/// the Doppler shift of waves carried by the current. base_phases then takes channel
/// coordinates (s, n) in place of (x, z).
template <typename Scalar>
PreparedWaves<Scalar> prepare_river_waves(const WaveSet& set, double local_time, double level, double mean_speed);

/// Each wave's phase k D.p + offset at the point (px, pz), reduced in double to [-pi, pi),
/// into base[i * stride]. (Not inline: the kernels are compiled per instruction set.)
void base_phases(const PreparedWaves<float>& w, double px, double pz, float* base, std::size_t stride);
void base_phases(const PreparedWaves<double>& w, double px, double pz, double* base, std::size_t stride);

}  // namespace tidewater::detail
