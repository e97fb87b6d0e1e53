// The phase-resolved fit (Ceres, automatic differentiation).
#include "tidewater/calibration/phase_fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <thread>

#include "jet_scalar.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/newton.hpp"
#include "tidewater/detail/water_point.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::calibration {

namespace {

constexpr double kFoldLimit = 0.95;  // sum(Q k A), as the runtime's shore steepness cap
constexpr std::size_t kChunk = 32;   // samples per residual block

using detail::scalar;
using tidewater::detail::add_wave;
using tidewater::detail::newton_radius;
using tidewater::detail::newton_tolerance;
using tidewater::detail::solve_rest_offset;
using tidewater::detail::SurfaceSums;
using tidewater::detail::wave_term;
using tidewater::detail::WaveTerm;

/// Parameters per wave: amplitude, omega (profile: k), phase, Q, and for a buoy the direction.
int stride(RecordKind kind) {
    return kind == RecordKind::buoy ? 5 : 4;
}

/// Finite-depth wavenumber (the runtime's solver); derivatives through one Newton step
/// from the converged value.
template <typename T>
T wavenumber(const T& omega, double depth) {
    if (!std::isfinite(depth)) return omega * omega / kGravity;
    const double k = wavenumber_at_depth(scalar(omega), depth);
    const double t = std::tanh(k * depth);
    const double df = kGravity * (t + k * depth * (1.0 - t * t));
    return T(k) - (T(kGravity * k * t) - omega * omega) / df;
}

/// The Gerstner model at one sample.
struct Model {
    RecordKind kind;
    double depth;
    int waves;

    /// Each wave's wavenumber (a profile fits k itself).
    template <typename T>
    void wavenumbers(const T* p, std::array<T, 64>& k) const {
        const auto m = static_cast<std::size_t>(stride(kind));
        for (std::size_t i = 0; i < static_cast<std::size_t>(waves); ++i)
            k[i] = kind == RecordKind::profile ? p[m * i + 1] : wavenumber(p[m * i + 1], depth);
    }

    /// Each wave's coefficients along the record's axis (direction +x): they depend on
    /// the parameters only, so a chunk of samples forms them once.
    template <typename T>
    struct AxisWaves {
        std::array<T, 64> k;
        std::array<WaveTerm<T>, 64> terms;
    };

    template <typename T>
    void axis_waves(const T* p, AxisWaves<T>& out) const {
        const auto m = static_cast<std::size_t>(stride(kind));
        wavenumbers(p, out.k);
        for (std::size_t i = 0; i < static_cast<std::size_t>(waves); ++i)
            out.terms[i] = wave_term<T>(out.k[i], T(0.0), p[m * i], p[m * i + 3], T(0.0));
    }

    /// The runtime's water evaluation along the axis at rest offset alpha: phase k alpha + c.
    template <typename T>
    SurfaceSums<T> along_axis(const AxisWaves<T>& w, const std::array<T, 64>& c, const T& alpha) const {
        SurfaceSums<T> s;
        for (std::size_t i = 0; i < static_cast<std::size_t>(waves); ++i)
            add_wave<false>(s, w.terms[i], w.k[i] * alpha + c[i]);
        return s;
    }

    /// The water along the axis at rest offsets from the target, for the Newton solve.
    struct AxisWater {
        const Model* model;
        const AxisWaves<double>* w;
        const std::array<double, 64>* c;  // phases at the target
        template <bool kVelocity>
        SurfaceSums<double> evaluate(double ex, double) const {
            return model->along_axis(*w, *c, ex);
        }
        void record(bool) {}
    };

    /// Solves alpha + sum Q A cos(k alpha + c) = target for the Eulerian records; returns z.
    /// `wd` holds the same waves in double. `known_alpha` skips the double-precision solve
    /// (the same parameters, another Jet pass); `solved_alpha` receives it.
    template <typename T>
    T eulerian(const T* p, const AxisWaves<T>& w, const AxisWaves<double>& wd, double sum_qa, double axis,
               const double* known_alpha, double* solved_alpha) const {
        const auto m = static_cast<std::size_t>(stride(kind));
        const auto n = static_cast<std::size_t>(waves);
        // Per wave, the phase part that does not depend on alpha.
        std::array<T, 64> c;
        for (std::size_t i = 0; i < n; ++i) {
            const T* wave = p + m * i;
            c[i] = kind == RecordKind::profile ? wave[2] : wave[2] - wave[1] * axis;
        }
        const double target = kind == RecordKind::profile ? axis : 0.0;
        // The runtime's Newton solve on the values, as a rest offset from the target.
        double a = target;
        if (known_alpha) {
            a = *known_alpha;
        } else {
            std::array<double, 64> cd;
            for (std::size_t i = 0; i < n; ++i) cd[i] = scalar(c[i]) + wd.k[i] * target;
            AxisWater water{this, &wd, &cd};
            const auto r = solve_rest_offset<false, double>(water, newton_tolerance(sum_qa), newton_radius(sum_qa));
            a = target + r.ex + r.step_x;
        }
        if (solved_alpha) *solved_alpha = a;
        // One Newton step in T gives alpha's exact first derivatives (implicit function
        // theorem); z is carried along it to first order, as the query kernel does.
        const SurfaceSums<T> at = along_axis(w, c, T(a));
        const T f = T(a - target) + at.dx, df = T(1.0) - at.mxx;
        const T slope = scalar(df) > 0.05 ? df : T(1.0);  // where the map folds, a plain fixed-point step
        return at.eta - at.sx * f / slope;
    }

    template <typename T>
    static double sum_qa(const T* p, int m, int n) {
        double s = 0.0;
        for (int i = 0; i < n; ++i) s += std::abs(scalar(p[m * i + 3]) * scalar(p[m * i]));
        return s;
    }

    double eulerian(const double* p, double axis) const {
        AxisWaves<double> w;
        axis_waves(p, w);
        return eulerian(p, w, w, sum_qa(p, stride(kind), waves), axis, nullptr, nullptr);
    }

    /// Each buoy wave's coefficients (direction w[4]); formed once per chunk.
    template <typename T>
    void buoy_waves(const T* p, std::array<WaveTerm<T>, 64>& terms) const {
        using std::cos;
        using std::sin;
        std::array<T, 64> k;
        wavenumbers(p, k);
        for (std::size_t i = 0; i < static_cast<std::size_t>(waves); ++i) {
            const T* w = p + 5 * i;
            terms[i] = wave_term<T>(k[i] * cos(w[4]), k[i] * sin(w[4]), w[0], w[3], w[1]);
        }
    }

    /// Heave, east and north of the buoy at rest position 0: the runtime's water evaluation.
    template <typename T>
    void lagrangian(const T* p, const std::array<WaveTerm<T>, 64>& terms, double t, T* out) const {
        SurfaceSums<T> s;
        for (std::size_t i = 0; i < static_cast<std::size_t>(waves); ++i)
            add_wave<false>(s, terms[i], p[5 * i + 2] - p[5 * i + 1] * t);
        out[0] = s.eta;
        out[1] = s.dx;
        out[2] = s.dz;
    }

    void lagrangian(const double* p, double t, double* out) const {
        std::array<WaveTerm<double>, 64> terms;
        buoy_waves(p, terms);
        lagrangian(p, terms, t, out);
    }
};

/// Residuals of a chunk of samples. Ceres evaluates a block's Jacobian in several Jet
/// passes with the same parameter values: the double-precision Eulerian solves are kept
/// from the first pass for the others. (A block is never evaluated by two threads at once.)
struct ChunkResiduals {
    Model model;
    const MeasuredRecord* record;
    std::size_t first, count;
    int parameters;
    mutable std::vector<double> cached_values, cached_alpha;

    template <typename T>
    bool operator()(T const* const* blocks, T* residuals) const {
        const T* p = blocks[0];
        if (model.kind == RecordKind::buoy) {
            std::array<WaveTerm<T>, 64> terms;
            model.buoy_waves(p, terms);
            for (std::size_t j = 0; j < count; ++j) {
                const std::size_t s = first + j;
                T out[3];
                model.lagrangian(p, terms, record->axis[s], out);
                residuals[3 * j] = out[0] - record->z[s];
                residuals[3 * j + 1] = out[1] - record->east[s];
                residuals[3 * j + 2] = out[2] - record->north[s];
            }
            return true;
        }
        bool same = cached_values.size() == static_cast<std::size_t>(parameters) && cached_alpha.size() == count;
        for (int i = 0; same && i < parameters; ++i) same = cached_values[static_cast<std::size_t>(i)] == scalar(p[i]);
        if (!same) {
            cached_values.resize(static_cast<std::size_t>(parameters));
            for (int i = 0; i < parameters; ++i) cached_values[static_cast<std::size_t>(i)] = scalar(p[i]);
            cached_alpha.assign(count, 0.0);
        }
        Model::AxisWaves<T> w;
        model.axis_waves(p, w);
        Model::AxisWaves<double> wd;
        std::vector<double> plain(static_cast<std::size_t>(parameters));
        for (int i = 0; i < parameters; ++i) plain[static_cast<std::size_t>(i)] = scalar(p[i]);
        model.axis_waves(plain.data(), wd);
        const double qa = Model::sum_qa(p, stride(model.kind), model.waves);
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t s = first + j;
            residuals[j] = model.eulerian(p, w, wd, qa, record->axis[s], same ? &cached_alpha[j] : nullptr,
                                          same ? nullptr : &cached_alpha[j]) -
                           record->z[s];
        }
        return true;
    }
};

/// Pushes sum(Q k A) back under the fold limit.
struct FoldPenalty {
    Model model;
    double weight;

    template <typename T>
    bool operator()(T const* const* parameters, T* residual) const {
        const T* p = parameters[0];
        const int m = stride(model.kind);
        T sum(0.0);
        for (int i = 0; i < model.waves; ++i) {
            const T* w = p + m * i;
            const T k = model.kind == RecordKind::profile ? w[1] : wavenumber(w[1], model.depth);
            sum += w[3] * k * w[0];
        }
        residual[0] = scalar(sum) > kFoldLimit ? (sum - kFoldLimit) * weight : T(0.0);
        return true;
    }
};

struct Peak {
    double frequency;  // rad per unit of the axis (omega, or k for a profile)
    double power;
};

/// Periodogram of `v` on bins w_min + b dw, each sample weighted by its spacing, so gaps
/// and uneven spacing (a profile clustered at the crest) do not bias it.
std::vector<double> periodogram(const MeasuredRecord& r, const std::vector<double>& v, double w_min, double dw,
                                std::size_t bins) {
    const double spacing = r.median_spacing();
    std::vector<double> weight(r.size());
    double mean = 0.0, total = 0.0;
    for (std::size_t s = 0; s < r.size(); ++s) {
        const double before = s > 0 ? r.axis[s] - r.axis[s - 1] : 0.0,
                     after = s + 1 < r.size() ? r.axis[s + 1] - r.axis[s] : 0.0;
        weight[s] = 0.5 * (std::min(before, 2.0 * spacing) + std::min(after, 2.0 * spacing));
        mean += v[s] * weight[s], total += weight[s];
    }
    mean /= total;
    std::vector<std::complex<double>> sum(bins, 0.0);
    for (std::size_t s = 0; s < r.size(); ++s) {
        std::complex<double> phasor = std::polar(1.0, -w_min * r.axis[s]);
        const std::complex<double> step = std::polar(1.0, -dw * r.axis[s]);
        const double x = (v[s] - mean) * weight[s];
        for (std::size_t b = 0; b < bins; ++b) {
            sum[b] += x * phasor;
            phasor *= step;
        }
    }
    std::vector<double> power(bins);
    for (std::size_t b = 0; b < bins; ++b) power[b] = std::norm(sum[b]);
    return power;
}

/// Least squares of sines and cosines at the given frequencies: coefficients and residual.
Eigen::VectorXd linear_fit(const MeasuredRecord& r, const std::vector<double>& v, const std::vector<double>& freqs,
                           std::vector<double>* residual) {
    const auto rows = static_cast<Eigen::Index>(r.size());
    const auto n = static_cast<Eigen::Index>(freqs.size());
    Eigen::MatrixXd design(rows, 2 * n);
    for (Eigen::Index s = 0; s < rows; ++s)
        for (Eigen::Index i = 0; i < n; ++i) {
            const double th = freqs[static_cast<std::size_t>(i)] * r.axis[static_cast<std::size_t>(s)];
            design(s, 2 * i) = std::cos(th);
            design(s, 2 * i + 1) = std::sin(th);
        }
    const Eigen::Map<const Eigen::VectorXd> rhs(v.data(), rows);
    Eigen::VectorXd c = design.colPivHouseholderQr().solve(rhs);
    if (residual) {
        const Eigen::VectorXd res = rhs - design * c;
        residual->assign(res.data(), res.data() + rows);
    }
    return c;
}

/// `count` frequencies by orthogonal matching pursuit: the strongest periodogram bin of
/// what the frequencies so far leave unexplained, at least one resolution (2 pi / span)
/// from those taken, then a joint least-squares fit, until `count` are taken.
std::vector<Peak> spectral_peaks(const MeasuredRecord& r, int count) {
    const double span = r.axis.back() - r.axis.front();
    const double resolution = kTwoPi / span;
    const double w_min = resolution, w_max = kPi / r.median_spacing();
    const double dw = resolution / 4.0;  // 4x oversampled
    const auto bins = static_cast<std::size_t>((w_max - w_min) / dw) + 1;
    std::vector<Peak> peaks;
    std::vector<double> freqs, residual = r.z;
    for (int i = 0; i < count; ++i) {
        const std::vector<double> power = periodogram(r, residual, w_min, dw, bins);
        double best = -1.0, at = 0.0;
        for (std::size_t b = 0; b < bins; ++b) {
            const double w = w_min + dw * static_cast<double>(b);
            if (power[b] <= best) continue;
            if (std::any_of(freqs.begin(), freqs.end(), [&](double f) { return std::abs(f - w) < resolution; }))
                continue;
            best = power[b], at = w;
        }
        if (best <= 0.0) break;
        freqs.push_back(at);
        peaks.push_back({at, best});
        linear_fit(r, r.z, freqs, &residual);
    }
    return peaks;
}

/// Initial parameters: linear least squares of sines and cosines at the peak frequencies.
/// `linear_rss` gets the elevation's residual sum of squares of that linear fit.
std::vector<double> initial_parameters(const MeasuredRecord& r, const std::vector<Peak>& peaks,
                                       double* linear_rss = nullptr) {
    const int n = static_cast<int>(peaks.size()), m = stride(r.kind);
    std::vector<double> freqs;
    for (const Peak& p : peaks) freqs.push_back(p.frequency);
    std::vector<double> residual;
    const Eigen::VectorXd cz = linear_fit(r, r.z, freqs, &residual);
    if (linear_rss) {
        *linear_rss = 0.0;
        for (double v : residual) *linear_rss += v * v;
    }
    Eigen::VectorXd ce, cn;
    if (r.kind == RecordKind::buoy)
        ce = linear_fit(r, r.east, freqs, nullptr), cn = linear_fit(r, r.north, freqs, nullptr);
    std::vector<double> p(static_cast<std::size_t>(m * n), 0.0);
    for (int i = 0; i < n; ++i) {
        double* w = p.data() + m * i;
        const double a = cz(2 * i), b = cz(2 * i + 1);
        w[0] = std::hypot(a, b);
        w[1] = peaks[static_cast<std::size_t>(i)].frequency;
        // gauge/buoy: A sin(phase - omega t) = A sin(phase) cos - A cos(phase) sin; profile: A sin(k x + phase).
        w[2] = r.kind == RecordKind::profile ? std::atan2(a, b) : std::atan2(a, -b);
        w[3] = 0.3;
        if (r.kind == RecordKind::buoy) {
            const double cp = std::cos(w[2]), sp = std::sin(w[2]);
            const double he = ce(2 * i) * cp + ce(2 * i + 1) * sp, hn = cn(2 * i) * cp + cn(2 * i + 1) * sp;
            w[3] = w[0] > 0.0 ? std::clamp(std::hypot(he, hn) / w[0], 0.0, 1.0) : 0.0;
            w[4] = std::atan2(hn, he);
        }
    }
    return p;
}

struct Solved {
    std::vector<double> p;
    double rss = 0.0;
    int iterations = 0;
    bool converged = false;
    std::unique_ptr<ceres::Problem> problem;
};

Solved solve(const MeasuredRecord& r, std::vector<double> p, int waves, const PhaseFitOptions& o, double huber) {
    const Model model{r.kind, r.depth, waves};
    const int m = stride(r.kind);
    const double resolution = kTwoPi / (r.axis.back() - r.axis.front());
    auto problem = std::make_unique<ceres::Problem>();
    const int per_sample = r.kind == RecordKind::buoy ? 3 : 1;
    for (std::size_t first = 0; first < r.size(); first += kChunk) {
        const std::size_t count = std::min(kChunk, r.size() - first);
        auto* cost = new ceres::DynamicAutoDiffCostFunction<ChunkResiduals, 16>(
            new ChunkResiduals{model, &r, first, count, m * waves, {}, {}});
        cost->AddParameterBlock(m * waves);
        cost->SetNumResiduals(static_cast<int>(count) * per_sample);
        problem->AddResidualBlock(cost, huber > 0.0 ? new ceres::HuberLoss(huber) : nullptr, p.data());
    }
    double scale = 0.0;
    for (double v : r.z) scale = std::max(scale, std::abs(v));
    auto* fold = new ceres::DynamicAutoDiffCostFunction<FoldPenalty, 8>(
        new FoldPenalty{model, 100.0 * scale * std::sqrt(double(r.size()))});
    fold->AddParameterBlock(m * waves);
    fold->SetNumResiduals(1);
    problem->AddResidualBlock(fold, nullptr, p.data());
    for (int i = 0; i < waves; ++i) {
        const double w0 = p[static_cast<std::size_t>(m * i + 1)];
        problem->SetParameterLowerBound(p.data(), m * i, 0.0);
        problem->SetParameterUpperBound(p.data(), m * i, 4.0 * scale + 1e-9);
        // Each wave stays within a quarter of a frequency resolution of its start: waves
        // that drift together can grow large and cancel, fitting noise.
        problem->SetParameterLowerBound(p.data(), m * i + 1, std::max(0.5 * w0, w0 - 0.25 * resolution));
        problem->SetParameterUpperBound(p.data(), m * i + 1, w0 + 0.25 * resolution);
        problem->SetParameterLowerBound(p.data(), m * i + 3, 0.0);
        problem->SetParameterUpperBound(p.data(), m * i + 3, 1.0);
    }
    ceres::Solver::Options options;
    options.max_num_iterations = o.max_iterations;
    options.num_threads =
        static_cast<int>(o.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : o.threads);
    options.linear_solver_type = ceres::DENSE_QR;
    options.logging_type = ceres::SILENT;
    options.function_tolerance = 1e-9;
    options.parameter_tolerance = 1e-9;
    // Long fits report every 10 iterations.
    struct Progress : ceres::IterationCallback {
        const PhaseFitOptions* o;
        int waves;
        ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
            if (s.iteration > 0 && s.iteration % 10 == 0)
                o->progress(fmt::format("fit: {} waves, iteration {}, cost {:.4g}", waves, s.iteration, s.cost));
            return ceres::SOLVER_CONTINUE;
        }
    } progress;
    progress.o = &o;
    progress.waves = waves;
    if (o.progress) options.callbacks.push_back(&progress);
    ceres::Solver::Summary summary;
    ceres::Solve(options, problem.get(), &summary);
    Solved out;
    out.iterations = static_cast<int>(summary.iterations.size());
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    // Plain residual sum of squares of the elevation (not the robust cost).
    const Model plain{r.kind, r.depth, waves};
    for (std::size_t s = 0; s < r.size(); ++s) {
        double z = 0.0;
        if (r.kind == RecordKind::buoy) {
            double o3[3];
            plain.lagrangian(p.data(), r.axis[s], o3);
            z = o3[0];
        } else {
            z = plain.eulerian(p.data(), r.axis[s]);
        }
        out.rss += (z - r.z[s]) * (z - r.z[s]);
    }
    out.p = std::move(p);
    out.problem = std::move(problem);
    return out;
}

double wrap(double a) {
    a = std::fmod(a, kTwoPi);
    return a < 0.0 ? a + kTwoPi : a;
}

}  // namespace

double FittedWave::period() const {
    return omega > 0.0 ? kTwoPi / omega : 0.0;
}

Result<PhaseFit> fit_phase_resolved(const MeasuredRecord& r, const PhaseFitOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = validate_record(r); !st) return st.error();
    if (o.waves < 0 || o.waves > 64 || o.max_waves < 1 || o.max_waves > 64)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("wave count {} / max {} out of range (1 to 64)", o.waves, o.max_waves)};
    if (!(r.depth > 0.0)) return Error{ErrorCode::invalid_argument, fmt::format("{}: depth must be > 0 m", r.source)};
    const int m = stride(r.kind);
    const int per_sample = r.kind == RecordKind::buoy ? 3 : 1;
    const int sample_limit = static_cast<int>(r.size() * static_cast<std::size_t>(per_sample)) / (2 * m);
    if (o.waves > sample_limit)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} waves need at least {} samples, the record has {}", r.source, o.waves,
                                 2 * m * o.waves, r.size())};
    const int top = o.waves > 0 ? o.waves : std::min(o.max_waves, sample_limit);
    if (top < 1) return Error{ErrorCode::invalid_argument, fmt::format("{}: too few samples for one wave", r.source)};
    const std::vector<Peak> peaks = spectral_peaks(r, top);
    if (peaks.empty())
        return Error{ErrorCode::invalid_argument, fmt::format("{}: the record has no spectral peak", r.source)};

    // Huber scale from the linear fit's residuals (robust spread).
    double tss = 0.0, mean = 0.0;
    for (double v : r.z) mean += v;
    mean /= static_cast<double>(r.size());
    for (double v : r.z) tss += (v - mean) * (v - mean);

    // Model order: BIC of the linear fits at the strongest peaks (cheap), then Ceres on the chosen one.
    std::vector<int> ladder;
    if (o.waves > 0) {
        ladder = {std::min<int>(o.waves, static_cast<int>(peaks.size()))};
    } else {
        for (int n = 1; n <= static_cast<int>(peaks.size()); n += std::max(1, n / 4)) ladder.push_back(n);
    }
    PhaseFit out;
    double best_bic = INFINITY;
    int best_n = ladder.front();
    for (int n : ladder) {
        double rss = 0.0;
        initial_parameters(r, std::vector<Peak>(peaks.begin(), peaks.begin() + n), &rss);
        // A buoy's horizontal motion adds residuals but the order is judged on the heave.
        const double samples = static_cast<double>(r.size());
        const double bic = samples * std::log(std::max(rss, 1e-300) / samples) + 2.0 * n * std::log(samples);
        out.bic.push_back({n, bic});
        if (bic < best_bic) best_bic = bic, best_n = n;
    }
    if (o.progress && ladder.size() > 1)
        o.progress(fmt::format("fit: {} waves chosen by BIC (of {} tried)", best_n, ladder.size()));
    const double huber = 3.0 * std::sqrt(tss / static_cast<double>(r.size()));
    Solved best =
        solve(r, initial_parameters(r, std::vector<Peak>(peaks.begin(), peaks.begin() + best_n)), best_n, o, huber);
    if (r.kind == RecordKind::profile) {
        // A profile often spans whole wavelengths, where a one-cycle window shifts the
        // periodogram's peak: also start from the harmonics of the span and keep the better.
        std::vector<Peak> harmonics;
        const double span = r.axis.back() - r.axis.front();
        for (int i = 1; i <= best_n; ++i) harmonics.push_back({kTwoPi * i / span, 0.0});
        Solved other = solve(r, initial_parameters(r, harmonics), best_n, o, huber);
        if (other.rss < best.rss) best = std::move(other);
    }
    if (o.progress)
        o.progress(
            fmt::format("fit: {} waves, R^2 {:.4f}, {} iterations", best_n, 1.0 - best.rss / tss, best.iterations));
    // Uncertainties from Ceres' covariance of the chosen fit.
    std::vector<double> sigma(best.p.size(), -1.0);
    {
        ceres::Covariance::Options co;
        co.algorithm_type = ceres::DENSE_SVD;
        co.null_space_rank = -1;
        co.num_threads = 1;
        ceres::Covariance covariance(co);
        const double* block = best.p.data();
        std::vector<std::pair<const double*, const double*>> blocks{{block, block}};
        if (covariance.Compute(blocks, best.problem.get())) {
            std::vector<double> c(best.p.size() * best.p.size());
            if (covariance.GetCovarianceBlock(block, block, c.data()))
                for (std::size_t k = 0; k < best.p.size(); ++k)
                    sigma[k] = std::sqrt(std::max(0.0, c[k * best.p.size() + k]));
        }
    }
    const Model model{r.kind, r.depth, best_n};
    out.model_z.resize(r.size());
    double rss_h = 0.0, tss_h = 0.0, me = 0.0, mn = 0.0;
    if (r.kind == RecordKind::buoy) {
        for (std::size_t s = 0; s < r.size(); ++s) me += r.east[s], mn += r.north[s];
        me /= static_cast<double>(r.size()), mn /= static_cast<double>(r.size());
    }
    for (std::size_t s = 0; s < r.size(); ++s) {
        if (r.kind == RecordKind::buoy) {
            double o3[3];
            model.lagrangian(best.p.data(), r.axis[s], o3);
            out.model_z[s] = o3[0];
            rss_h += (o3[1] - r.east[s]) * (o3[1] - r.east[s]) + (o3[2] - r.north[s]) * (o3[2] - r.north[s]);
            tss_h += (r.east[s] - me) * (r.east[s] - me) + (r.north[s] - mn) * (r.north[s] - mn);
        } else {
            out.model_z[s] = model.eulerian(best.p.data(), r.axis[s]);
        }
    }
    out.rmse = std::sqrt(best.rss / static_cast<double>(r.size()));
    out.r2 = 1.0 - best.rss / tss;
    out.horizontal_r2 = tss_h > 0.0 ? 1.0 - rss_h / tss_h : 0.0;
    out.iterations = best.iterations;
    out.converged = best.converged;
    for (int i = 0; i < best_n; ++i) {
        const double* w = best.p.data() + m * i;
        const double* sg = sigma.data() + m * i;
        FittedWave f;
        f.amplitude = w[0];
        f.phase = wrap(w[2]);
        f.steepness = w[3];
        if (r.kind == RecordKind::profile) {
            f.k = w[1];
            f.omega = std::isfinite(r.depth) ? std::sqrt(kGravity * f.k * std::tanh(f.k * r.depth))
                                             : std::sqrt(kGravity * f.k);
        } else {
            f.omega = w[1];
            f.k = wavenumber(w[1], r.depth);
        }
        f.direction_deg = r.kind == RecordKind::buoy ? wrap(w[4]) * 180.0 / kPi : 0.0;
        f.amplitude_sigma = sg[0];
        if (sg[1] >= 0.0) f.period_sigma = r.kind == RecordKind::profile ? -1.0 : kTwoPi / (w[1] * w[1]) * sg[1];
        f.phase_sigma = sg[2];
        f.steepness_sigma = sg[3];
        if (r.kind == RecordKind::buoy && sg[4] >= 0.0) f.direction_sigma_deg = sg[4] * 180.0 / kPi;
        // A wave with no amplitude has no phase: flip to keep A >= 0 (bounds already do).
        out.waves.push_back(f);
    }
    // The penalty is soft: make the set fold-free for certain, with the model's k and
    // with the deep-water k the runtime uses (the larger of the two sums).
    double fold = 0.0, fold_deep = 0.0;
    for (const FittedWave& w : out.waves) {
        fold += w.steepness * w.k * w.amplitude;
        fold_deep += w.steepness * (w.omega * w.omega / kGravity) * w.amplitude;
    }
    if (std::max(fold, fold_deep) > kFoldLimit) {
        const double scale = kFoldLimit / std::max(fold, fold_deep);
        for (FittedWave& w : out.waves) w.steepness *= scale;
        out.steepness_scaled = true;
    }
    std::sort(out.waves.begin(), out.waves.end(),
              [](const FittedWave& a, const FittedWave& b) { return a.amplitude > b.amplitude; });
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

}  // namespace tidewater::calibration
