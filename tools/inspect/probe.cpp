#include "probe.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "tidewater/constants.hpp"
#include "tidewater/query.hpp"

namespace tidewater::inspect {

Result<ProbeSeries> probe(const Scene& scene, glm::dvec2 at, const std::vector<double>& times) {
    if (times.size() < 16)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("probe: {} time steps, at least 16 make a spectrum", times.size())};
    if (!std::isfinite(at.x) || !std::isfinite(at.y))
        return Error{ErrorCode::invalid_argument, "probe: the point must be finite"};
    const double dt = (times.back() - times.front()) / static_cast<double>(times.size() - 1);
    ProbeSeries p;
    p.at = at;
    p.time = times;
    p.height.resize(times.size());
    const std::vector<glm::dvec2> where{at};
    std::vector<SurfacePoint> out(1);
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (auto st = query_surface(scene.ocean, times[k], where, out); !st) return st.error();
        p.height[k] = out[0].height;
    }
    // Hann-windowed, zero-padded x8 periodogram.
    const std::size_t n = times.size(), padded = 8 * n;
    double mean = 0.0, w2 = 0.0;
    for (double h : p.height) mean += h;
    mean /= static_cast<double>(n);
    std::vector<double> buf(padded, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double w = 0.5 - 0.5 * std::cos(kTwoPi * static_cast<double>(k) / static_cast<double>(n - 1));
        buf[k] = (p.height[k] - mean) * w;
        w2 += w * w;
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, buf);
    const std::size_t bins = padded / 2 + 1;
    p.frequency.resize(bins), p.power.resize(bins);
    // The peak search starts at one cycle per record (bin 8 with x8 padding).
    std::size_t peak = 8;
    for (std::size_t b = 0; b < bins; ++b) {
        p.frequency[b] = static_cast<double>(b) / (static_cast<double>(padded) * dt);
        p.power[b] = 2.0 * std::norm(spectrum[b]) * dt / w2;
        if (b > 8 && p.power[b] > p.power[peak]) peak = b;
    }
    double variance = 0.0;
    for (double h : p.height) variance += (h - mean) * (h - mean);
    if (!(variance > 1e-12 * static_cast<double>(n))) return p;  // still water or dry land: no period
    double f = p.frequency[peak];
    if (peak + 1 < bins && peak > 0) {
        const double a = p.power[peak - 1], b = p.power[peak], c = p.power[peak + 1];
        const double den = a - 2.0 * b + c;
        if (den < 0.0) f += 0.5 * (a - c) / den * (p.frequency[1] - p.frequency[0]);
    }
    p.dominant_period = f > 0.0 ? 1.0 / f : 0.0;
    return p;
}

}  // namespace tidewater::inspect
