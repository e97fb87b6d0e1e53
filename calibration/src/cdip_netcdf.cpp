// CDIP netCDF-4 buoy files (the only translation unit that includes netCDF).
#include <fmt/format.h>
#include <netcdf.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>

#include "netcdf_classic_header.hpp"
#include "spectrum_direction.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/calibration/spectrum.hpp"

namespace tidewater::calibration {

namespace {

/// The most values one variable may hold (2^27 doubles, 1 GiB: a year of CDIP's 1.28 Hz
/// displacements is 40 million).
constexpr std::size_t kMaxVariableValues = std::size_t{1} << 27;

class NcFile {
  public:
    explicit NcFile(const std::filesystem::path& path) : name_(path.string()) {
        // A classic file's header is checked first: netCDF sizes its buffers from it.
        misfit_ = classic_header_misfit(path);
        if (!misfit_.empty()) {
            status_ = NC_ENOTNC;
            return;
        }
        status_ = nc_open(name_.c_str(), NC_NOWRITE, &id_);
    }
    ~NcFile() {
        if (status_ == NC_NOERR) nc_close(id_);
    }
    NcFile(const NcFile&) = delete;
    NcFile& operator=(const NcFile&) = delete;

    Status opened() const {
        if (status_ == NC_NOERR) return {};
        return Error{ErrorCode::io_error, fmt::format("{}: not a readable netCDF file ({})", name_,
                                                      misfit_.empty() ? nc_strerror(status_) : misfit_)};
    }
    Result<int> group(const char* name) const {
        int g = 0;
        if (nc_inq_grp_ncid(id_, name, &g) != NC_NOERR)
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: no {} group (CDIP buoy files keep displacements in XYZ and "
                                     "spectra in Wave)",
                                     name_, name)};
        return g;
    }
    /// A whole variable of `group` as doubles, with its length.
    Result<std::vector<double>> doubles(int g, const char* group, const char* var) const {
        int v = 0;
        if (nc_inq_varid(g, var, &v) != NC_NOERR)
            return Error{ErrorCode::schema_error, fmt::format("{}: {}/{} is missing", name_, group, var)};
        int dims = 0;
        nc_inq_varndims(g, v, &dims);
        std::size_t count = 1;
        if (dims > 0) {
            std::vector<int> ids(static_cast<std::size_t>(dims));
            nc_inq_vardimid(g, v, ids.data());
            for (int id : ids) {
                std::size_t len = 0;
                nc_inq_dimlen(g, id, &len);
                // The header says how many values there are: bounded before they are allocated.
                if (len > 0 && count > kMaxVariableValues / len)
                    return Error{ErrorCode::invalid_argument,
                                 fmt::format("{}: {}/{} holds more than {} values: not a record this reads", name_,
                                             group, var, kMaxVariableValues)};
                count *= len;
            }
        }
        std::vector<double> out(count);
        if (count > 0 && nc_get_var_double(g, v, out.data()) != NC_NOERR)
            return Error{ErrorCode::io_error, fmt::format("{}: {}/{} cannot be read as numbers", name_, group, var)};
        return out;
    }
    /// Several variables of `group`, by name; fails on the first missing one.
    Result<std::map<std::string, std::vector<double>>> read_all(int g, const char* group,
                                                                std::initializer_list<const char*> names) const {
        std::map<std::string, std::vector<double>> out;
        for (const char* name : names) {
            auto v = doubles(g, group, name);
            if (!v) return v.error();
            out[name] = std::move(v).value();
        }
        return out;
    }
    /// The epoch of a "UNIT since YYYY-MM-DD HH:MM:SS[.f]" units attribute: seconds since 1970 and seconds per unit.
    Result<std::pair<double, double>> time_units(int g, const char* group, const char* var) const {
        int v = 0;
        std::size_t len = 0;
        if (nc_inq_varid(g, var, &v) != NC_NOERR || nc_inq_attlen(g, v, "units", &len) != NC_NOERR || len > 200)
            return Error{ErrorCode::schema_error, fmt::format("{}: {}/{} has no time units", name_, group, var)};
        std::string units(len, '\0');
        nc_get_att_text(g, v, "units", units.data());
        char unit[32] = {0};
        int y = 0, mo = 0, d = 0, h = 0, mi = 0;
        double s = 0.0;
        if (std::sscanf(units.c_str(), "%31s since %d-%d-%d %d:%d:%lf", unit, &y, &mo, &d, &h, &mi, &s) != 7)
            return Error{ErrorCode::schema_error, fmt::format("{}: {}/{} units \"{}\" are not \"UNIT since DATE TIME\"",
                                                              name_, group, var, units)};
        const std::string u = unit;
        const double scale = u == "nanoseconds" ? 1e-9
                             : u == "seconds"   ? 1.0
                             : u == "minutes"   ? 60.0
                             : u == "hours"     ? 3600.0
                             : u == "days"      ? 86400.0
                                                : 0.0;
        if (scale == 0.0)
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: {}/{} has unknown time unit \"{}\"", name_, group, var, u)};
        using namespace std::chrono;
        const sys_days date{year{y} / month{static_cast<unsigned>(mo)} / day{static_cast<unsigned>(d)}};
        const double epoch =
            static_cast<double>(date.time_since_epoch().count()) * 86400.0 + h * 3600.0 + mi * 60.0 + s;
        return std::pair{epoch, scale};
    }
    const std::string& name() const { return name_; }
    int root() const { return id_; }

  private:
    std::string name_;
    int id_ = 0;
    int status_ = NC_NOERR;
    std::string misfit_;  ///< why a classic header does not fit its file
};

}  // namespace

Result<MeasuredRecord> read_cdip_xyz(const std::filesystem::path& path, double start_utc_s, double end_utc_s) {
    NcFile nc(path);
    if (auto st = nc.opened(); !st) return st.error();
    auto g = nc.group("XYZ");
    if (!g) return g.error();
    auto vars = nc.read_all(*g, "XYZ", {"x", "y", "z", "FlagPrimary", "t", "FilterDelay"});
    if (!vars) return vars.error();
    // CDIP's x is north, y west (PROVENANCE.md's cross-phase check).
    const auto *north = &(*vars)["x"], *west = &(*vars)["y"], *z = &(*vars)["z"], *flags = &(*vars)["FlagPrimary"],
               *t = &(*vars)["t"];
    const auto* delay = &(*vars)["FilterDelay"];
    auto units = nc.time_units(*g, "XYZ", "t");
    if (!units) return units.error();
    const std::size_t n = z->size();
    if (north->size() != n || west->size() != n || flags->size() != n || t->size() != n)
        return Error{ErrorCode::schema_error, fmt::format("{}: XYZ variables have different lengths", nc.name())};
    const double filter_delay = delay->empty() ? 0.0 : delay->front();
    // The displacements are along magnetic north; turn them to true north with the
    // station's declination (Meta/Declination, degrees east), as CDIP's directions are.
    double declination = 0.0;
    if (auto meta = nc.group("Meta")) {
        if (auto d = nc.doubles(*meta, "Meta", "Declination"); d && !d->empty() && std::isfinite(d->front()))
            declination = d->front();
    }
    const double dr = declination * 3.14159265358979323846 / 180.0;
    const double cd = std::cos(dr), sd = std::sin(dr);
    const bool window = end_utc_s > start_utc_s && start_utc_s >= 0.0;
    MeasuredRecord r;
    r.kind = RecordKind::buoy;
    r.source = nc.name();
    for (std::size_t k = 0; k < n; ++k) {
        const double when = units->first + (*t)[k] * units->second - filter_delay;  // true sample time
        if (window && (when < start_utc_s || when >= end_utc_s)) continue;
        if ((*flags)[k] != 1.0 && (*flags)[k] != 2.0) {  // 1 good, 2 not evaluated (real time); 9 missing
            ++r.skipped_flagged;
            continue;
        }
        if (!std::isfinite((*z)[k]) || (*z)[k] <= -999.0 || (*north)[k] <= -999.0 || (*west)[k] <= -999.0) {
            ++r.skipped_missing;
            continue;
        }
        r.axis.push_back(when);
        r.z.push_back((*z)[k]);
        // A bearing grows clockwise: true = magnetic + declination.
        const double e = -(*west)[k], n_ = (*north)[k];
        r.east.push_back(e * cd + n_ * sd);
        r.north.push_back(-e * sd + n_ * cd);
    }
    if (r.axis.empty())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: no usable XYZ samples{} ({} flagged, {} missing)", nc.name(),
                                 window ? " in the time window" : "", r.skipped_flagged, r.skipped_missing)};
    r.axis_origin = r.axis.front();
    for (double& a : r.axis) a -= r.axis_origin;
    if (auto st = validate_record(r); !st) return st.error();
    return r;
}

Result<std::vector<CdipWaveSummary>> read_cdip_wave_summaries(const std::filesystem::path& path) {
    NcFile nc(path);
    if (auto st = nc.opened(); !st) return st.error();
    auto g = nc.group("Wave");
    if (!g) return g.error();
    auto vars = nc.read_all(*g, "Wave", {"Hs", "Tp", "Dp", "TimeBounds"});
    if (!vars) return vars.error();
    const auto *hs = &(*vars)["Hs"], *tp = &(*vars)["Tp"], *dp = &(*vars)["Dp"], *bounds = &(*vars)["TimeBounds"];
    auto units = nc.time_units(*g, "Wave", "TimeBounds");
    if (!units) return units.error();
    if (tp->size() != hs->size() || dp->size() != hs->size() || bounds->size() != 2 * hs->size())
        return Error{ErrorCode::schema_error, fmt::format("{}: Wave variables have different lengths", nc.name())};
    std::vector<CdipWaveSummary> out(hs->size());
    for (std::size_t k = 0; k < out.size(); ++k) {
        out[k].hs = (*hs)[k];
        out[k].tp = (*tp)[k];
        out[k].dp = (*dp)[k];
        out[k].start_utc_s = units->first + (*bounds)[2 * k] * units->second;
        out[k].end_utc_s = units->first + (*bounds)[2 * k + 1] * units->second;
    }
    return out;
}

void set_direction(MeasuredSpectrum& s, std::size_t k, double from_deg, double r1) {
    const double to = (from_deg + 180.0) * 3.14159265358979323846 / 180.0;  // bearing of travel
    s.travel_east[k] = s.density[k] * r1 * std::sin(to);
    s.travel_north[k] = s.density[k] * r1 * std::cos(to);
    s.r1[k] = r1;
}

Result<std::vector<SpectralRecord>> read_cdip_spectra(const std::filesystem::path& path) {
    NcFile nc(path);
    if (auto st = nc.opened(); !st) return st.error();
    const int root = nc.root();
    auto vars = nc.read_all(
        root, "", {"waveFrequency", "waveBandwidth", "waveEnergyDensity", "waveA1Value", "waveB1Value", "waveTime"});
    if (!vars) return vars.error();
    const auto *freq = &(*vars)["waveFrequency"], *width = &(*vars)["waveBandwidth"],
               *energy = &(*vars)["waveEnergyDensity"];
    const auto *a1 = &(*vars)["waveA1Value"], *b1 = &(*vars)["waveB1Value"], *time = &(*vars)["waveTime"];
    auto units = nc.time_units(root, "", "waveTime");
    if (!units) return units.error();
    auto hs = nc.doubles(root, "", "waveHs"), tp = nc.doubles(root, "", "waveTp"), dp = nc.doubles(root, "", "waveDp");
    const std::size_t nf = freq->size(), nt = time->size();
    if (width->size() != nf || energy->size() != nt * nf || a1->size() != nt * nf || b1->size() != nt * nf)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: wave spectrum variables have inconsistent sizes", nc.name())};
    std::vector<SpectralRecord> out(nt);
    for (std::size_t t = 0; t < nt; ++t) {
        SpectralRecord& r = out[t];
        r.time_utc_s = units->first + (*time)[t] * units->second;
        if (hs && hs->size() == nt) r.reported_hs = (*hs)[t];
        if (tp && tp->size() == nt) r.reported_tp = (*tp)[t];
        if (dp && dp->size() == nt) r.reported_dp = (*dp)[t];
        MeasuredSpectrum& s = r.spectrum;
        s.frequency = *freq;
        s.bandwidth = *width;
        s.df = (*width)[0];
        s.directional = true;
        s.density.resize(nf), s.travel_east.resize(nf), s.travel_north.resize(nf), s.r1.resize(nf);
        for (std::size_t k = 0; k < nf; ++k) {
            const double e = (*energy)[t * nf + k];
            s.density[k] = std::isfinite(e) && e > 0.0 ? e : 0.0;
            // CDIP's a1, b1 are relative to true north: the mean direction waves come from.
            const double x = (*a1)[t * nf + k], y = (*b1)[t * nf + k];
            if (std::isfinite(x) && std::isfinite(y))
                set_direction(s, k, std::atan2(y, x) * 180.0 / 3.14159265358979323846, std::hypot(x, y));
        }
    }
    return out;
}

}  // namespace tidewater::calibration
