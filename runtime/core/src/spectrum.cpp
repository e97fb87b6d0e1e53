#include "tidewater/spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tidewater/constants.hpp"

namespace tidewater {

namespace {

constexpr double kPmAlpha = 8.1e-3;
// Integration grid for m0 and the cumulative energy table, relative to the peak.
constexpr double kLowFactor = 0.2;
constexpr double kHighFactor = 30.0;
constexpr int kGridSize = 8192;
// The equal-energy bins cover this central share of m0 (the rest is thin tails).
constexpr double kTailShare = 0.001;

double jonswap_alpha(const SpectrumSpec& s) {
    return 0.076 * std::pow(s.wind_speed * s.wind_speed / (s.fetch * kGravity), 0.22);
}

double spectrum_alpha(const SpectrumSpec& s) {
    return s.kind == SpectrumKind::jonswap ? jonswap_alpha(s) : kPmAlpha;
}

/// Uniform double in [0, 1) from 53 random bits; unlike std::uniform_real_distribution
/// this is the same on every standard library.
double unit_uniform(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

struct CumulativeTable {
    std::vector<double> omega;
    std::vector<double> energy;  // integral of S from omega[0] to omega[i]
};

CumulativeTable cumulative_energy(const SpectrumSpec& s) {
    const double wp = peak_omega(s);
    const double lo = kLowFactor * wp, hi = kHighFactor * wp;
    CumulativeTable t;
    t.omega.resize(kGridSize);
    t.energy.resize(kGridSize);
    const double ratio = std::log(hi / lo) / (kGridSize - 1);
    double prev_w = lo, prev_s = spectral_density(s, lo), sum = 0.0;
    t.omega[0] = lo;
    t.energy[0] = 0.0;
    for (int i = 1; i < kGridSize; ++i) {
        const double w = lo * std::exp(ratio * i);
        const double sw = spectral_density(s, w);
        sum += 0.5 * (sw + prev_s) * (w - prev_w);
        t.omega[static_cast<std::size_t>(i)] = w;
        t.energy[static_cast<std::size_t>(i)] = sum;
        prev_w = w;
        prev_s = sw;
    }
    return t;
}

/// Frequency at which the cumulative energy reaches `e` (linear within a cell).
double omega_at_energy(const CumulativeTable& t, double e) {
    const auto it = std::lower_bound(t.energy.begin(), t.energy.end(), e);
    if (it == t.energy.begin()) return t.omega.front();
    if (it == t.energy.end()) return t.omega.back();
    const auto i = static_cast<std::size_t>(it - t.energy.begin());
    const double e0 = t.energy[i - 1], e1 = t.energy[i];
    const double f = e1 > e0 ? (e - e0) / (e1 - e0) : 0.0;
    return t.omega[i - 1] + f * (t.omega[i] - t.omega[i - 1]);
}

/// Direction offset (rad) drawn from D(a) ~ cos^(2s)(a/2) on [-pi, pi] by inverting its CDF.
double spread_offset(double spreading, double u) {
    if (spreading <= 0.0) return (2.0 * u - 1.0) * kPi;
    constexpr int n = 2048;
    std::vector<double> cdf(n + 1, 0.0);
    auto density = [&](double a) { return std::pow(std::cos(0.5 * a), 2.0 * spreading); };
    for (int i = 1; i <= n; ++i) {
        const double a0 = -kPi + kTwoPi * (i - 1) / n, a1 = -kPi + kTwoPi * i / n;
        cdf[static_cast<std::size_t>(i)] =
            cdf[static_cast<std::size_t>(i - 1)] + 0.5 * (density(a0) + density(a1)) * (a1 - a0);
    }
    const double target = u * cdf.back();
    const auto it = std::lower_bound(cdf.begin(), cdf.end(), target);
    const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - cdf.begin()));
    const double c0 = cdf[i - 1], c1 = cdf[i];
    const double f = c1 > c0 ? (target - c0) / (c1 - c0) : 0.0;
    return -kPi + kTwoPi * (static_cast<double>(i - 1) + f) / n;
}

}  // namespace

double peak_omega(const SpectrumSpec& s) {
    if (s.kind == SpectrumKind::pierson_moskowitz) return 0.877 * kGravity / s.wind_speed;
    return 22.0 * std::cbrt(kGravity * kGravity / (s.wind_speed * s.fetch));
}

double spectral_density(const SpectrumSpec& s, double omega) {
    if (omega <= 0.0) return 0.0;
    const double wp = peak_omega(s);
    const double r4 = std::pow(wp / omega, 4.0);
    const double pm = spectrum_alpha(s) * kGravity * kGravity * std::pow(omega, -5.0) * std::exp(-1.25 * r4);
    if (s.kind == SpectrumKind::pierson_moskowitz) return pm;
    const double sigma = omega <= wp ? 0.07 : 0.09;
    const double d = (omega - wp) / (sigma * wp);
    return pm * std::pow(s.peak_enhancement, std::exp(-0.5 * d * d));
}

double spectrum_significant_wave_height(const SpectrumSpec& s) {
    return 4.0 * std::sqrt(cumulative_energy(s).energy.back());
}

Status validate(const SpectrumSpec& s, const std::string& context) {
    auto bad = [&](const char* field, double v, const char* range) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/{}: {} is out of range (allowed: {})", context, field, v, range)};
    };
    if (!std::isfinite(s.wind_speed) || s.wind_speed <= 0.0 || s.wind_speed > 60.0)
        return bad("wind_speed", s.wind_speed, "0 < wind_speed <= 60 m/s");
    if (s.kind == SpectrumKind::jonswap) {
        if (!std::isfinite(s.fetch) || s.fetch < 1e3 || s.fetch > 1e7)
            return bad("fetch", s.fetch, "1000 <= fetch <= 1e7 m");
        if (!std::isfinite(s.peak_enhancement) || s.peak_enhancement < 1.0 || s.peak_enhancement > 10.0)
            return bad("peak_enhancement", s.peak_enhancement, "1 <= peak_enhancement <= 10");
    }
    if (!std::isfinite(s.mean_direction_deg) || std::abs(s.mean_direction_deg) > 1e6)
        return bad("direction", s.mean_direction_deg, "finite degrees");
    if (!std::isfinite(s.spreading) || s.spreading < 0.0 || s.spreading > 100.0)
        return bad("spreading", s.spreading, "0 <= spreading <= 100");
    if (s.wave_count < 1 || static_cast<std::size_t>(s.wave_count) > kMaxWaves)
        return bad("wave_count", s.wave_count, "1 <= wave_count <= 64");
    if (!std::isfinite(s.steepness) || s.steepness < 0.0 || s.steepness > 1.0)
        return bad("steepness", s.steepness, "0 <= steepness <= 1");
    return {};
}

Result<std::vector<WaveSpec>> generate_waves(const SpectrumSpec& s, const std::string& context) {
    if (auto st = validate(s, context); !st) return st.error();
    const CumulativeTable table = cumulative_energy(s);
    const double m0 = table.energy.back();
    const double lo = kTailShare * m0, hi = (1.0 - kTailShare) * m0;
    const int n = s.wave_count;
    const double bin_energy = (hi - lo) / n;

    std::mt19937_64 rng(s.seed);
    std::vector<WaveSpec> waves(static_cast<std::size_t>(n));
    double sum_ka = 0.0;
    for (int i = 0; i < n; ++i) {
        WaveSpec& w = waves[static_cast<std::size_t>(i)];
        // A frequency inside the bin (jittered so sets with different seeds differ),
        // carrying exactly the bin's energy.
        const double jitter = 0.2 + 0.6 * unit_uniform(rng);
        const double omega = omega_at_energy(table, lo + (i + jitter) * bin_energy);
        w.wavelength = deep_water_wavelength(omega);
        w.amplitude = std::sqrt(2.0 * bin_energy);
        w.direction_deg = s.mean_direction_deg + spread_offset(s.spreading, unit_uniform(rng)) * (180.0 / kPi);
        w.phase = kTwoPi * unit_uniform(rng);
        sum_ka += (kTwoPi / w.wavelength) * w.amplitude;
    }
    const double q = sum_ka > 0.0 ? std::min(1.0, s.steepness / sum_ka) : 0.0;
    for (WaveSpec& w : waves) w.steepness = q;
    return waves;
}

}  // namespace tidewater
