// Phase-resolved fit: N Gerstner waves that reproduce a record sample by sample,
// fitted by Ceres with automatic differentiation, a robust (Huber) loss and bounds
// that keep the set fold-free, initialised from the record's spectral peaks. The
// model order is chosen by the Bayesian information criterion unless N is given.
//
// Models (theta_i = k_i (D_i . x) - omega_i t + phase_i, as the runtime):
//   gauge:   z(t) at x = 0, inverting x = alpha + sum Q A D cos(theta(alpha)) as the
//            Eulerian queries do; all waves travel along +x (a gauge cannot tell direction).
//   buoy:    the particle at rest at x = 0: z = sum A sin(theta), horizontal = sum Q A D cos(theta);
//            direction and Q come out of the fit.
//   profile: z(x) at t = 0 along the line (+x), inverted like the gauge.
// With a finite record depth, k follows omega^2 = g k tanh(k h).
// Units: m, s, rad, degrees. Threading: reentrant; `threads` Ceres threads per fit.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tidewater/calibration/record.hpp"
#include "tidewater/result.hpp"

namespace tidewater::calibration {

struct PhaseFitOptions {
    int waves = 0;         ///< 0: choose by BIC up to max_waves.
    int max_waves = 32;    ///< Upper bound for the automatic choice (at most 64).
    unsigned threads = 1;  ///< Ceres threads (0 = all).
    int max_iterations = 200;
    std::function<void(const std::string&)> progress;  ///< Optional progress lines.
};

struct FittedWave {
    double amplitude = 0.0;      ///< m
    double omega = 0.0;          ///< rad/s (profile: from k by dispersion)
    double k = 0.0;              ///< rad/m, the local wavenumber (finite depth when given)
    double direction_deg = 0.0;  ///< Travel, degrees from +x (east) toward +z (north)
    double phase = 0.0;          ///< rad, wrapped to [0, 2 pi)
    double steepness = 0.0;      ///< Gerstner Q in [0, 1]
    /// One-sigma uncertainties from Ceres' covariance (negative: not available).
    double amplitude_sigma = -1.0, period_sigma = -1.0, direction_sigma_deg = -1.0, phase_sigma = -1.0,
           steepness_sigma = -1.0;
    double period() const;  ///< s
};

struct PhaseFit {
    std::vector<FittedWave> waves;  ///< Largest amplitude first.
    std::vector<double> model_z;    ///< The model at every sample (elevation or heave).
    double rmse = 0.0;              ///< Of the elevation/heave, m.
    double r2 = 0.0;                ///< 1 - RSS / TSS of the elevation/heave.
    double horizontal_r2 = 0.0;     ///< Buoy: of east and north together.
    int iterations = 0;             ///< Ceres iterations of the chosen fit.
    double seconds = 0.0;           ///< Wall time of the whole fit.
    bool converged = false;
    /// Sum(Q k A) ended above 0.95 and every Q was scaled down to it (the preset stays fold-free).
    bool steepness_scaled = false;
    std::vector<std::pair<int, double>> bic;  ///< (N, BIC) of every order tried.
};

Result<PhaseFit> fit_phase_resolved(const MeasuredRecord& record, const PhaseFitOptions& options = {});

}  // namespace tidewater::calibration
