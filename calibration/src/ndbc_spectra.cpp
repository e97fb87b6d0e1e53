// NDBC real-time spectral files: .data_spec (energy density), .swdir (alpha1), .swr1 (r1).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "record_file.hpp"
#include "spectrum_direction.hpp"

namespace tidewater::calibration {

namespace {

struct Row {
    double time = 0.0;
    std::vector<double> values, freqs;
};

/// Rows of "YY MM DD hh mm [skip] value (freq) value (freq) ...", keyed by time.
Result<std::map<double, Row>> read_rows(const std::filesystem::path& path, int skip) {
    auto file = open_record_file(path);
    if (!file) return file.error();
    std::ifstream& in = *file;
    std::map<double, Row> rows;
    std::string line;
    std::size_t line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream cells(line);
        int y = 0, mo = 0, d = 0, h = 0, mi = 0;
        if (!(cells >> y >> mo >> d >> h >> mi) || mo < 1 || mo > 12 || d < 1 || d > 31)
            return Error{ErrorCode::parse_error,
                         fmt::format("{}:{}: expected YY MM DD hh mm first", path.string(), line_no)};
        for (int k = 0; k < skip; ++k) {
            double ignored = 0.0;
            cells >> ignored;
        }
        using namespace std::chrono;
        const sys_days date{year{y} / month{static_cast<unsigned>(mo)} / day{static_cast<unsigned>(d)}};
        Row row;
        row.time = static_cast<double>(date.time_since_epoch().count()) * 86400.0 + h * 3600.0 + mi * 60.0;
        std::string value, freq;
        while (cells >> value >> freq) {
            if (freq.size() < 3 || freq.front() != '(' || freq.back() != ')')
                return Error{ErrorCode::parse_error,
                             fmt::format("{}:{}: expected \"value (frequency)\" pairs", path.string(), line_no)};
            try {
                row.values.push_back(std::stod(value));
                row.freqs.push_back(std::stod(freq.substr(1, freq.size() - 2)));
            } catch (const std::exception&) {
                return Error{ErrorCode::parse_error,
                             fmt::format("{}:{}: \"{} {}\" is not a number pair", path.string(), line_no, value, freq)};
            }
        }
        if (row.values.empty())
            return Error{ErrorCode::parse_error, fmt::format("{}:{}: no spectrum on the line", path.string(), line_no)};
        // Each band's width is taken from its neighbours.
        if (row.values.size() < 2)
            return Error{ErrorCode::parse_error,
                         fmt::format("{}:{}: a spectrum needs two frequencies or more", path.string(), line_no)};
        for (std::size_t k = 1; k < row.freqs.size(); ++k)
            if (!(row.freqs[k] > row.freqs[k - 1]))
                return Error{ErrorCode::parse_error,
                             fmt::format("{}:{}: the frequencies do not increase ({} after {})", path.string(), line_no,
                                         row.freqs[k], row.freqs[k - 1])};
        rows[row.time] = std::move(row);
    }
    if (rows.empty()) return Error{ErrorCode::parse_error, fmt::format("{}: no spectra in the file", path.string())};
    return rows;
}

}  // namespace

Result<std::vector<SpectralRecord>> read_ndbc_spectra(const std::filesystem::path& data_spec) {
    auto energy = read_rows(data_spec, 1);  // .data_spec has a separation frequency after the time
    if (!energy) return energy.error();
    std::filesystem::path dir_path = data_spec, r1_path = data_spec;
    dir_path.replace_extension(".swdir");
    r1_path.replace_extension(".swr1");
    std::map<double, Row> directions, r1s;
    if (std::filesystem::exists(dir_path) && std::filesystem::exists(r1_path)) {
        auto d = read_rows(dir_path, 0);
        if (!d) return d.error();
        auto r = read_rows(r1_path, 0);
        if (!r) return r.error();
        directions = std::move(d).value();
        r1s = std::move(r).value();
    }
    std::vector<SpectralRecord> out;
    for (auto it = energy->rbegin(); it != energy->rend(); ++it) {  // newest first
        const Row& row = it->second;
        SpectralRecord r;
        r.time_utc_s = row.time;
        MeasuredSpectrum& s = r.spectrum;
        s.frequency = row.freqs;
        const std::size_t n = row.freqs.size();
        s.density.resize(n);
        s.bandwidth.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            s.density[k] = std::max(0.0, row.values[k]);
            // Band edges half way to the neighbours.
            const double lo =
                k > 0 ? 0.5 * (row.freqs[k - 1] + row.freqs[k]) : row.freqs[k] - 0.5 * (row.freqs[1] - row.freqs[0]);
            const double hi = k + 1 < n ? 0.5 * (row.freqs[k] + row.freqs[k + 1])
                                        : row.freqs[k] + 0.5 * (row.freqs[k] - row.freqs[k - 1]);
            s.bandwidth[k] = hi - lo;
        }
        s.df = s.bandwidth.empty() ? 0.0 : s.bandwidth[0];
        const auto d = directions.find(row.time), q = r1s.find(row.time);
        if (d != directions.end() && q != r1s.end() && d->second.values.size() == n && q->second.values.size() == n) {
            s.directional = true;
            s.travel_east.assign(n, 0.0), s.travel_north.assign(n, 0.0), s.r1.assign(n, 0.0);
            for (std::size_t k = 0; k < n; ++k)
                if (d->second.values[k] < 990.0 && q->second.values[k] < 990.0)
                    set_direction(s, k, d->second.values[k], q->second.values[k]);
        }
        out.push_back(std::move(r));
    }
    return out;
}

}  // namespace tidewater::calibration
