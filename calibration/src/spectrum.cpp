// Welch spectra (Eigen's FFT), sea-state summaries and sampling presets from a JONSWAP.
#include "tidewater/calibration/spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <unsupported/Eigen/FFT>

#include "jonswap_shape.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::calibration {

namespace {

double wrap_degrees(double d) {
    d = std::fmod(d, 360.0);
    return d < 0.0 ? d + 360.0 : d;
}

}  // namespace

Result<MeasuredSpectrum> welch_spectrum(const MeasuredRecord& r, const WelchOptions& options) {
    if (r.kind == RecordKind::profile)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: a profile has no frequency spectrum (fit it phase-resolved)", r.source)};
    const double dt = r.median_spacing();
    if (!(dt > 0.0)) return Error{ErrorCode::invalid_argument, fmt::format("{}: no sample spacing", r.source)};
    const auto seg = static_cast<std::size_t>(std::lround(options.segment_seconds / dt));
    if (seg < 16 || seg > r.size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} samples at {} s cannot fill a {} s spectral segment", r.source, r.size(), dt,
                                 options.segment_seconds)};
    const bool buoy = r.kind == RecordKind::buoy;
    // Uniform runs: a gap (spacing over 1.5 dt) ends a run; segments never cross one.
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t start = 0;
    for (std::size_t k = 1; k <= r.size(); ++k)
        if (k == r.size() || r.axis[k] - r.axis[k - 1] > 1.5 * dt) {
            runs.push_back({start, k});
            start = k;
        }
    std::vector<double> window(seg);
    double w2 = 0.0;
    for (std::size_t k = 0; k < seg; ++k) {
        window[k] = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(k) / static_cast<double>(seg));
        w2 += window[k] * window[k];
    }
    const std::size_t bins = seg / 2 + 1;
    MeasuredSpectrum s;
    s.df = 1.0 / (static_cast<double>(seg) * dt);
    s.directional = buoy;
    s.density.assign(bins, 0.0);
    std::vector<double> de(bins, 0.0), dn(bins, 0.0), ee(bins, 0.0), nn(bins, 0.0);
    Eigen::FFT<double> fft;
    std::vector<double> buf(seg);
    std::vector<std::complex<double>> Z, E, N;
    auto transform = [&](const std::vector<double>& v, std::size_t from, std::vector<std::complex<double>>& out) {
        double mean = 0.0;
        for (std::size_t k = 0; k < seg; ++k) mean += v[from + k];
        mean /= static_cast<double>(seg);
        for (std::size_t k = 0; k < seg; ++k) buf[k] = (v[from + k] - mean) * window[k];
        fft.fwd(out, buf);
    };
    for (const auto& [a, b] : runs)
        for (std::size_t from = a; from + seg <= b; from += seg / 2) {
            transform(r.z, from, Z);
            if (buoy) {
                transform(r.east, from, E);
                transform(r.north, from, N);
            }
            for (std::size_t f = 0; f < bins; ++f) {
                s.density[f] += std::norm(Z[f]);
                if (buoy) {
                    // Horizontal motion along the direction of travel lags heave by 90 degrees.
                    de[f] += -std::imag(std::conj(Z[f]) * E[f]);
                    dn[f] += -std::imag(std::conj(Z[f]) * N[f]);
                    ee[f] += std::norm(E[f]);
                    nn[f] += std::norm(N[f]);
                }
            }
            ++s.segments;
        }
    if (s.segments == 0)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: no gap-free stretch of {} s for a spectrum", r.source, options.segment_seconds)};
    // One-sided density: 2 |X|^2 dt / (sum w^2), averaged over segments.
    const double norm = 2.0 * dt / (w2 * s.segments);
    s.frequency.resize(bins);
    for (std::size_t f = 0; f < bins; ++f) {
        s.frequency[f] = static_cast<double>(f) * s.df;
        s.density[f] *= norm * (f == 0 || f + 1 == bins ? 0.5 : 1.0);
    }
    if (buoy) {
        s.travel_east.resize(bins), s.travel_north.resize(bins), s.r1.resize(bins);
        for (std::size_t f = 0; f < bins; ++f) {
            s.travel_east[f] = de[f];
            s.travel_north[f] = dn[f];
            const double denom = std::sqrt(s.density[f] / norm * (ee[f] + nn[f]));
            s.r1[f] = denom > 0.0 ? std::min(1.0, std::hypot(de[f], dn[f]) / denom) : 0.0;
        }
    }
    return s;
}

std::size_t MeasuredSpectrum::nearest_bin(double f) const {
    std::size_t best = 0;
    for (std::size_t k = 1; k < frequency.size(); ++k)
        if (std::abs(frequency[k] - f) < std::abs(frequency[best] - f)) best = k;
    return best;
}

SeaState summarize(const MeasuredSpectrum& s, double f_lo, double f_hi) {
    SeaState out;
    double m0 = 0.0, best = -1.0;
    std::size_t peak = 0;
    for (std::size_t f = 0; f < s.frequency.size(); ++f) {
        if (s.frequency[f] < f_lo || s.frequency[f] > f_hi) continue;
        m0 += s.density[f] * s.width(f);
        if (s.density[f] > best) best = s.density[f], peak = f;
    }
    out.hs = 4.0 * std::sqrt(m0);
    // Peak frequency refined by a parabola through the peak bin and its neighbours.
    double fp = s.frequency[peak];
    if (peak > 0 && peak + 1 < s.frequency.size()) {
        // The vertex of the parabola through the peak bin and its neighbours (any spacing).
        const double x0 = s.frequency[peak - 1], x1 = s.frequency[peak], x2 = s.frequency[peak + 1];
        const double y0 = s.density[peak - 1], y1 = s.density[peak], y2 = s.density[peak + 1];
        const double num = (x1 - x0) * (x1 - x0) * (y1 - y2) - (x1 - x2) * (x1 - x2) * (y1 - y0);
        const double den = (x1 - x0) * (y1 - y2) - (x1 - x2) * (y1 - y0);
        if (den != 0.0) fp = std::clamp(x1 - 0.5 * num / den, x0, x2);
    }
    out.tp = fp > 0.0 ? 1.0 / fp : 0.0;
    if (s.directional) {
        // Peak direction: the travel vector summed over the peak bin and its neighbours.
        double pe = 0.0, pn = 0.0, me = 0.0, mn = 0.0, r1 = 0.0, w = 0.0;
        for (std::size_t f = peak > 0 ? peak - 1 : 0; f <= std::min(peak + 1, s.frequency.size() - 1); ++f)
            pe += s.travel_east[f], pn += s.travel_north[f];
        for (std::size_t f = 0; f < s.frequency.size(); ++f) {
            if (s.frequency[f] < f_lo || s.frequency[f] > f_hi) continue;
            me += s.travel_east[f], mn += s.travel_north[f];
            if (s.frequency[f] > 0.7 * fp && s.frequency[f] < 1.5 * fp) r1 += s.r1[f] * s.density[f], w += s.density[f];
        }
        const double travel_peak = std::atan2(pn, pe) * 180.0 / kPi;
        out.peak_from_deg = wrap_degrees(270.0 - travel_peak);
        out.mean_travel_deg = wrap_degrees(std::atan2(mn, me) * 180.0 / kPi);
        const double r = w > 0.0 ? std::clamp(r1 / w, 0.0, 0.99) : 0.0;
        out.spreading_s = r / (1.0 - r);
    }
    return out;
}

double jonswap_density(double f, double hs, double tp, double gamma) {
    if (f <= 0.0 || tp <= 0.0) return 0.0;
    const double fp = 1.0 / tp;
    // Normalise numerically: the integral of the shape at this (tp, gamma), kept for the next call.
    static thread_local double cached_tp = -1.0, cached_gamma = -1.0, cached_integral = 0.0;
    if (tp != cached_tp || gamma != cached_gamma) {
        double integral = 0.0;
        const double df = fp / 400.0;
        for (double x = 0.3 * fp; x < 8.0 * fp; x += df) integral += detail::jonswap_shape(x, tp, gamma, x <= fp) * df;
        cached_tp = tp, cached_gamma = gamma, cached_integral = integral;
    }
    return hs * hs / 16.0 * detail::jonswap_shape(f, tp, gamma, f <= fp) / cached_integral;
}

Result<std::vector<WaveSpec>> sample_preset_waves(const JonswapFit& fit, int count, std::uint64_t seed, double fold) {
    if (count < 1 || count > static_cast<int>(kMaxWaves))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("wave count {} is out of range (1 to {})", count, kMaxWaves)};
    if (!(fit.hs > 0.0) || !(fit.tp > 0.0))
        return Error{ErrorCode::invalid_argument, "the fitted spectrum has no energy"};
    // Equal-energy frequency bands between 0.6 fp and 4 fp; each wave sits at its band's centroid.
    const double fp = 1.0 / fit.tp, lo = 0.6 * fp, hi = 4.0 * fp, df = (hi - lo) / 4000.0;
    std::vector<double> cumulative{0.0};
    for (int k = 0; k < 4000; ++k)
        cumulative.push_back(cumulative.back() + jonswap_density(lo + (k + 0.5) * df, fit.hs, fit.tp, fit.gamma) * df);
    const double total = cumulative.back();
    std::mt19937_64 rng(seed);
    auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<WaveSpec> waves(static_cast<std::size_t>(count));
    std::size_t k = 0;
    for (int i = 0; i < count; ++i) {
        const double e0 = total * i / count, e1 = total * (i + 1) / count;
        double fm = 0.0, em = 0.0;
        for (; k < 4000 && cumulative[k + 1] <= e1 + 1e-15 * total; ++k) {
            const double e = cumulative[k + 1] - std::max(cumulative[k], e0);
            fm += (lo + (static_cast<double>(k) + 0.5) * df) * e, em += e;
        }
        const double f = em > 0.0 ? fm / em : lo + (static_cast<double>(k) + 0.5) * df;
        const double omega = 2.0 * kPi * f;
        WaveSpec& w = waves[static_cast<std::size_t>(i)];
        w.wavelength = kTwoPi * kGravity / (omega * omega);
        w.amplitude = std::sqrt(2.0 * (e1 - e0));  // sum A^2 / 2 = m0
        // Directions: stratified quantiles of cos^2s((theta - mean)/2), deterministic.
        const double q = std::fmod((i + 0.5) * 0.6180339887498949, 1.0);
        double spread = 0.0;
        if (fit.spreading_s > 0.0) {
            // Inverse CDF by bisection on a tabulated density.
            const double s = fit.spreading_s;
            double a = -kPi, b = kPi;
            auto cdf = [&](double x) {
                double c = 0.0, all = 0.0;
                for (int n = 0; n < 720; ++n) {
                    const double th = -kPi + (n + 0.5) * kTwoPi / 720.0;
                    const double d = std::pow(std::cos(0.5 * th), 2.0 * s);
                    all += d;
                    if (th < x) c += d;
                }
                return c / all;
            };
            for (int it = 0; it < 30; ++it) {
                const double m = 0.5 * (a + b);
                (cdf(m) < q ? a : b) = m;
            }
            spread = 0.5 * (a + b) * 180.0 / kPi;
        }
        w.direction_deg = fit.mean_travel_deg + spread;
        w.phase = kTwoPi * uniform();
    }
    double sum = 0.0;
    for (const auto& w : waves) sum += kTwoPi / w.wavelength * w.amplitude;
    const double q = sum > 0.0 ? std::min(1.0, fold / sum) : 0.0;
    for (auto& w : waves) w.steepness = q;
    return waves;
}

}  // namespace tidewater::calibration
