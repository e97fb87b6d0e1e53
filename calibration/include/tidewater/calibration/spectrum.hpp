// Spectra of measured records and the spectral fit: Welch estimate, sea-state
// summary (Hs, Tp, direction), a JONSWAP (Hs, Tp, gamma) and cos-2s spreading fit
// with Ceres, and a deterministic preset sampled from the fitted spectrum.
// Units: Hz, m^2/Hz, m, s, degrees. Threading: reentrant.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "tidewater/calibration/record.hpp"
#include "tidewater/result.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::calibration {

struct WelchOptions {
    double segment_seconds = 200.0;  ///< Segment length (df = 1 / this), Hann window, 50% overlap.
};

struct MeasuredSpectrum {
    std::vector<double> frequency;  ///< Hz, bin centres from df.
    std::vector<double> density;    ///< Heave (or elevation) variance density, m^2/Hz.
    /// Buoy only: per bin, the direction of travel's vector (east, north) from the heave /
    /// horizontal quadrature spectrum, and r1 (0..1, how concentrated the direction is).
    std::vector<double> travel_east, travel_north, r1;
    std::vector<double> bandwidth;  ///< Hz per bin when bins differ (spectral files); empty: every bin is df wide.
    double df = 0.0;
    int segments = 0;
    bool directional = false;

    double width(std::size_t bin) const { return bandwidth.empty() ? df : bandwidth[bin]; }
    /// The bin whose centre is nearest to `f`, Hz.
    std::size_t nearest_bin(double f) const;
};

/// One spectrum from a spectral file, with what its producer reported for it.
struct SpectralRecord {
    double time_utc_s = 0.0;  ///< Start (CDIP) or stamp (NDBC), s since 1970.
    MeasuredSpectrum spectrum;
    double reported_hs = -1.0, reported_tp = -1.0, reported_dp = -1.0;  ///< m, s, degrees from (negative: not given)
};

/// Spectra of a CDIP spectral netCDF file (wave* variables: energy density, bandwidth,
/// a1/b1 relative to true north).
Result<std::vector<SpectralRecord>> read_cdip_spectra(const std::filesystem::path& path);
/// Spectra of an NDBC .data_spec file, with direction from the sibling .swdir (alpha1)
/// and .swr1 (r1) files when they are there. Newest first, as NDBC writes them.
Result<std::vector<SpectralRecord>> read_ndbc_spectra(const std::filesystem::path& data_spec);

/// Welch's estimate over the record's uniformly sampled runs (gaps split segments).
Result<MeasuredSpectrum> welch_spectrum(const MeasuredRecord& record, const WelchOptions& options = {});

struct SeaState {
    double hs = 0.0;               ///< 4 sqrt(m0) over the band, m.
    double tp = 0.0;               ///< 1 / peak frequency, s.
    double peak_from_deg = 0.0;    ///< Buoy only: direction waves come from at the peak, degrees clockwise from north.
    double mean_travel_deg = 0.0;  ///< Buoy only: energy-weighted direction of travel, degrees from east toward north.
    double spreading_s = 0.0;      ///< Buoy only: cos-2s spreading from r1 near the peak.
};

/// Summary over [f_lo, f_hi] Hz.
SeaState summarize(const MeasuredSpectrum& spectrum, double f_lo = 0.025, double f_hi = 0.58);

/// JONSWAP in Goda's form: S(f) = beta Hs^2 Tp^-4 f^-5 exp(-1.25 (Tp f)^-4) gamma^r,
/// with beta normalised numerically so that 4 sqrt(m0) = Hs.
struct JonswapFit {
    double hs = 0.0, tp = 0.0, gamma = 1.0;
    double mean_travel_deg = 0.0;  ///< From the buoy's directional moments (0 for 1-D data).
    double peak_from_deg = 0.0;  ///< Buoy: direction waves come from in the bin at 1/tp, degrees clockwise from north.
    double spreading_s = 0.0;    ///< cos-2s exponent (0 for 1-D data).
    double r2 = 0.0;             ///< Of the fitted density against the measured one, over the band.
    int iterations = 0;
};
double jonswap_density(double f, double hs, double tp, double gamma);

/// Fits the JONSWAP to `spectrum` over [f_lo, f_hi] with Ceres.
Result<JonswapFit> fit_jonswap(const MeasuredSpectrum& spectrum, double f_lo = 0.025, double f_hi = 0.58);

/// N waves that reproduce the fitted sea state: frequencies spanning the spectrum,
/// amplitudes from its density (sum A^2/2 = m0), directions from the spreading, phases
/// from `seed`, one Q for all so that sum(Q k A) = `fold` (at most Q = 1).
Result<std::vector<WaveSpec>> sample_preset_waves(const JonswapFit& fit, int count, std::uint64_t seed,
                                                  double fold = 0.6);

}  // namespace tidewater::calibration
