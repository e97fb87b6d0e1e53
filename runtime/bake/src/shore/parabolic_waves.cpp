#include "shore/parabolic_waves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "shore/fast_marching.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::detail {

namespace {

using Complex = std::complex<double>;

/// H_rms / H_max under which Battjes and Janssen's share of broken waves is nought (under 1e-10).
inline constexpr double kNoBrokenShare = 0.2;
/// A random sea's highest waves over the depth, H_max / h: Battjes and Janssen's 0.73
/// (SWAN's default).
inline constexpr double kRandomSeaBreakerIndex = 0.73;

/// Linear dispersion without units: k h and the group velocity's share n = cg / c as
/// functions of s = sqrt(omega^2 h / g), tabulated up to deep water (k h = kDeepKh) and
/// read linearly: within 1e-6 of the solve, at a tenth of its cost.
class DispersionTable {
  public:
    DispersionTable() {
        const double last = std::sqrt(kDeepKh);  // omega^2 h / g <= k h: past it, the water is deep
        step_ = last / (kEntries - 1);
        for (std::size_t e = 0; e < kEntries; ++e) {
            const double s = std::max(static_cast<double>(e) * step_, 1e-9), x = s * s;
            const double kh = wavenumber_at_depth(1.0, x * kGravity) * x * kGravity;  // omega = 1: h = g x
            kh_[e] = kh;
            n_[e] = kh > 20.0 ? 0.5 : 0.5 * (1.0 + 2.0 * kh / std::sinh(2.0 * kh));
        }
    }
    /// k h and n at s (0 <= s < sqrt(kDeepKh)).
    void at(double s, double& kh, double& n) const {
        const double f = s / step_;
        const std::size_t e = std::min(static_cast<std::size_t>(f), kEntries - 2);
        const double t = f - static_cast<double>(e);
        kh = kh_[e] + t * (kh_[e + 1] - kh_[e]);
        n = n_[e] + t * (n_[e + 1] - n_[e]);
    }

  private:
    static constexpr std::size_t kEntries = 4096;
    double step_ = 0.0;
    std::array<double, kEntries> kh_{}, n_{};
};

const DispersionTable& dispersion_table() {
    static const DispersionTable table;
    return table;
}

/// What the march reads of a row: wavenumber, group velocity and depth per point (the
/// depth at least a thousandth of the deep-water wavelength over 2 pi, so that the
/// dispersion stays defined next to land), which points are water, and which are deep
/// (k h >= kDeepKh), where the wave is the open sea's, as the rays take it: k = omega^2 / g.
struct RowMedium {
    std::vector<double> k, cg, h;
    std::vector<char> wet, deep;
};

/// What every point's medium shares for a wave of angular frequency omega (rad/s): its
/// deep-water wavenumber and group velocity, and the least depth the march takes (a
/// thousandth of the deep-water wavelength over 2 pi). Formed once a march: most of a
/// march's points are in deep water.
struct DeepWater {
    explicit DeepWater(double w) : omega(w), k(w * w / kGravity), cg(0.5 * w / k), shallowest(1e-3 / k) {}
    double omega, k, cg, shallowest;
};

/// Sets point j of `r` for still-water depth `depth` (m).
void fill_point_medium(const DeepWater& d, double depth, RowMedium& r, std::size_t j) {
    r.wet[j] = depth > 0.0;
    r.h[j] = std::max(depth, d.shallowest);
    double kh = kDeepKh, share = 0.5;
    // k(h) >= omega^2 / g: water that deep for the deep-water k is deep without a look-up.
    if (d.k * r.h[j] < kDeepKh) dispersion_table().at(std::sqrt(d.k * r.h[j]), kh, share);
    r.deep[j] = kh >= kDeepKh;
    r.k[j] = r.deep[j] ? d.k : kh / r.h[j];
    r.cg[j] = r.deep[j] ? d.cg : share * d.omega / r.k[j];
}

/// Fills `r` for a row of `depths` (its vectors are reused from row to row).
void fill_row_medium(const DeepWater& d, std::span<const float> depths, RowMedium& r) {
    const std::size_t n = depths.size();
    for (auto* v : {&r.k, &r.cg, &r.h}) v->resize(n);
    r.wet.resize(n);
    r.deep.resize(n);
    for (std::size_t j = 0; j < n; ++j) fill_point_medium(d, static_cast<double>(depths[j]), r, j);
}

/// Solves the tridiagonal system lower_j x_{j-1} + diag_j x_j + upper_j x_{j+1} = rhs_j
/// (Thomas); `diag` and `rhs` are overwritten, the answer left in `rhs`.
void solve_tridiagonal(const std::vector<Complex>& lower, std::vector<Complex>& diag, const std::vector<Complex>& upper,
                       std::vector<Complex>& rhs) {
    // 1 / z as conj(z) / |z|^2: the library's complex division guards against overflow
    // that these coefficients (of order 1) cannot reach, at several times the cost.
    auto inverse = [](Complex z) { return std::conj(z) / std::norm(z); };
    const std::size_t n = diag.size();
    Complex diag_before = diag[0], m_before;
    diag[0] = inverse(diag[0]);
    for (std::size_t j = 1; j < n; ++j) {
        // Over deep water the rows are alike and the elimination's pivots settle to one
        // value: where this row and the pivot it starts from are the last one's, so is
        // what it gives (the same operations on the same values), without the division
        // that holds up each step.
        const Complex given = diag[j];
        Complex m;
        if (j >= 2 && given == diag_before && lower[j] == lower[j - 1] && upper[j - 1] == upper[j - 2] &&
            diag[j - 1] == diag[j - 2]) {
            m = m_before;
            diag[j] = diag[j - 1];
        } else {
            m = lower[j] * diag[j - 1];
            diag[j] = inverse(given - m * upper[j - 1]);
        }
        rhs[j] -= m * rhs[j - 1];
        diag_before = given;
        m_before = m;
    }
    rhs[n - 1] *= diag[n - 1];
    for (std::size_t j = n - 1; j-- > 0;) rhs[j] = (rhs[j] - upper[j] * rhs[j + 1]) * diag[j];
}

}  // namespace

namespace {

/// Kirby and Dalrymple's dispersion solved for k, from k_linear.
double solve_amplitude_dispersion(double omega, double depth, double amplitude, double k_linear) {
    // Kirby and Dalrymple's (1986) composite of Stokes' third order in deep and
    // intermediate water with Hedges' shallow-water form:
    // omega^2 = g k (1 + f1 (k a)^2 D) tanh(k h + f2 k a), f1 = tanh^5(kh), f2 = (kh / sinh kh)^4.
    auto residual = [&](double k) {
        const double kh = k * depth, ka = k * amplitude;
        if (kh > 20.0) return kGravity * k * (1.0 + ka * ka) - omega * omega;
        const double e = std::exp(-2.0 * kh);  // tanh, sinh and cosh from one exponential
        const double t = (1.0 - e) / (1.0 + e), sh = (1.0 - e) / (2.0 * std::sqrt(e));
        const double sh2 = sh * sh, t2 = t * t, r = kh / sh, r2 = r * r;
        const double cosh4 = 1.0 + 8.0 * sh2 * (1.0 + sh2);  // cosh(4x) = 1 + 8 sinh^2 x cosh^2 x
        const double d = (cosh4 + 8.0 - 2.0 * t2) / (8.0 * sh2 * sh2);
        const double e_shift = e * std::exp(-2.0 * r2 * r2 * ka);  // tanh(kh + f2 k a) from exp(-2 (kh + f2 k a))
        return kGravity * k * (1.0 + t2 * t2 * t * ka * ka * d) * (1.0 - e_shift) / (1.0 + e_shift) - omega * omega;
    };
    // The dispersion shifts k by a few per cent: secant steps from the linear k.
    double k0 = k_linear, k1 = k_linear * 0.98;
    double r0 = residual(k0), r1 = residual(k1);
    for (int i = 0; i < 8 && r1 != r0; ++i) {
        const double k2 = k1 - r1 * (k1 - k0) / (r1 - r0);
        k0 = k1;
        r0 = r1;
        k1 = std::clamp(k2, 0.5 * k_linear, 1.5 * k_linear);
        if (std::abs(k1 - k0) < 1e-6 * k_linear) break;
        r1 = residual(k1);
    }
    return std::isfinite(k1) ? k1 : k_linear;
}

}  // namespace

double amplitude_dispersed_wavenumber(double omega, double depth, double amplitude, double k_linear) {
    if (!(amplitude * k_linear > 1e-3)) return k_linear;  // under 1e-5 of k in deep water
    return solve_amplitude_dispersion(omega, depth, amplitude, k_linear);
}

double weggel_breaker_index(double slope, double height, double period) {
    const double m = std::clamp(slope, 0.0, 0.1);
    const double a = 43.8 * (1.0 - std::exp(-19.0 * m));
    const double b = 1.56 / (1.0 + std::exp(-19.5 * m));
    return std::max(0.6, b - a * height / (kGravity * period * period));
}

double broken_share(double rms_over_max) {
    const double b = rms_over_max;
    if (!(b > kNoBrokenShare)) return 0.0;
    if (b >= 1.0) return 1.0;
    // f(Q) = 1 - Q + b^2 ln Q rises from -inf at 0 to its one root below 1 (f' = 0 at
    // Q = b^2 < 1), and is concave: Newton's steps from a point where it is negative
    // (exp(-1 / b^2), where f = -Q) climb to the root from below without passing it.
    const double b2 = b * b;
    double q = std::exp(-1.0 / b2);
    for (int i = 0; i < 100; ++i) {
        const double step = (1.0 - q + b2 * std::log(q)) / (b2 / q - 1.0);
        q -= step;
        if (!(std::abs(step) > 1e-13 * q)) break;
    }
    return std::min(q, b2);
}

double shuto_exponent(double ursell) {
    if (!(ursell >= 30.0)) return std::numeric_limits<double>::quiet_NaN();
    if (ursell <= 50.0) return -2.0 / 7.0;
    // H h^(5/2) (s - 2 sqrt 3) = const with s = sqrt(U), d ln s = d ln H / 2 - d ln h.
    const double s = std::sqrt(ursell), r3 = std::sqrt(3.0);
    return (5.0 * r3 - 1.5 * s) / (1.5 * s - 2.0 * r3);
}

namespace {

/// Kirby and Dalrymple's amplitude dispersion without units: k h as a function of
/// s = sqrt(omega^2 h / g) and r = a / h, tabulated over shallow and intermediate water
/// (s up to 2, k h up to about 4) and heights up to the depth (k a up to 0.45), read as k h / s
/// (1 / sqrt(1 + r) in the shallowest water, where Hedges' form holds): within
/// 2e-6 of the solve over the table's range (`AmplitudeDispersion` tests). Past its range
/// the solve is called.
class AmplitudeDispersionTable {
  public:
    static constexpr int kS = 512, kR = 256;
    static constexpr double kMaxS = 2.0, kMaxR = 1.0, kSteepest = 0.45;
    AmplitudeDispersionTable() {
        for (int i = 0; i <= kS; ++i)
            for (int j = 0; j <= kR; ++j) {
                const double s = std::max(i * kMaxS / kS, 1e-4), r = j * kMaxR / kR;
                const double h = s * s * kGravity;  // omega = 1
                const double k = solve_amplitude_dispersion(1.0, h, r * h, wavenumber_at_depth(1.0, h));
                q_[static_cast<std::size_t>(i) * (kR + 1) + static_cast<std::size_t>(j)] = k * h / s;
            }
    }
    /// The wavenumber (rad/m) of a wave of amplitude `amplitude` at `depth`, whose linear
    /// wavenumber is `k_linear` (as amplitude_dispersed_wavenumber).
    double wavenumber(double omega, double depth, double amplitude, double k_linear) const {
        if (!(amplitude * k_linear > 1e-3)) return k_linear;
        const double s = omega * std::sqrt(depth / kGravity), r = amplitude / depth;
        // Past Stokes' steepest wave (k a 0.44) the solve may end on its bounds, wherever
        // it starts: solved there.
        if (!(s < kMaxS && r < kMaxR && amplitude * k_linear < kSteepest))
            return amplitude_dispersed_wavenumber(omega, depth, amplitude, k_linear);
        // Quadratic through the three nodes nearest each way: the dispersion grows as r
        // (Hedges) and as r^2 (Stokes) from r = 0, which a line between nodes misses.
        const double fs = s * (kS / kMaxS), fr = r * (kR / kMaxR);
        const int i = std::clamp(static_cast<int>(std::lround(fs)), 1, kS - 1);
        const int j = std::clamp(static_cast<int>(std::lround(fr)), 1, kR - 1);
        const std::array<double, 3> ws = weights(fs - i), wr = weights(fr - j);
        double q = 0.0;
        for (int a = 0; a < 3; ++a) {
            const double* row =
                q_.data() + static_cast<std::size_t>(i - 1 + a) * (kR + 1) + static_cast<std::size_t>(j - 1);
            q += ws[static_cast<std::size_t>(a)] * (wr[0] * row[0] + wr[1] * row[1] + wr[2] * row[2]);
        }
        return q * s / depth;
    }

  private:
    /// Lagrange's weights at nodes -1, 0, 1 for a point t from the middle one.
    static std::array<double, 3> weights(double t) { return {0.5 * t * (t - 1.0), 1.0 - t * t, 0.5 * t * (t + 1.0)}; }

    std::vector<double> q_ = std::vector<double>(static_cast<std::size_t>(kS + 1) * (kR + 1));
};

}  // namespace

double tabulated_amplitude_dispersed_wavenumber(double omega, double depth, double amplitude, double k_linear) {
    static const AmplitudeDispersionTable table;
    return table.wavenumber(omega, depth, amplitude, k_linear);
}

namespace {

/// Steps a breaking row takes a local wavelength at least: where waves break, the march
/// steps that finely (the onset and the surf zone's decay length are short), elsewhere
/// at the grid's spacing.
inline constexpr double kSurfStepsPerWavelength = 16.0;
inline constexpr int kMostSubsteps = 8;
/// A regular wave nears breaking over this height over the depth; the most its height
/// is raised over the incident one by shoaling and focusing, as the substeps allow for.
inline constexpr double kNearBreaking = 0.5, kMostRaised = 2.5;
/// Weggel's index is never under this: a wave lower than this times the depth, and not
/// yet broken, does not break in the step.
inline constexpr double kLowestBreakerIndex = 0.6;
/// Shuto's nonlinear shoaling starts at this Ursell number.
inline constexpr double kShutoUrsell = 30.0;

/// The march's state from row to row.
class Marcher {
  public:
    explicit Marcher(const ParabolicInput& in)
        : in_(in), n_(static_cast<std::size_t>(in.grid.across)), deep_(in.omega) {
        period_ = in.sea_period > 0.0 ? in.sea_period : kTwoPi / in.omega;
        // Under this height over the depth nothing breaks: Weggel's least index, or where
        // Battjes and Janssen's share of broken waves is nought.
        lowest_breaking_ = in.random_sea ? kNoBrokenShare * kRandomSeaBreakerIndex : kLowestBreakerIndex;
        for (auto* v : {&a, &lower_, &diag_, &upper_, &rhs_, &half_turn_}) v->assign(n_, Complex(0.0));
        for (auto* v : {&k_, &p_}) v->assign(n_, 0.0);
        parts_.assign(n_, 1);
        broken.assign(n_, 0);
        for (RowMedium* m : {&from_, &to_}) {
            for (auto* v : {&m->k, &m->cg, &m->h}) v->assign(n_, 0.0);
            m->wet.assign(n_, 0);
            m->deep.assign(n_, 0);
        }
    }

    void enter(const RowMedium& row) {
        for (std::size_t j = 0; j < n_; ++j) {
            const double shoaled = in_.incident_in_deep_water ? shoaling_coefficient(in_.omega, row.h[j]) : 1.0;
            a[j] = row.wet[j] ? Complex(in_.incident_amplitude * shoaled) : Complex(0.0);
        }
    }

    /// Substeps point j's turns take over a step of dx from `here`: more where the wave
    /// may break (the onset and the surf zone's decay length are short). By the depth
    /// alone, against the incident height raised by the most shoaling and focusing
    /// allowed for, never by the wave's own height: a point's march then does not hang on
    /// the breaking elsewhere in its row, nor on a change too small to matter tipping a
    /// point over a threshold (a march taken up again after an edit steps as the whole did).
    int substeps(const RowMedium& here, std::size_t j, double dx) const {
        if (!in_.breaking || !here.wet[j]) return 1;
        const double incident = 2.0 * in_.incident_amplitude * in_.sea_over_component;
        const double onset = in_.random_sea ? lowest_breaking_ : kNearBreaking;
        if (onset * here.h[j] >= kMostRaised * incident) return 1;
        const double finest = kTwoPi / here.k[j] / kSurfStepsPerWavelength;
        return std::clamp(static_cast<int>(std::ceil(dx / finest - 1e-9)), 1, kMostSubsteps);
    }

    /// A window's first and last points held at a longer march's values (MarchColumns):
    /// its amplitude there (`lo`, `hi`: held) and breaking, with the phase it carries.
    struct Sides {
        bool lo = false, hi = false;
        Complex a_lo, a_hi;
        char broken_lo = 0, broken_hi = 0;
        double phase = 0.0;
    };

    /// One step of dx from `here` (still-water depths `here_depths`) to `next`.
    void advance(const RowMedium& here, const RowMedium& next, std::span<const float> here_depths,
                 std::span<const float> next_depths, double dx, const Sides* sides = nullptr);

    const DeepWater& deep_water() const { return deep_; }
    /// Marks in `sea_asked` the points whose turns this step (from `here` to `next`, dx)
    /// read the sea's height: all but those in deep water, not broken, in one substep, that
    /// neither break nor shoal nonlinearly at `bound` (m) or at their own height, the most
    /// their height can be (open_sea holds there, whatever the sea's height under it).
    void ask_sea_height(const RowMedium& here, const RowMedium& next, double dx, double bound) {
        for (std::size_t j = 0; j < n_; ++j) {
            const bool open = deep_and_whole(here, next, j) && substeps(here, j, dx) == 1 &&
                              linear_and_unbroken(here, next, j, std::max(bound, own_height(j)));
            sea_asked[j] = open ? 0 : 1;
        }
    }
    /// The sea's rms height along the row the next step leaves (empty: none given), read
    /// where `sea_asked` marks.
    std::vector<float> sea_height;
    std::vector<char> sea_asked;
    std::vector<Complex> a;
    std::vector<char> broken;
    /// The phase common to the row (the rows' mean wavenumbers over water, integrated):
    /// A carries exp(-i phase) beside its own.
    double phase = 0.0;

  private:
    /// The height point j breaks and shoals at (m): the sea's where given, else its own.
    double height_at(std::size_t j) const {
        return !sea_height.empty() && sea_height[j] > 0.0f ? static_cast<double>(sea_height[j]) : own_height(j);
    }
    /// Point j's own estimate of the sea's height: the component's times sea_over_component.
    double own_height(std::size_t j) const { return 2.0 * std::sqrt(std::norm(a[j])) * in_.sea_over_component; }
    /// Ursell's number g H T^2 / h^2 of a wave `height` high between depths h and h_next.
    double ursell(double h, double h_next, double height) const {
        const double depth = 0.5 * (h + h_next);
        return kGravity * height * period_ * period_ / (depth * depth);
    }
    /// Whether point j, `height` high, shoals nonlinearly from `here` to `next`.
    bool shoals_nonlinearly(const RowMedium& here, const RowMedium& next, std::size_t j, double height) const {
        return in_.nonlinear_shoaling && here.wet[j] && next.h[j] < here.h[j] &&
               ursell(here.h[j], next.h[j], height) >= kShutoUrsell;
    }
    /// Whether point j is the open sea's wave from `here` to `next`: in deep water, too low
    /// to break and shoaling linearly, its group velocity does not change (no growth) and
    /// its phase is the deep-water one. Most of a march's points: the cheap tests first.
    bool open_sea(const RowMedium& here, const RowMedium& next, std::size_t j) const {
        return deep_and_whole(here, next, j) && linear_and_unbroken(here, next, j, height_at(j));
    }
    /// Whether point j is in deep water at both rows and has not broken.
    bool deep_and_whole(const RowMedium& here, const RowMedium& next, std::size_t j) const {
        return here.deep[j] && next.deep[j] && !broken[j];
    }
    /// Whether point j, `height` (m) high, neither starts to break nor shoals nonlinearly
    /// from `here` to `next`.
    bool linear_and_unbroken(const RowMedium& here, const RowMedium& next, std::size_t j, double height) const {
        return !(in_.breaking && here.wet[j] && height > lowest_breaking_ * here.h[j]) &&
               !shoals_nonlinearly(here, next, j, height);
    }
    /// The half step's turn of point j: the phase against the row's mean wavenumber, and
    /// the growth or decay (shoaling, breaking, nonlinear shoaling).
    Complex half_turn(const RowMedium& here, const RowMedium& next, std::size_t j, double k_bar, double dx);

    const ParabolicInput& in_;
    std::size_t n_;
    DeepWater deep_;
    double period_ = 0.0, lowest_breaking_ = 0.0;
    std::vector<Complex> lower_, diag_, upper_, rhs_, half_turn_;
    /// Point j's turn through depths from `here_depth` to `next_depth` over the half of a
    /// step of dx that starts `from` (0 or 0.5) of the way, in `parts` substeps.
    void turn_through(float here_depth, float next_depth, std::size_t j, double k_bar, double dx, double from,
                      int parts);

    std::vector<double> k_, p_;
    std::vector<int> parts_;  ///< per point, the substeps its turns took this step
    RowMedium from_, to_;     ///< a substepped point's media, at its index
};

Complex Marcher::half_turn(const RowMedium& here, const RowMedium& next, std::size_t j, double k_bar, double dx) {
    if (open_sea(here, next, j)) return std::polar(1.0, 0.5 * (deep_.k - k_bar) * dx);
    const double h = here.h[j], height = height_at(j);
    const bool nonlinear = shoals_nonlinearly(here, next, j, height);
    // Energy flux k p |A|^2 = omega cg |A|^2 is kept: A shrinks as sqrt(cg) grows, by
    // (cg here / cg next)^(1/4) over the half step. Breaking takes more (`dissipation`:
    // the amplitude's rate of decay, 1/m); nonlinear shoaling, where it grows faster, less.
    const double flux_ratio = next.cg[j] / here.cg[j];
    double dissipation = 0.0;
    bool shuto = false;
    if (in_.breaking && in_.random_sea && here.wet[j]) {
        // Battjes and Janssen: the sea loses D = (alpha / 4) rho g f Q_b H_max^2 (alpha 1,
        // f its mean frequency) of its energy flux E cg, E = rho g H_rms^2 / 8; each
        // component at the sea's rate.
        const double highest = kRandomSeaBreakerIndex * h;
        const double share = broken_share(height / highest);
        broken[j] = share >= 0.5 ? 1 : 0;
        if (share > 0.0) {
            const double ratio = highest / height;
            dissipation = share * ratio * ratio / (period_ * here.cg[j]);
        } else {
            shuto = nonlinear;
        }
    } else {
        // A regular wave: it breaks past Weggel's index and decays as Dally et al. say.
        if (in_.breaking && here.wet[j]) {
            const double slope = std::max(0.0, (h - next.h[j]) / dx);
            if (!broken[j] && height > kLowestBreakerIndex * h &&
                height > weggel_breaker_index(slope, height, period_) * h)
                broken[j] = 1;
            if (broken[j] && height < in_.surf.stable_index * h) broken[j] = 0;
        } else {
            broken[j] = 0;
        }
        if (broken[j]) {
            // Dally et al.: d(E cg)/dx = -K / h (E cg - E_s cg), E_s at height Gamma h.
            const double stable = in_.surf.stable_index * h / height;
            dissipation = 0.5 * in_.surf.decay / h * (1.0 - stable * stable);
        } else {
            shuto = nonlinear;
        }
    }
    double magnitude = 0.0;
    if (shuto) {
        // Grows as H ~ h^n where that is faster than linear shoaling.
        const double decay = std::min(0.5 * std::log(flux_ratio) / dx,
                                      -shuto_exponent(ursell(h, next.h[j], height)) * std::log(next.h[j] / h) / dx);
        magnitude = std::exp(-0.5 * decay * dx);
    } else {
        magnitude = 1.0 / std::sqrt(std::sqrt(flux_ratio));
        if (dissipation > 0.0) magnitude *= std::exp(-0.5 * dissipation * dx);
    }
    // The phase travels at the amplitude's own speed (amplitude dispersion).
    const double kn = in_.amplitude_dispersion && here.wet[j] && !(here.deep[j] && next.deep[j])
                          ? tabulated_amplitude_dispersed_wavenumber(in_.omega, 0.5 * (h + next.h[j]),
                                                                     std::sqrt(std::norm(a[j])), k_[j])
                          : k_[j];
    return std::polar(magnitude, 0.5 * (kn - k_bar) * dx);
}

void Marcher::turn_through(float here_depth, float next_depth, std::size_t j, double k_bar, double dx, double from,
                           int parts) {
    const double k_mean = k_[j];
    const double piece = 0.5 * dx / parts;
    auto depth_at = [&](int q) {
        const double t = from + 0.5 * static_cast<double>(q) / parts;
        return static_cast<double>(here_depth) +
               t * (static_cast<double>(next_depth) - static_cast<double>(here_depth));
    };
    for (int part = 0; part < parts; ++part) {
        fill_point_medium(deep_, depth_at(part), from_, j);
        fill_point_medium(deep_, depth_at(part + 1), to_, j);
        k_[j] = 0.5 * (from_.k[j] + to_.k[j]);
        // half_turn takes half of the way between its media: twice, the whole piece.
        const Complex f = half_turn(from_, to_, j, k_bar, piece);
        a[j] *= f * f;
    }
    k_[j] = k_mean;
}

void Marcher::advance(const RowMedium& here, const RowMedium& next, std::span<const float> here_depths,
                      std::span<const float> next_depths, double dx, const Sides* sides) {
    const std::size_t un = n_;
    const double dy2 = in_.grid.dy * in_.grid.dy;
    // The row's mean wavenumber over its water carries the fast phase: A varies slowly.
    double k_sum = 0.0;
    int wet = 0;
    double k_before = 0.0, cg_before = 0.0, p_before = 0.0;  // the last point's: over deep water, every point's
    for (std::size_t j = 0; j < un; ++j) {
        k_[j] = 0.5 * (here.k[j] + next.k[j]);
        const double cg = 0.5 * (here.cg[j] + next.cg[j]);
        p_[j] = k_[j] == k_before && cg == cg_before ? p_before : in_.omega / k_[j] * cg;
        k_before = k_[j];
        cg_before = cg;
        p_before = p_[j];
        if (here.wet[j] && next.wet[j]) {
            k_sum += k_[j];
            ++wet;
        }
    }
    const double k_bar = wet > 0 ? k_sum / wet : deep_.k;
    phase += k_bar * dx;
    // A_x = (i (k - k_bar) - s) A + R A, R = i / (2 k) L, L A = (p A_y)_y / p (walls at
    // the sides), split (Strang): the phase and the growth or decay taken exactly over
    // each half step, whatever the step against the wavelength or the surf zone's decay
    // length (Crank-Nicolson would turn a strong decay into a flip of sign); Crank-
    // Nicolson between for the diffraction, (1 - dx/2 R) A' = (1 + dx/2 R) A.
    const Complex deep_turn = std::polar(1.0, 0.5 * (deep_.k - k_bar) * dx);
    for (std::size_t j = 0; j < un; ++j) {
        const int parts = substeps(here, j, dx);
        if (parts == 1) {
            const bool open = (!sea_height.empty() && sea_asked[j] == 0) || open_sea(here, next, j);
            const Complex turn = open ? deep_turn : half_turn(here, next, j, k_bar, dx);
            half_turn_[j] = turn;
            a[j] *= turn;
            continue;
        }
        // Where the wave breaks or nears breaking each half step's turn is taken in
        // substeps through the depths between the rows' (linearly), its height and
        // breaking updated each: the first half through the first half of the step here,
        // the second after the diffraction.
        parts_[j] = parts;
        half_turn_[j] = 1.0;
        turn_through(here_depths[j], next_depths[j], j, k_bar, dx, 0.0, parts);
    }
    // Crank-Nicolson's row j: its matrix's (lower, diag, upper) and its right side's
    // weights of A_j, A_j-1 and A_j+1, from the p's about it and k there. Over deep water
    // every point's are the last one's: they are formed again only where those moved.
    struct Row {
        double p_lo = -1.0, p_hi = -1.0, p = -1.0, k = -1.0;
        Complex lower, diag, upper, here, before, after;
    } row;
    for (std::size_t j = 0; j < un; ++j) {
        const double p_lo = j > 0 ? 0.5 * (p_[j] + p_[j - 1]) : 0.0;
        const double p_hi = j + 1 < un ? 0.5 * (p_[j] + p_[j + 1]) : 0.0;
        if (!next.wet[j]) {
            lower_[j] = upper_[j] = 0.0;
            diag_[j] = 1.0;
            rhs_[j] = 0.0;
            continue;
        }
        if (p_lo != row.p_lo || p_hi != row.p_hi || p_[j] != row.p || k_[j] != row.k) {
            const double l_lo = p_lo / (p_[j] * dy2), l_hi = p_hi / (p_[j] * dy2), l_mid = -(l_lo + l_hi);
            const Complex alpha(0.0, -0.25 * dx / k_[j]), beta(0.0, 0.25 * dx / k_[j]);
            row = {p_lo,         p_hi,
                   p_[j],        k_[j],
                   alpha * l_lo, 1.0 + alpha * l_mid,
                   alpha * l_hi, 1.0 + beta * l_mid,
                   beta * l_lo,  beta * l_hi};
        }
        lower_[j] = row.lower;
        upper_[j] = row.upper;
        diag_[j] = row.diag;
        Complex sum = row.here * a[j];
        if (j > 0) sum += row.before * a[j - 1];
        if (j + 1 < un) sum += row.after * a[j + 1];
        rhs_[j] = sum;
    }
    // Held: the longer march's value, turned from its common phase to this one's.
    const Complex side_turn = sides ? std::polar(1.0, sides->phase - phase) : Complex(1.0);
    auto hold = [&](std::size_t j, Complex value) {
        lower_[j] = upper_[j] = 0.0;
        diag_[j] = 1.0;
        rhs_[j] = value * side_turn;
        parts_[j] = 0;  // neither turned again nor substepped: the value as it is
    };
    if (sides && sides->lo) hold(0, sides->a_lo);
    if (sides && sides->hi) hold(un - 1, sides->a_hi);
    solve_tridiagonal(lower_, diag_, upper_, rhs_);
    for (std::size_t j = 0; j < un; ++j) {
        if (parts_[j] == 0) {
            a[j] = rhs_[j];
            parts_[j] = 1;
        } else if (parts_[j] > 1) {
            a[j] = rhs_[j];
            turn_through(here_depths[j], next_depths[j], j, k_bar, dx, 0.5, parts_[j]);
            parts_[j] = 1;
        } else {
            a[j] = rhs_[j] * half_turn_[j];
        }
    }
    if (sides && sides->lo) broken[0] = sides->broken_lo;
    if (sides && sides->hi) broken[un - 1] = sides->broken_hi;
}

}  // namespace

/// The march's rows and state between steps (ParabolicMarch's).
struct ParabolicMarch::State {
    explicit State(const ParabolicInput& in) : marcher(in) {}
    Marcher marcher;
    std::vector<float> here_depths, next_depths;
    RowMedium here, next;
};

ParabolicMarch::ParabolicMarch(const ParabolicInput& in) : in_(in) {
    const auto un = static_cast<std::size_t>(in.grid.across);
    if (in.grid.steps <= 0 || un == 0) return;
    state_ = std::make_unique<State>(in);
    State& s = *state_;
    for (auto* v : {&s.here_depths, &s.next_depths}) v->resize(un);
    in.depth_row(0, s.here_depths);
    fill_row_medium(s.marcher.deep_water(), s.here_depths, s.here);
    s.marcher.enter(s.here);
    if (!in.entering_amplitude.empty()) {
        std::copy(in.entering_amplitude.begin(), in.entering_amplitude.end(), s.marcher.a.begin());
        std::copy(in.entering_broken.begin(), in.entering_broken.end(), s.marcher.broken.begin());
        s.marcher.phase = in.entering_phase;
    }
    if (in.sea_height_row) {
        s.marcher.sea_height.resize(un);
        s.marcher.sea_asked.resize(un);
    }
    if (MarchColumns* c = in.keep_columns) {
        c->count = (un - 1) / static_cast<std::size_t>(c->every) + 1;
        keep_columns();
    }
}

ParabolicMarch::~ParabolicMarch() = default;

double ParabolicMarch::phase() const {
    return state_->marcher.phase;
}

ParabolicRow ParabolicMarch::row() const {
    return {step_, state_->marcher.a, state_->marcher.broken};
}

void ParabolicMarch::keep_columns() {
    State& s = *state_;
    MarchColumns& c = *in_.keep_columns;
    for (std::size_t k = 0; k < c.count; ++k) {
        const std::size_t j = k * static_cast<std::size_t>(c.every);
        c.amplitude.emplace_back(s.marcher.a[j]);
        c.broken.push_back(s.marcher.broken[j]);
    }
    c.phase.push_back(s.marcher.phase);
}

bool ParabolicMarch::advance() {
    if (!state_ || step_ + 1 >= in_.grid.steps) return false;
    State& s = *state_;
    Marcher& m = s.marcher;
    in_.depth_row(step_ + 1, s.next_depths);
    fill_row_medium(m.deep_water(), s.next_depths, s.next);
    if (in_.sea_height_row) {
        m.ask_sea_height(s.here, s.next, in_.grid.dx, in_.sea_height_bound);
        in_.sea_height_row(step_, m.sea_height, m.sea_asked);
    }
    // A window's sides are held at the march it is a window of.
    const MarchColumns* held = in_.sides;
    const auto t = static_cast<std::size_t>(in_.sides_first_row + step_ + 1);
    Marcher::Sides sides;
    sides.lo = held && in_.side_lo != ParabolicInput::kNoSide;
    sides.hi = held && in_.side_hi != ParabolicInput::kNoSide;
    if (sides.lo) {
        sides.a_lo = Complex(held->amplitude[t * held->count + in_.side_lo]);
        sides.broken_lo = held->broken[t * held->count + in_.side_lo];
    }
    if (sides.hi) {
        sides.a_hi = Complex(held->amplitude[t * held->count + in_.side_hi]);
        sides.broken_hi = held->broken[t * held->count + in_.side_hi];
    }
    // A march without sides may run past the rows the longer march kept.
    if (sides.lo || sides.hi) sides.phase = held->phase[t];
    m.advance(s.here, s.next, s.here_depths, s.next_depths, in_.grid.dx, sides.lo || sides.hi ? &sides : nullptr);
    if (in_.keep_columns) keep_columns();
    if (in_.advanced) in_.advanced(t, m.a, m.broken, m.phase);
    std::swap(s.here, s.next);
    std::swap(s.here_depths, s.next_depths);
    ++step_;
    return true;
}

}  // namespace tidewater::detail
