// Measured surface data, read from CSV, CDIP netCDF or Datawell raw files, ready to fit.
//
// Axes: heave/elevation z is up. Horizontal buoy displacement is east and north;
// the runtime's x is east and z is north, so a direction of travel in degrees
// "from +x toward +z" is counter-clockwise from east (docs/calibration.md).
// Units: metres, seconds. Threading: plain values; readers are reentrant.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace tidewater::calibration {

enum class RecordKind {
    gauge,    ///< Elevation z(t) at a fixed point (Eulerian).
    buoy,     ///< A floating buoy's east/north/heave displacement over time (Lagrangian).
    profile,  ///< Elevation z(x) along a line at one instant.
};

const char* to_string(RecordKind kind);

struct MeasuredRecord {
    RecordKind kind = RecordKind::gauge;
    std::string source;         ///< File name, for messages and reports.
    std::vector<double> axis;   ///< Time, s (gauge, buoy; from the first kept sample) or position, m (profile).
    std::vector<double> z;      ///< Elevation or heave, m, up.
    std::vector<double> east;   ///< Buoy only, m.
    std::vector<double> north;  ///< Buoy only, m.
    double axis_origin = 0.0;   ///< The file's axis value of axis[0] (s or m).
    double depth = std::numeric_limits<double>::infinity();  ///< Water depth, m; finite: finite-depth dispersion.
    std::size_t skipped_missing = 0;                         ///< Empty, NaN or sentinel values.
    std::size_t skipped_flagged = 0;                         ///< Samples a quality flag marks bad.

    std::size_t size() const { return axis.size(); }
    /// Median spacing of the axis (s or m).
    double median_spacing() const;
};

}  // namespace tidewater::calibration
