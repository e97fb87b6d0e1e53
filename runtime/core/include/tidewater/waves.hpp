// Gerstner wave sets: authoring parameters, validation and the fold-free rule.
//
// Units: metres, seconds, radians (direction in degrees as authored).
// Threading: WaveSet is immutable after creation and safe to share.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

/// One wave as authored in a preset or scene.
struct WaveSpec {
    double direction_deg = 0.0;  ///< Direction of travel, degrees from +x toward +z.
    double wavelength = 10.0;    ///< Deep-water wavelength, m, > 0.
    double amplitude = 0.1;      ///< m, >= 0.
    double steepness = 0.5;      ///< Gerstner Q, in [0, 1].
    double phase = 0.0;          ///< Phase offset, rad.
};

/// What to do when a set breaks sum(Q*k*A) <= 1.
enum class FoldPolicy {
    reject,  ///< Return ErrorCode::fold_violation.
    clamp,   ///< Scale every Q down so that the sum equals the limit, and warn.
};

/// One wave with its derived quantities, ready for evaluation.
struct Wave {
    double dir_x = 1.0;  ///< Unit direction of travel, x component.
    double dir_z = 0.0;  ///< Unit direction of travel, z component.
    double k = 0.0;      ///< Wavenumber 2*pi/lambda, rad/m.
    double omega = 0.0;  ///< Angular frequency from deep-water dispersion omega^2 = g*k, rad/s.
    double amplitude = 0.0;
    double steepness = 0.0;
    double phase = 0.0;

    double period() const;       ///< s
    double phase_speed() const;  ///< m/s
    bool operator==(const Wave&) const = default;
};

/// A validated set of at most kMaxWaves waves that satisfies the fold-free rule.
class WaveSet {
  public:
    WaveSet() = default;

    /// Validates each spec (finite values, wavelength > 0, amplitude >= 0,
    /// steepness in [0, 1]) and the fold-free rule. `context` prefixes error
    /// messages (e.g. "scene.json: /ocean/waves"). With FoldPolicy::clamp a
    /// violating set is scaled and a warning appended to `warnings`.
    static Result<WaveSet> create(std::span<const WaveSpec> specs, FoldPolicy policy,
                                  const std::string& context = "waves", std::vector<std::string>* warnings = nullptr);

    std::span<const Wave> waves() const { return waves_; }
    std::size_t size() const { return waves_.size(); }
    bool empty() const { return waves_.empty(); }

    /// sum(Q*k*A): the fold measure, <= 1 for every WaveSet.
    double fold_measure() const;
    /// sum(Q*A): an upper bound of the horizontal displacement, m.
    double max_horizontal_displacement() const;
    /// sum(A): an upper bound of |eta|, m.
    double max_elevation() const;
    /// 4*sqrt(sum(A^2)/2): significant wave height of the set, m.
    double significant_wave_height() const;
    /// sum((k*A)^2)/2: the mean square slope of the linear surface, both axes together
    /// (Cox and Munk's total slope variance).
    double mean_square_slope() const;

  private:
    std::vector<Wave> waves_;
};

/// Deep-water dispersion: angular frequency of a wave of wavelength `lambda` (m).
double deep_water_omega(double wavelength);
/// Deep-water wavelength of a wave of angular frequency `omega` (rad/s).
double deep_water_wavelength(double omega);

}  // namespace tidewater
