// One wave component over the depth by the parabolic mild-slope equation: refraction and
// diffraction together, marched along the wave's offshore direction with Crank-Nicolson
// steps (Radder 1979; Kirby and Dalrymple 1983, whose amplitude dispersion it keeps in
// Kirby and Dalrymple's 1986 composite form). The small-angle form: Padé's and Kirby's
// wide-angle forms made the focus behind Berkhoff's shoal depend on the grid across the
// march, and each wave is marched along its own direction, so that only refraction and
// diffraction turn it. Near breaking the height grows as Shuto's (1974) nonlinear
// shoaling says; breaking starts where the height passes Weggel's (1972) index for the
// local beach slope and steepness, and the broken wave loses energy as Dally, Dean and
// Dalrymple (1985) say until it is stable again; a random sea breaks as a whole as
// Battjes and Janssen (1978) say. Everything is in the scene's own units:
// no length or time of its own. Private to the bake.
#pragma once

#include <complex>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>

namespace tidewater::detail {

/// A grid in the wave's frame: `steps` rows along the march (x', the wave's offshore
/// direction), `across` points a row (y'), row-major by step.
struct ParabolicGrid {
    int steps = 0, across = 0;
    double dx = 0.0, dy = 0.0;  ///< m
    std::size_t index(int step, int j) const {
        return static_cast<std::size_t>(step) * static_cast<std::size_t>(across) + static_cast<std::size_t>(j);
    }
    std::size_t size() const { return static_cast<std::size_t>(steps) * static_cast<std::size_t>(across); }
};

/// Dally, Dean and Dalrymple's (1985) surf zone: a broken wave loses energy flux at
/// decay * cg / h * (E - E_stable) until its height is stable_index * h.
struct SurfZone {
    double decay = 0.15;        ///< K
    double stable_index = 0.4;  ///< Gamma
};

/// A march's state at every `every`-th point (0, every, 2 every, ...), kept on each of its
/// rows from its first, so that a window of it can be marched again later with these as
/// its sides. The amplitudes carry a phase common to the whole row (the rows' mean
/// wavenumbers, integrated), kept with them: a window's own differs.
struct MarchColumns {
    int every = 0;                                ///< set by the caller
    std::size_t count = 0;                        ///< columns a row
    std::vector<std::complex<double>> amplitude;  ///< row r's column c at r * count + c
    std::vector<char> broken;
    std::vector<double> phase;  ///< per row, the phase common to it
    std::size_t bytes() const {
        return amplitude.size() * sizeof(amplitude[0]) + broken.size() + phase.size() * sizeof(double);
    }
};

/// What a march reads: the grid, the wave, its depth row by row, and the physics it keeps.
struct ParabolicInput {
    ParabolicGrid grid;
    double omega = 0.0;  ///< rad/s
    /// Fills a row's still-water depth (m, <= 0: land), `across` values; called once a row,
    /// rows in order.
    std::function<void(int step, std::span<float> depth)> depth_row;
    /// The amplitude along the first row (m, phase 0 there): the wave as it enters; with
    /// `incident_in_deep_water`, the deep-water amplitude, shoaled linearly to each point.
    double incident_amplitude = 0.0;
    bool incident_in_deep_water = false;
    /// The sea's height over this component's where it breaks (sqrt of the sea's energy
    /// over the component's, as they enter), and the sea's mean period (s; 0: the
    /// component's): every component breaks and shoals nonlinearly where the sea does.
    double sea_over_component = 1.0;
    double sea_period = 0.0;
    /// A random sea (more than one component): it breaks as Battjes and Janssen (1978)
    /// say, a share Q_b of its waves broken at any point, instead of as one regular wave
    /// (Weggel's onset, Dally's decay).
    bool random_sea = false;
    /// Where the sea has been marched as a whole (march_sea), its rms height there (m; <= 0
    /// where it was not: the component's height times sea_over_component stands in), at the
    /// points of the row that `asked` marks (the others are not read), called once a row,
    /// rows in order: every component breaks and shoals nonlinearly at the sea's own height,
    /// not at its own estimate of it.
    std::function<void(int step, std::span<float> height, std::span<const char> asked)> sea_height_row;
    /// No height sea_height_row gives is over this (m). A point in deep water that neither
    /// breaks nor shoals nonlinearly at this height is the open sea's whatever the sea's
    /// height there: its height is not asked (most of a march's points).
    double sea_height_bound = std::numeric_limits<double>::infinity();
    /// Where given (`across` values each), the march starts on its first row from this
    /// state instead of the incident wave, carrying `entering_phase` (MarchColumns): a
    /// march taken up again from a row it kept.
    std::span<const std::complex<double>> entering_amplitude;
    std::span<const char> entering_broken;
    double entering_phase = 0.0;
    /// Where given, the march keeps its state at every `every`-th point there on each row
    /// (MarchColumns).
    MarchColumns* keep_columns = nullptr;
    /// Where given, this march is a window of the march that kept `sides`, taken up at
    /// its row `sides_first_row`: its first and last points are held at that march's
    /// values at kept columns `side_lo` and
    /// `side_hi` (kNoSide: a wall, the longer march's own), so that over the same depths
    /// the window reproduces that march.
    const MarchColumns* sides = nullptr;
    static constexpr std::size_t kNoSide = static_cast<std::size_t>(-1);
    std::size_t side_lo = kNoSide, side_hi = kNoSide;
    int sides_first_row = 0;
    /// Where given, called after each step with the longer march's row it stands for
    /// (sides_first_row + step), the state (`across` values) and the phase it carries.
    std::function<void(std::size_t row, std::span<const std::complex<double>> amplitude, std::span<const char> broken,
                       double phase)>
        advanced;
    SurfZone surf;
    bool breaking = true;              ///< false: no breaking, no dissipation
    bool nonlinear_shoaling = true;    ///< false: linear shoaling only
    bool amplitude_dispersion = true;  ///< false: the phase at the linear speed
};

/// One row as the march leaves it: the complex amplitude A (m) of the surface elevation
/// A exp(i (phase - omega t)), whose phase is the integral of the rows' mean wavenumber
/// plus arg A, and where the wave is broken.
struct ParabolicRow {
    int step = 0;
    std::span<const std::complex<double>> amplitude;
    std::span<const char> broken;
};

/// A march of `input` a row at a time, from its first row (entered on construction) to its
/// last: two marches can go in step. The sides are walls (no flux across). `input` must
/// outlive it. Not copyable.
class ParabolicMarch {
  public:
    explicit ParabolicMarch(const ParabolicInput& input);
    ~ParabolicMarch();
    ParabolicMarch(const ParabolicMarch&) = delete;
    ParabolicMarch& operator=(const ParabolicMarch&) = delete;
    /// Whether the grid has a row (none when it has no steps or no points across).
    bool started() const { return state_ != nullptr; }
    /// The row the march is on (valid until the next advance).
    ParabolicRow row() const;
    /// Steps to the next row; false (and stays) at the last.
    bool advance();
    /// The phase common to the row the march is on (MarchColumns).
    double phase() const;

  private:
    struct State;
    void keep_columns();
    const ParabolicInput& in_;
    int step_ = 0;
    std::unique_ptr<State> state_;
};

/// The wavenumber of a wave of amplitude `amplitude` (m) at depth `depth` (m), whose linear
/// wavenumber is `k_linear`: Kirby and Dalrymple's (1986) amplitude dispersion, Stokes'
/// third order where the water is deep enough, Hedges' form where it is shallow.
double amplitude_dispersed_wavenumber(double omega, double depth, double amplitude, double k_linear);
/// The same from a table (the march's): within 2e-6 of it in shallow and intermediate
/// water (sqrt(omega^2 depth / g) under 2) for heights up to the depth; solved past that.
/// Thread-safe (the table is made on the first call).
double tabulated_amplitude_dispersed_wavenumber(double omega, double depth, double amplitude, double k_linear);

/// Weggel's (1972) breaker index H_b / h_b on a beach of slope `slope` (>= 0, used up to
/// 0.1) for a wave of height H (m) and period T (s): b - a H / (g T^2), at least 0.6.
double weggel_breaker_index(double slope, double height, double period);

/// Battjes and Janssen's (1978) share Q_b of broken waves in a Rayleigh sea of rms height
/// H_rms whose highest waves are H_max: 1 - Q_b = -(H_rms / H_max)^2 ln Q_b (0 where
/// H_rms / H_max <= 0.2, 1 from 1 up).
double broken_share(double rms_over_max);

/// Shuto's (1974) exponent n of H ~ h^n for nonlinear shoaling at Ursell number
/// U = g H T^2 / h^2: none (NaN) under 30, where linear shoaling holds; -2/7 to 50; then
/// from H h^(5/2) (sqrt(U) - 2 sqrt(3)) = const.
double shuto_exponent(double ursell);

}  // namespace tidewater::detail
