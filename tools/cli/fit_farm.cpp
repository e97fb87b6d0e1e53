#include "fit_farm.hpp"

#if defined(TIDEWATER_HAVE_CALIBRATION)

#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "farm_job.hpp"
#include "tidewater/detail/atomic_folder.hpp"
#include "tidewater/detail/json_reader.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace fs = std::filesystem;

namespace {

constexpr const char* kVerb = "fit";

/// One unit: a record file and what to fit in it.
struct FitUnit {
    FitArgs args;                 ///< data resolved against the manifest's folder
    std::string data_as_written;  ///< the manifest's own path, for messages and the summary
    std::string station;
    std::vector<std::string> windows;  ///< time series: "A:B" each; none: the whole record
    std::vector<int> records;          ///< spectral files: which spectra; none: all
};

/// The largest manifest read, units.
constexpr std::int64_t kMaxUnits = 1000000;

Result<std::vector<FitUnit>> read_manifest(const std::string& path, const FitArgs& defaults) {
    auto text = detail::read_text_file(path);
    if (!text) return text.error();
    auto doc = detail::parse_json_text(*text, path);
    if (!doc) return doc.error();
    auto top = detail::ObjectReader::open(*doc, path, "");
    if (!top) return top.error();
    if (auto st = top->allow_only({"version", "units"}); !st) return st.error();
    std::int64_t version = 0;
    if (auto st = top->integer("version", version, 1, 1, true); !st) return st.error();
    if (!top->has("units") || !top->at("units").is_array() || top->at("units").empty())
        return top->error("units", "must be a non-empty array of units");
    if (static_cast<std::int64_t>(top->at("units").size()) > kMaxUnits)
        return top->error("units", fmt::format("{} units: at most {}", top->at("units").size(), kMaxUnits));
    const fs::path folder = fs::path(path).parent_path();
    std::vector<FitUnit> units;
    for (std::size_t u = 0; u < top->at("units").size(); ++u) {
        auto r = detail::ObjectReader::open(top->at("units")[u], path, fmt::format("/units/{}", u));
        if (!r) return r.error();
        if (auto st = r->allow_only({"data", "station", "kind", "format", "columns", "scales", "sentinels", "method",
                                     "depth", "waves", "max_waves", "seed", "windows", "records"});
            !st)
            return st.error();
        FitUnit unit;
        unit.args = defaults;
        unit.args.preset.clear(), unit.args.report.clear(), unit.args.plot.clear(), unit.args.series.clear();
        unit.args.window.clear(), unit.args.name.clear();
        if (auto st = r->string("data", unit.data_as_written, true); !st) return st.error();
        const fs::path data(unit.data_as_written);
        unit.args.data = (data.is_absolute() ? data : folder / data).string();
        unit.station = data.stem().string();
        std::int64_t waves = unit.args.waves, max_waves = unit.args.max_waves, seed = 0;
        for (auto [key, out] : {std::pair{"station", &unit.station}, std::pair{"kind", &unit.args.kind},
                                std::pair{"format", &unit.args.format}, std::pair{"method", &unit.args.method}})
            if (auto st = r->string(key, *out); !st) return st.error();
        if (unit.station.empty() || unit.station.find_first_of("/\\") != std::string::npos)
            return r->error("station", "must be a name without slashes (it names the presets)");
        if (auto kind = parse_kind(unit.args.kind); !kind) return r->error("kind", kind.error().message);
        if (unit.args.method != "phase" && unit.args.method != "spectral")
            return r->error("method", fmt::format("\"{}\": use phase or spectral", unit.args.method));
        if (auto st = r->number("depth", unit.args.depth); !st) return st.error();
        if (!(unit.args.depth >= 0.0) || !std::isfinite(unit.args.depth))
            return r->error("depth", "must be a finite number of metres (0 = deep water)");
        if (auto st = r->integer("waves", waves, 0, 256); !st) return st.error();
        if (auto st = r->integer("max_waves", max_waves, 1, 256); !st) return st.error();
        if (r->has("seed")) {
            if (auto st = r->integer("seed", seed, 0, std::int64_t{1} << 53); !st) return st.error();
            unit.args.seed = static_cast<std::uint64_t>(seed);
        }
        unit.args.waves = static_cast<int>(waves), unit.args.max_waves = static_cast<int>(max_waves);
        // "columns": {"z": "height"} and "scales": {"z": 0.01}, as --column z=height and --scale z=0.01.
        for (const char* key : {"columns", "scales"}) {
            if (!r->has(key)) continue;
            if (!r->at(key).is_object()) return r->error(key, "must be an object of role: value");
            auto& list = std::string_view(key) == "columns" ? unit.args.columns : unit.args.scales;
            list.clear();
            for (const auto& [role, value] : r->at(key).items()) {
                if (std::string_view(key) == "columns" ? !value.is_string() : !value.is_number())
                    return r->error(key, fmt::format("{}: must be a {}", role,
                                                     std::string_view(key) == "columns" ? "column name" : "number"));
                list.push_back(role + "=" + (value.is_string() ? value.get<std::string>() : value.dump()));
            }
        }
        if (r->has("sentinels")) {
            const auto& s = r->at("sentinels");
            if (!s.is_array()) return r->error("sentinels", "must be an array of numbers");
            unit.args.sentinels.clear();
            for (const auto& v : s) {
                if (!v.is_number()) return r->error("sentinels", "must be an array of numbers");
                unit.args.sentinels.push_back(v.get<double>());
            }
        }
        if (r->has("windows")) {
            const auto& w = r->at("windows");
            if (!w.is_array() || w.empty()) return r->error("windows", "must be a non-empty array of \"A:B\"");
            for (const auto& v : w) {
                if (!v.is_string()) return r->error("windows", "must be a non-empty array of \"A:B\"");
                unit.windows.push_back(v.get<std::string>());
            }
        }
        if (r->has("records")) {
            const auto& rec = r->at("records");
            if (!(rec.is_string() && rec.get<std::string>() == "all")) {
                if (!rec.is_array() || rec.empty())
                    return r->error("records", "must be \"all\" or a non-empty array of spectrum indices");
                for (const auto& v : rec) {
                    if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > INT32_MAX)
                        return r->error("records", "must be \"all\" or a non-empty array of spectrum indices");
                    unit.records.push_back(v.get<int>());
                }
            }
        }
        if (is_spectral_file(unit.args) && !unit.windows.empty())
            return r->error("windows", "a spectral file's unit picks spectra with \"records\", not windows");
        if (!is_spectral_file(unit.args) && !unit.records.empty())
            return r->error("records", "only a spectral file's unit picks spectra");
        units.push_back(std::move(unit));
    }
    return units;
}

/// "STATION_20240102T000000Z" for UTC starts; "STATION_t300s" (or _x12m for a profile)
/// for times from the file's own origin.
std::string preset_name(const std::string& station, const FitProducts& fit, bool profile) {
    if (fit.start_is_utc) {
        const std::time_t t = static_cast<std::time_t>(std::floor(fit.start));
        std::tm tm{};
        gmtime_r(&t, &tm);
        char stamp[32];
        std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
        return station + "_" + stamp;
    }
    std::string n = fmt::format("{:.3f}", fit.start);
    while (n.back() == '0') n.pop_back();
    if (n.back() == '.') n.pop_back();
    return fmt::format("{}_{}{}{}", station, profile ? "x" : "t", n, profile ? "m" : "s");
}

Status write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", path.string())};
    return {};
}

/// Fits unit `u` into `folder`: a preset and a report per window or spectrum, and unit.json.
Status fit_unit(const FitUnit& u, std::size_t task, const fs::path& folder) {
    auto say = [&](const std::string& s) {
        if (!u.args.quiet) std::fprintf(stderr, "%s\n", s.c_str());
    };
    std::vector<std::pair<std::string, Result<FitProducts>>> fits;  // (window or record, fit)
    if (is_spectral_file(u.args)) {
        auto records = read_spectral_file(u.args);
        if (!records) return records.error();
        std::vector<int> picked = u.records;
        if (picked.empty())
            for (int k = 0; k < static_cast<int>(records->size()); ++k) picked.push_back(k);
        for (int k : picked) {
            if (k >= static_cast<int>(records->size()))
                return Error{ErrorCode::invalid_argument, fmt::format("{}: spectrum {}: the file has spectra 0 to {}",
                                                                      u.data_as_written, k, records->size() - 1)};
            fits.emplace_back(fmt::format("spectrum {}", k),
                              fit_spectral_record(u.args, (*records)[static_cast<std::size_t>(k)], k));
        }
    } else if (u.windows.empty()) {
        fits.emplace_back("whole record", fit_series(u.args, say));
    } else {
        for (const std::string& w : u.windows) {
            FitArgs a = u.args;
            a.window = w;
            fits.emplace_back("window " + w, fit_series(a, say));
        }
    }
    nlohmann::json rows = nlohmann::json::array();
    std::set<std::string> names;
    for (auto& [what, fit] : fits) {
        if (!fit) return Error{fit.error().code, fmt::format("{}: {}", what, fit.error().message)};
        const std::string name = preset_name(u.station, *fit, u.args.kind == "profile");
        if (!names.insert(name).second)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: two of its fits start at the same time and would both be {}",
                                     u.data_as_written, name)};
        fit->preset["name"] = name;
        if (auto st = write_text(folder / (name + ".json"), fit->preset.dump(2) + "\n"); !st) return st;
        if (auto st = write_text(folder / (name + ".report.json"), fit->report.dump(2) + "\n"); !st) return st;
        const FitSummary& s = fit->summary;
        rows.push_back({{"name", name},
                        {"what", what},
                        {"start", fit->start},
                        {"start_is_utc", fit->start_is_utc},
                        {"hs_m", s.hs_m},
                        {"tp_s", s.tp_s},
                        {"mean_travel_deg", s.mean_travel_deg},
                        {"r2", s.r2},
                        {"converged", s.converged},
                        {"waves", s.waves}});
    }
    const nlohmann::json unit = {{"unit", task}, {"data", u.data_as_written}, {"station", u.station}, {"fits", rows}};
    return write_text(folder / "unit.json", unit.dump(2) + "\n");
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

/// The library: every unit's presets, and summary.csv, in the units' order.
Status merge(const farm::JobFolder& job, const std::vector<FitUnit>& units) {
    auto describe = [&](std::size_t t) { return units[t].data_as_written; };
    if (auto st = farm::require_all_done(job, units.size(), describe); !st) return st;
    return detail::write_folder_atomically(job.out() / "library", [&](const fs::path& library) -> Status {
        std::string csv = "name,station,data,fitted,start,hs_m,tp_s,mean_travel_deg,r2,converged,waves\n";
        std::map<std::string, std::size_t> owner;
        for (std::size_t t = 0; t < units.size(); ++t) {
            const fs::path folder = job.unit_folder(t);
            auto text = detail::read_text_file((folder / "unit.json").string());
            if (!text) return text.error();
            auto doc = detail::parse_json_text(*text, (folder / "unit.json").string());
            if (!doc) return doc.error();
            try {
                for (const auto& row : doc->at("fits")) {
                    const std::string name = row.at("name").get<std::string>();
                    if (auto [at, fresh] = owner.emplace(name, t); !fresh)
                        return Error{ErrorCode::invalid_argument,
                                     fmt::format("units {} ({}) and {} ({}) both make the preset {}", at->second,
                                                 describe(at->second), t, describe(t), name)};
                    std::error_code ec;
                    fs::copy_file(folder / (name + ".json"), library / (name + ".json"), ec);
                    if (ec)
                        return Error{ErrorCode::io_error,
                                     fmt::format("{}: cannot copy into the library: {}",
                                                 (folder / (name + ".json")).string(), ec.message())};
                    csv += fmt::format("{},{},{},{},{:.3f},{:.6g},{:.6g},{:.6g},{:.6g},{},{}\n", csv_field(name),
                                       csv_field(doc->at("station").get<std::string>()), csv_field(describe(t)),
                                       csv_field(row.at("what").get<std::string>()), row.at("start").get<double>(),
                                       row.at("hs_m").get<double>(), row.at("tp_s").get<double>(),
                                       row.at("mean_travel_deg").get<double>(), row.at("r2").get<double>(),
                                       row.at("converged").get<bool>() ? "true" : "false", row.at("waves").get<int>());
                }
            } catch (const nlohmann::json::exception& e) {
                return Error{ErrorCode::schema_error,
                             fmt::format("{}: not a unit's summary: {}", (folder / "unit.json").string(), e.what())};
            }
        }
        return write_text(library / "summary.csv", csv);
    });
}

}  // namespace

int run_fit_farm(const FitFarmArgs& f, const FitArgs& defaults) {
    if (f.out.empty()) return fail(kVerb, "--manifest needs --out DIR, the job's folder");
    if (!defaults.data.empty() || !defaults.preset.empty() || !defaults.report.empty())
        return fail(kVerb, "--manifest names the records: leave out --data, --preset and --report");
    if ((f.task >= 0) + f.status + f.merge > 1) return fail(kVerb, "give one of --task, --status and --merge");
    auto units = read_manifest(f.manifest, defaults);
    if (!units) return fail(kVerb, units.error().message);
    const farm::JobFolder job(f.out);
    auto describe = [&](std::size_t t) { return (*units)[t].data_as_written; };
    if (f.status) {
        std::fputs(farm::status_report(job, units->size(), describe).c_str(), stdout);
        return 0;
    }
    if (f.merge) {
        if (auto st = merge(job, *units); !st) return fail(kVerb, st.error().message);
        std::printf("merged %zu units into %s\n", units->size(), (job.out() / "library").string().c_str());
        return 0;
    }
    if (f.task >= static_cast<int>(units->size()))
        return fail(kVerb, fmt::format("--task {}: the manifest has units 0 to {}", f.task, units->size() - 1));
    const std::size_t first = f.task >= 0 ? static_cast<std::size_t>(f.task) : 0;
    const std::size_t last = f.task >= 0 ? first + 1 : units->size();
    int failed = 0;
    for (std::size_t t = first; t < last; ++t) {
        bool skipped = false;
        const Status st = job.run_unit(
            t, [&](const fs::path& folder) { return fit_unit((*units)[t], t, folder); }, skipped);
        if (!st) {
            fail(kVerb, fmt::format("unit {}: {}", t, st.error().message));
            ++failed;
        } else {
            std::printf("unit %zu (%s): %s\n", t, describe(t).c_str(), skipped ? "done already" : "done");
        }
    }
    if (failed > 0) return 1;
    if (f.task >= 0) return 0;
    if (auto st = merge(job, *units); !st) return fail(kVerb, st.error().message);
    std::printf("merged %zu units into %s\n", units->size(), (job.out() / "library").string().c_str());
    return 0;
}

}  // namespace tidewater::cli

#endif
