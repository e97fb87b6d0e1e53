#include "data_options.hpp"

#include <fmt/format.h>

#if defined(TIDEWATER_HAVE_CALIBRATION)
#include "tidewater/calibration/readers.hpp"
#endif

namespace tidewater::cli {

void add_data_options(CLI::App* cmd, DataOptions& o) {
    cmd->add_option("--data", o.data,
                    "Measured data: CSV with a header, CDIP netCDF (.nc), Datawell raw (.raw) or two columns");
    cmd->add_option("--kind", o.kind,
                    "gauge (elevation at a point), buoy (east/north/heave) or profile (elevation along x)")
        ->capture_default_str();
    cmd->add_option("--format", o.format,
                    "csv, cdip (x/y/z), datawell, columns, or the spectral files cdip-spectra and ndbc (.data_spec) "
                    "(default: from the extension)");
    cmd->add_option("--column", o.columns, "ROLE=NAME: the CSV column for t, x, z, east, north or flag");
    cmd->add_option("--scale", o.scales, "ROLE=FACTOR: file units to metres or seconds (e.g. z=0.01 for cm)");
    cmd->add_option("--sentinel", o.sentinels,
                    "A value that means missing (default: -999, -999.9, -999.99, -9999, 9999, 99999)");
}

#if defined(TIDEWATER_HAVE_CALIBRATION)
using namespace tidewater::calibration;

namespace {

Result<std::pair<std::string, std::string>> split_pair(const std::string& s, const char* option) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
        return Error{ErrorCode::invalid_argument, fmt::format("{} \"{}\": expected ROLE=VALUE", option, s)};
    return std::pair{s.substr(0, eq), s.substr(eq + 1)};
}

}  // namespace

Result<RecordKind> parse_kind(const std::string& kind) {
    if (kind == "gauge") return RecordKind::gauge;
    if (kind == "buoy") return RecordKind::buoy;
    if (kind == "profile") return RecordKind::profile;
    return Error{ErrorCode::invalid_argument, fmt::format("--kind {}: use gauge, buoy or profile", kind)};
}

Result<MeasuredRecord> read_data(const DataOptions& a, RecordKind kind) {
    std::string format = a.format;
    const std::string ext = std::filesystem::path(a.data).extension().string();
    if (format.empty()) format = ext == ".nc" ? "cdip" : ext == ".raw" ? "datawell" : ext == ".csv" ? "csv" : "columns";
    if (format == "cdip" || format == "datawell") {
        if (kind != RecordKind::buoy)
            return Error{ErrorCode::invalid_argument, fmt::format("{} files hold buoy data: give --kind buoy", format)};
        return format == "cdip" ? read_cdip_xyz(a.data) : read_datawell_raw(a.data);
    }
    if (format == "columns") return read_two_column(a.data, kind);
    if (format != "csv")
        return Error{ErrorCode::invalid_argument,
                     fmt::format("--format {}: use csv, cdip, datawell or columns", format)};
    CsvColumns columns;
    for (const auto& c : a.columns) {
        auto p = split_pair(c, "--column");
        if (!p) return p.error();
        columns.role_to_column[p->first] = p->second;
    }
    for (const auto& c : a.scales) {
        auto p = split_pair(c, "--scale");
        if (!p) return p.error();
        double v = 0.0;
        try {
            std::size_t used = 0;
            v = std::stod(p->second, &used);
            if (used != p->second.size()) throw std::invalid_argument("trailing");
        } catch (const std::exception&) {
            return Error{ErrorCode::invalid_argument,
                         fmt::format("--scale {}: \"{}\" is not a number", p->first, p->second)};
        }
        columns.scale[p->first] = v;
    }
    if (!a.sentinels.empty()) columns.sentinels = a.sentinels;
    return read_csv_record(a.data, kind, columns);
}

#endif

}  // namespace tidewater::cli
