// What `tidewater fit` makes of one measured record (a window of a time series, or one
// spectrum of a spectral file): the preset, the report, the optional plot and series, and
// a summary line. Computing them writes nothing: the single fit and the farmed job's
// units (fit_farm.hpp) write them each in their own way.
#pragma once

#include <cstdint>
#include <string>

#include "data_options.hpp"

namespace tidewater::cli {

/// The fit's settings, as `tidewater fit`'s options give them (also in a build without
/// the calibration library, whose `fit` only says so).
struct FitArgs : DataOptions {
    std::string method = "phase", preset, report, series, plot, name, window;
    double depth = 0.0;
    int waves = 0, max_waves = 32, record_index = 0;
    unsigned threads = 1;
    std::uint64_t seed = 1;
    bool quiet = false;
};

}  // namespace tidewater::cli

#if defined(TIDEWATER_HAVE_CALIBRATION)

#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "tidewater/calibration/spectrum.hpp"
#include "tidewater/result.hpp"

namespace tidewater::cli {

/// The sea state a fit found, for summaries.
struct FitSummary {
    double hs_m = 0.0, tp_s = 0.0, mean_travel_deg = 0.0;
    double r2 = 0.0;  ///< the phase fit's R^2 of the series, or the spectral fit's of the spectrum's shape
    bool converged = true;
    int waves = 0;
};

struct FitProducts {
    nlohmann::json preset, report;
    std::string plot, series;  ///< empty unless asked for (FitArgs::plot, FitArgs::series)
    /// The first sample's time (s since 1970 where the file gives times so; s or m from
    /// the file's own origin otherwise) and whether it is a UTC time.
    double start = 0.0;
    bool start_is_utc = false;
    FitSummary summary;
};

/// Whether `a` names a spectral file (by --format or the file's extension).
bool is_spectral_file(const FitArgs& a);
/// The spectra of a spectral file (`a.format` ndbc or cdip-spectra, or an NDBC
/// .data_spec by its extension).
Result<std::vector<calibration::SpectralRecord>> read_spectral_file(const FitArgs& a);
/// A JONSWAP fit of spectrum `index` of a spectral file, and a preset sampled from it.
Result<FitProducts> fit_spectral_record(const FitArgs& a, const calibration::SpectralRecord& record, int index);
/// A phase-resolved or spectral fit of the time series (or profile) `a.data`, cut to
/// `a.window` when given; `say` receives progress lines.
Result<FitProducts> fit_series(const FitArgs& a, const std::function<void(const std::string&)>& say);

}  // namespace tidewater::cli

#endif
