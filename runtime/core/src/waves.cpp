#include "tidewater/waves.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tidewater/constants.hpp"

namespace tidewater {

double deep_water_omega(double wavelength) {
    return std::sqrt(kGravity * kTwoPi / wavelength);
}

double deep_water_wavelength(double omega) {
    return kTwoPi * kGravity / (omega * omega);
}

double Wave::period() const {
    return kTwoPi / omega;
}

double Wave::phase_speed() const {
    return omega / k;
}

namespace {

Status check_range(double value, double lo, double hi, const std::string& where, const char* field,
                   const char* range_text) {
    if (!std::isfinite(value)) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/{}: must be a finite number (allowed: {})", where, field, range_text)};
    }
    if (value < lo || value > hi) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/{}: {} is out of range (allowed: {})", where, field, value, range_text)};
    }
    return {};
}

Status validate_spec(const WaveSpec& s, const std::string& where) {
    if (auto st = check_range(s.direction_deg, -1e6, 1e6, where, "direction", "finite degrees"); !st) return st;
    if (!std::isfinite(s.wavelength) || s.wavelength <= 0.0 || s.wavelength > 1e5) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/wavelength: {} is out of range (allowed: 0 < wavelength <= 100000 m)", where,
                                 s.wavelength)};
    }
    if (auto st = check_range(s.amplitude, 0.0, 1e3, where, "amplitude", "0 <= amplitude <= 1000 m"); !st) return st;
    if (auto st = check_range(s.steepness, 0.0, 1.0, where, "steepness", "0 <= steepness <= 1"); !st) return st;
    if (auto st = check_range(s.phase, -1e6, 1e6, where, "phase", "finite radians"); !st) return st;
    return {};
}

}  // namespace

Result<WaveSet> WaveSet::create(std::span<const WaveSpec> specs, FoldPolicy policy, const std::string& context,
                                std::vector<std::string>* warnings) {
    if (specs.size() > kMaxWaves) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {} waves given, at most {} allowed", context, specs.size(), kMaxWaves)};
    }
    WaveSet set;
    set.waves_.reserve(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const WaveSpec& s = specs[i];
        if (auto st = validate_spec(s, fmt::format("{}/{}", context, i)); !st) return st.error();
        Wave w;
        const double rad = s.direction_deg * (kPi / 180.0);
        w.dir_x = std::cos(rad);
        w.dir_z = std::sin(rad);
        w.k = kTwoPi / s.wavelength;
        w.omega = deep_water_omega(s.wavelength);
        w.amplitude = s.amplitude;
        w.steepness = s.steepness;
        w.phase = s.phase;
        set.waves_.push_back(w);
    }

    const double fold = set.fold_measure();
    if (fold > kFoldLimit) {
        if (policy == FoldPolicy::reject) {
            return Error{ErrorCode::fold_violation,
                         fmt::format("{}: sum(steepness * k * amplitude) = {:.4f} exceeds {} and the surface "
                                     "would fold; lower steepness or amplitude, or set \"fold_policy\": \"clamp\"",
                                     context, fold, kFoldLimit)};
        }
        const double scale = kFoldLimit / fold;
        for (Wave& w : set.waves_) w.steepness *= scale;
        if (warnings) {
            warnings->push_back(
                fmt::format("{}: sum(steepness * k * amplitude) = {:.4f} exceeds {}; every steepness scaled by {:.4f}",
                            context, fold, kFoldLimit, scale));
        }
    }
    return set;
}

double WaveSet::fold_measure() const {
    double sum = 0.0;
    for (const Wave& w : waves_) sum += w.steepness * w.k * w.amplitude;
    return sum;
}

double WaveSet::max_horizontal_displacement() const {
    double sum = 0.0;
    for (const Wave& w : waves_) sum += w.steepness * w.amplitude;
    return sum;
}

double WaveSet::max_elevation() const {
    double sum = 0.0;
    for (const Wave& w : waves_) sum += w.amplitude;
    return sum;
}

double WaveSet::significant_wave_height() const {
    double m0 = 0.0;
    for (const Wave& w : waves_) m0 += 0.5 * w.amplitude * w.amplitude;
    return 4.0 * std::sqrt(m0);
}

double WaveSet::mean_square_slope() const {
    double sum = 0.0;
    for (const Wave& w : waves_) sum += 0.5 * (w.k * w.amplitude) * (w.k * w.amplitude);
    return sum;
}

}  // namespace tidewater
