// The JONSWAP fit (Ceres, automatic differentiation). The fitted sea keeps the
// record's energy: Hs is the measured 4 sqrt(m0) over the band, and Ceres fits the
// shape (Tp, gamma) by least squares on the density around the dominant peak.
#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "jet_scalar.hpp"
#include "jonswap_shape.hpp"
#include "tidewater/calibration/spectrum.hpp"

namespace tidewater::calibration {

namespace {

using detail::jonswap_shape;
using detail::scalar;

/// Residuals over the band: (m0 shape_i / sum_j shape_j df - S_i) / S_peak.
struct ShapeResiduals {
    std::vector<double> f, s, w;  // centre, density and width of each bin
    double m0 = 0.0, peak = 1.0;

    template <typename T>
    bool operator()(T const* const* parameters, T* residuals) const {
        return evaluate(parameters[0], parameters[1], residuals);
    }

    template <typename T>
    bool evaluate(const T* tp, const T* gamma, T* residuals) const {
        std::vector<T> shape(f.size());
        T sum(0.0);
        for (std::size_t k = 0; k < f.size(); ++k) {
            shape[k] = jonswap_shape(f[k], tp[0], gamma[0], f[k] <= 1.0 / scalar(tp[0]));
            sum += shape[k] * w[k];
        }
        for (std::size_t k = 0; k < f.size(); ++k) residuals[k] = (m0 * shape[k] / sum - s[k]) / peak;
        return true;
    }
};

}  // namespace

Result<JonswapFit> fit_jonswap(const MeasuredSpectrum& spectrum, double f_lo, double f_hi) {
    auto guard = std::make_unique<ShapeResiduals>();
    ShapeResiduals* residuals = guard.get();
    const SeaState measured = summarize(spectrum, f_lo, f_hi);
    // One JONSWAP describes one sea: its shape is fitted around the dominant peak
    // (0.6 to 2.5 fp); the energy is the whole band's.
    const double fp = measured.tp > 0.0 ? 1.0 / measured.tp : f_lo;
    const double lo = std::max(f_lo, 0.6 * fp), hi = std::min(f_hi, 2.5 * fp);
    double band_m0 = 0.0;
    for (std::size_t k = 0; k < spectrum.frequency.size(); ++k) {
        const double f = spectrum.frequency[k];
        if (f >= f_lo && f <= f_hi) band_m0 += spectrum.density[k] * spectrum.width(k);
        if (f >= lo && f <= hi && f > 0.0) {
            residuals->f.push_back(f);
            residuals->s.push_back(spectrum.density[k]);
            residuals->w.push_back(spectrum.width(k));
        }
    }
    if (residuals->f.size() < 4)
        return Error{ErrorCode::invalid_argument, fmt::format("the spectrum has {} bins in {}-{} Hz: too few to fit",
                                                              residuals->f.size(), f_lo, f_hi)};
    for (std::size_t k = 0; k < residuals->s.size(); ++k) residuals->m0 += residuals->s[k] * residuals->w[k];
    residuals->peak = *std::max_element(residuals->s.begin(), residuals->s.end());
    if (!(residuals->m0 > 0.0) || !(band_m0 > 0.0))
        return Error{ErrorCode::invalid_argument, "the spectrum has no energy in the band"};

    double tp = std::clamp(measured.tp, 1.0, 40.0), gamma = 3.3;
    ceres::Problem problem;
    const int count = static_cast<int>(residuals->f.size());
    auto* cost = new ceres::DynamicAutoDiffCostFunction<ShapeResiduals, 4>(guard.release());
    cost->AddParameterBlock(1);
    cost->AddParameterBlock(1);
    cost->SetNumResiduals(count);
    problem.AddResidualBlock(cost, nullptr, &tp, &gamma);
    problem.SetParameterLowerBound(&tp, 0, 1.0);
    problem.SetParameterUpperBound(&tp, 0, 40.0);
    problem.SetParameterLowerBound(&gamma, 0, 1.0);
    problem.SetParameterUpperBound(&gamma, 0, 20.0);
    ceres::Solver::Options options;
    options.max_num_iterations = 100;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);

    JonswapFit fit;
    fit.hs = 4.0 * std::sqrt(band_m0);
    fit.tp = tp;
    fit.gamma = gamma;
    fit.iterations = static_cast<int>(summary.iterations.size());
    fit.mean_travel_deg = measured.mean_travel_deg;
    fit.spreading_s = measured.spreading_s;
    if (spectrum.directional) {
        // The peak direction: the bin holding the fitted peak frequency (CDIP's Dp is its peak band's).
        const std::size_t bin = spectrum.nearest_bin(1.0 / fit.tp);
        if (bin < spectrum.frequency.size()) {
            const double travel =
                std::atan2(spectrum.travel_north[bin], spectrum.travel_east[bin]) * 180.0 / 3.14159265358979323846;
            fit.peak_from_deg = std::fmod(270.0 - travel + 720.0, 360.0);
        }
    }
    std::vector<double> r(residuals->f.size());
    residuals->evaluate(&tp, &gamma, r.data());
    double mean = 0.0, tss = 0.0, rss = 0.0;
    for (double v : residuals->s) mean += v;
    mean /= count;
    for (std::size_t k = 0; k < r.size(); ++k) {
        rss += r[k] * r[k] * residuals->peak * residuals->peak;
        tss += (residuals->s[k] - mean) * (residuals->s[k] - mean);
    }
    fit.r2 = tss > 0.0 ? 1.0 - rss / tss : 0.0;
    return fit;
}

}  // namespace tidewater::calibration
