// Readers for measured surface data. Every failure names the file and, where
// there is one, the line and column. Missing and flagged samples are skipped and
// counted, never fitted.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tidewater/calibration/record.hpp"
#include "tidewater/result.hpp"

namespace tidewater::calibration {

/// Which CSV column holds each quantity. Roles: "t" (s, gauge and buoy), "x" (m,
/// profile), "z" (m, up), "east" and "north" (m, buoy), "flag" (optional quality flag).
struct CsvColumns {
    std::map<std::string, std::string> role_to_column;
    std::map<std::string, double> scale;  ///< Per role: value in file units times this = SI (e.g. z=0.01 for cm).
    std::vector<double> sentinels{-999.0, -999.9, -999.99, -9999.0, 9999.0, 99999.0};  ///< Values meaning "missing".
    std::vector<double> good_flags{0.0, 1.0, 2.0};  ///< Flag values kept (others are flagged bad).
};

/// Reads a CSV file with a header row. The kind decides which roles are required.
Result<MeasuredRecord> read_csv_record(const std::filesystem::path& path, RecordKind kind, const CsvColumns& columns);

/// Reads a CDIP netCDF-4 file's XYZ group (x = north, y = west, z = up; FlagPrimary 9 is
/// missing) as a buoy record. With start/end (s since 1970, end > start) only samples whose
/// true time (stored time minus the filter delay) lies in [start, end) are kept.
Result<MeasuredRecord> read_cdip_xyz(const std::filesystem::path& path, double start_utc_s = -1.0,
                                     double end_utc_s = -1.0);

/// One spectral summary CDIP computed for a half-hour (the netCDF Wave group).
struct CdipWaveSummary {
    double start_utc_s = 0.0, end_utc_s = 0.0;  ///< The record's time bounds, s since 1970.
    double hs = 0.0;                            ///< m
    double tp = 0.0;                            ///< s
    double dp = 0.0;                            ///< Peak direction waves come from, degrees true.
};
Result<std::vector<CdipWaveSummary>> read_cdip_wave_summaries(const std::filesystem::path& path);

/// A Datawell raw file ("status, heave, north, west" in cm at 1.28 Hz) as a buoy record.
Result<MeasuredRecord> read_datawell_raw(const std::filesystem::path& path);

/// A two-column whitespace-separated file (axis, value), e.g. wave-tank probes, with
/// NaN rows skipped and counted.
Result<MeasuredRecord> read_two_column(const std::filesystem::path& path, RecordKind kind);

/// Checks what a fit needs: at least 8 samples, a strictly increasing axis, finite
/// values that are not all equal. Messages name the record's source.
Status validate_record(const MeasuredRecord& record);

}  // namespace tidewater::calibration
