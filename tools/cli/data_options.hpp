// Measured-data options shared by `fit` and `inspect --data`: the file, its kind and
// format, CSV column mapping, unit scales and missing-value sentinels.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#if defined(TIDEWATER_HAVE_CALIBRATION)
#include "tidewater/calibration/record.hpp"
#include "tidewater/result.hpp"
#endif

namespace tidewater::cli {

struct DataOptions {
    std::string data, kind = "gauge", format;
    std::vector<std::string> columns, scales;
    std::vector<double> sentinels;
};

/// Adds --data, --kind, --format, --column, --scale and --sentinel to `cmd`.
void add_data_options(CLI::App* cmd, DataOptions& o);

#if defined(TIDEWATER_HAVE_CALIBRATION)
Result<calibration::RecordKind> parse_kind(const std::string& kind);
/// Reads the record the options name (format from the extension unless given).
Result<calibration::MeasuredRecord> read_data(const DataOptions& o, calibration::RecordKind kind);
#endif

}  // namespace tidewater::cli
