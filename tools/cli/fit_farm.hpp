// `tidewater fit --manifest M --out DIR [--task N | --status | --merge]`: a batch of fits
// as a farmed job (farm_job.hpp, docs/scale-out.md). The manifest lists units, one record
// file each, with the windows (time series) or spectra (spectral files) to fit; unit N
// writes a preset and a report per window or spectrum, named by station and time. The
// merge writes DIR/library/: every preset, and summary.csv (Hs, Tp, direction, R^2,
// converged per preset). Without --task, --status or --merge every unit not done runs in
// order, then the merge: the serial run of the whole job.
#pragma once

#include <string>

#include "fit_products.hpp"

namespace tidewater::cli {

struct FitFarmArgs {
    std::string manifest, out;
    int task = -1;  ///< -1: every unit, then the merge
    bool status = false, merge = false;
};

#if defined(TIDEWATER_HAVE_CALIBRATION)
/// Runs the farmed job's step `f` asks for; `defaults` gives what the manifest's units
/// leave out (and --quiet, --threads). Returns the process's exit code.
int run_fit_farm(const FitFarmArgs& f, const FitArgs& defaults);
#endif

}  // namespace tidewater::cli
