// CSV, Datawell raw and two-column text readers.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "record_file.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/detail/json_reader.hpp"

namespace tidewater::calibration {

namespace {

std::string trim(std::string_view s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r' || s[a] == '"')) ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r' || s[b - 1] == '"')) --b;
    return std::string(s.substr(a, b - a));
}

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t k = 0; k <= line.size(); ++k)
        if (k == line.size() || line[k] == sep) {
            out.push_back(trim(std::string_view(line).substr(start, k - start)));
            start = k + 1;
        }
    return out;
}

/// A number, or NaN for an empty/"nan"/"NaN" cell; false when the cell is not a number.
bool parse_cell(const std::string& cell, double& out) {
    if (cell.empty() || cell == "nan" || cell == "NaN" || cell == "NA" || cell == "-") {
        out = std::nan("");
        return true;
    }
    const char* first = cell.data();
    const char* last = first + cell.size();
    if (*first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

/// Puts the axis in seconds (or metres) from the first kept sample.
void rebase(MeasuredRecord& r) {
    if (r.axis.empty()) return;
    r.axis_origin = r.axis.front();
    for (double& a : r.axis) a -= r.axis_origin;
}

}  // namespace

Result<MeasuredRecord> read_csv_record(const std::filesystem::path& path, RecordKind kind, const CsvColumns& columns) {
    const std::string name = path.string();
    std::vector<std::string> roles = {kind == RecordKind::profile ? "x" : "t", "z"};
    if (kind == RecordKind::buoy) roles.insert(roles.end(), {"east", "north"});
    const std::set<std::string> known = {"t", "x", "z", "east", "north", "flag"};
    for (const auto& [role, column] : columns.role_to_column) {
        if (!known.count(role))
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: unknown role \"{}\" (roles: t, x, z, east, north, flag)", name, role)};
        if (role != "flag" && std::find(roles.begin(), roles.end(), role) == roles.end())
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: role \"{}\" is not used by {} data", name, role, to_string(kind))};
    }
    for (const auto& [role, factor] : columns.scale)
        if (!known.count(role) || !std::isfinite(factor) || factor == 0.0)
            return Error{
                ErrorCode::invalid_argument,
                fmt::format("{}: scale for \"{}\" must be a known role and a finite, non-zero number", name, role)};
    auto in = open_record_file(path);
    if (!in) return in.error();
    std::string line;
    if (!std::getline(*in, line) || trim(line).empty())
        return Error{ErrorCode::parse_error,
                     fmt::format("{}: the file is empty (a header row naming the columns is required)", name)};
    const char sep = line.find(',') != std::string::npos ? ',' : (line.find(';') != std::string::npos ? ';' : '\t');
    const std::vector<std::string> header = split(line, sep);
    std::string header_list;
    for (const auto& h : header) header_list += (header_list.empty() ? "" : ", ") + h;
    std::vector<std::string> used = roles;
    if (columns.role_to_column.count("flag")) used.push_back("flag");
    std::vector<std::size_t> index;
    for (const std::string& role : used) {
        const auto it = columns.role_to_column.find(role);
        const std::string column = it != columns.role_to_column.end() ? it->second : role;
        const auto pos = std::find(header.begin(), header.end(), column);
        if (pos == header.end())
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: no column \"{}\" for {} (the header has: {}); map it with --column {}=NAME",
                                     name, column, role, header_list, role)};
        index.push_back(static_cast<std::size_t>(pos - header.begin()));
    }
    auto scale_of = [&](const std::string& role) {
        const auto it = columns.scale.find(role);
        return it != columns.scale.end() ? it->second : 1.0;
    };
    MeasuredRecord r;
    r.kind = kind;
    r.source = name;
    std::size_t line_no = 1;
    while (std::getline(*in, line)) {
        ++line_no;
        if (trim(line).empty()) continue;
        const std::vector<std::string> cells = split(line, sep);
        double values[5];
        bool missing = false;
        for (std::size_t c = 0; c < used.size(); ++c) {
            if (index[c] >= cells.size())
                return Error{ErrorCode::parse_error,
                             fmt::format("{}:{}: {} cells, column \"{}\" is number {}", name, line_no, cells.size(),
                                         header[index[c]], index[c] + 1)};
            if (!parse_cell(cells[index[c]], values[c]))
                return Error{ErrorCode::parse_error, fmt::format("{}:{}: column \"{}\": \"{}\" is not a number", name,
                                                                 line_no, header[index[c]], cells[index[c]])};
            const bool sentinel =
                std::find(columns.sentinels.begin(), columns.sentinels.end(), values[c]) != columns.sentinels.end();
            if (c == 0 && !std::isfinite(values[c]))
                return Error{ErrorCode::parse_error, fmt::format("{}:{}: the {} is missing", name, line_no, used[0])};
            if (c > 0 && used[c] != "flag" && (!std::isfinite(values[c]) || sentinel)) missing = true;
        }
        if (used.back() == "flag") {
            const double flag = values[used.size() - 1];
            if (std::find(columns.good_flags.begin(), columns.good_flags.end(), flag) == columns.good_flags.end()) {
                ++r.skipped_flagged;
                continue;
            }
        }
        if (missing) {
            ++r.skipped_missing;
            continue;
        }
        r.axis.push_back(values[0] * scale_of(used[0]));
        r.z.push_back(values[1] * scale_of("z"));
        if (kind == RecordKind::buoy) {
            r.east.push_back(values[2] * scale_of("east"));
            r.north.push_back(values[3] * scale_of("north"));
        }
    }
    if (r.axis.empty())
        return Error{ErrorCode::invalid_argument, fmt::format("{}: no usable samples ({} missing, {} flagged)", name,
                                                              r.skipped_missing, r.skipped_flagged)};
    rebase(r);
    if (auto st = validate_record(r); !st) return st.error();
    return r;
}

Result<MeasuredRecord> read_datawell_raw(const std::filesystem::path& path) {
    auto in = open_record_file(path);
    if (!in) return in.error();
    MeasuredRecord r;
    r.kind = RecordKind::buoy;
    r.source = path.string();
    std::string line;
    std::size_t line_no = 0, sample = 0;
    while (std::getline(*in, line)) {
        ++line_no;
        if (trim(line).empty()) continue;
        const auto cells = split(line, ',');
        double v[4];
        if (cells.size() != 4 || !parse_cell(cells[0], v[0]) || !parse_cell(cells[1], v[1]) ||
            !parse_cell(cells[2], v[2]) || !parse_cell(cells[3], v[3]))
            return Error{ErrorCode::parse_error,
                         fmt::format("{}:{}: expected \"status, heave, north, west\" in cm", r.source, line_no)};
        const double t = static_cast<double>(sample++) / 1.28;
        if (v[0] != 0.0) {
            ++r.skipped_flagged;
            continue;
        }
        if (!std::isfinite(v[1]) || !std::isfinite(v[2]) || !std::isfinite(v[3])) {
            ++r.skipped_missing;
            continue;
        }
        r.axis.push_back(t);
        r.z.push_back(0.01 * v[1]);
        r.north.push_back(0.01 * v[2]);
        r.east.push_back(-0.01 * v[3]);  // the file's axis is west
    }
    if (r.axis.empty()) return Error{ErrorCode::invalid_argument, fmt::format("{}: no usable samples", r.source)};
    rebase(r);
    if (auto st = validate_record(r); !st) return st.error();
    return r;
}

Result<MeasuredRecord> read_two_column(const std::filesystem::path& path, RecordKind kind) {
    auto in = open_record_file(path);
    if (!in) return in.error();
    MeasuredRecord r;
    r.kind = kind;
    r.source = path.string();
    std::string line;
    std::size_t line_no = 0;
    while (std::getline(*in, line)) {
        ++line_no;
        std::istringstream cells(line);
        std::string a, b, extra;
        if (!(cells >> a)) continue;
        double v0 = 0.0, v1 = 0.0;
        if (!(cells >> b) || (cells >> extra) || !parse_cell(a, v0) || !parse_cell(b, v1))
            return Error{ErrorCode::parse_error, fmt::format("{}:{}: expected two numbers", r.source, line_no)};
        if (!std::isfinite(v0))
            return Error{ErrorCode::parse_error, fmt::format("{}:{}: the first column is missing", r.source, line_no)};
        if (!std::isfinite(v1)) {
            ++r.skipped_missing;
            continue;
        }
        r.axis.push_back(v0);
        r.z.push_back(v1);
    }
    if (r.axis.empty()) return Error{ErrorCode::invalid_argument, fmt::format("{}: no usable samples", r.source)};
    rebase(r);
    if (auto st = validate_record(r); !st) return st.error();
    return r;
}

Result<std::ifstream> open_record_file(const std::filesystem::path& path) {
    if (auto fits = detail::check_file_size(path, kMaxRecordFileBytes, "a record this reads"); !fits)
        return fits.error();
    std::ifstream in(path);
    if (!in) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", path.string())};
    return in;
}

}  // namespace tidewater::calibration
