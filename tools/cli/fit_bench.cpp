#include "fit_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/readers.hpp"

namespace tidewater::cli {

using namespace tidewater::calibration;

Result<nlohmann::json> run_fit_bench(const std::filesystem::path& refdata, unsigned threads,
                                     const std::function<void(const std::string&)>& progress) {
    const unsigned all = threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
    // A 30-minute CDIP buoy record (x north, y west) and tank probe 1 around its highest crest.
    CsvColumns columns;
    columns.role_to_column = {{"t", "t_s"}, {"north", "x_m"}, {"east", "y_m"}, {"z", "z_m"}, {"flag", "flag_primary"}};
    columns.scale = {{"east", -1.0}};
    auto buoy =
        read_csv_record(refdata / "cdip_067_san_nicolas_xyz" / "067_20220102_xyz_30min.csv", RecordKind::buoy, columns);
    if (!buoy) return buoy.error();
    auto probe = read_two_column(refdata / "eagre_wavetank_202002" / "WAVE_1.dat", RecordKind::gauge);
    if (!probe) return probe.error();
    const double crest =
        probe->axis[static_cast<std::size_t>(std::max_element(probe->z.begin(), probe->z.end()) - probe->z.begin())];
    MeasuredRecord tank;
    tank.kind = RecordKind::gauge;
    tank.source = probe->source + " (30 s around the highest crest)";
    tank.depth = 1.0;
    for (std::size_t k = 0; k < probe->size(); ++k)
        if (std::abs(probe->axis[k] - crest) < 15.0)
            tank.axis.push_back(probe->axis[k] - (crest - 15.0)), tank.z.push_back(probe->z[k]);

    nlohmann::json report = {{"benchmark", "phase_fit"}, {"threads_all", all}, {"runs", nlohmann::json::array()}};
    for (const MeasuredRecord* r : {&*buoy, &tank}) {
        for (int waves : {8, 32, 64}) {
            for (unsigned t : {1u, all}) {
                if (t == all && all == 1) continue;
                if (progress) progress(fmt::format("{}: {} waves, {} thread(s)", r->source, waves, t));
                PhaseFitOptions o;
                o.waves = waves;
                o.threads = t;
                auto fit = fit_phase_resolved(*r, o);
                if (!fit) return fit.error();
                report["runs"].push_back({{"record", r->source},
                                          {"kind", to_string(r->kind)},
                                          {"samples", r->size()},
                                          {"waves", waves},
                                          {"threads", t},
                                          {"seconds", fit->seconds},
                                          {"r2", fit->r2},
                                          {"iterations", fit->iterations}});
            }
        }
    }
    return report;
}

std::string fit_bench_markdown(const nlohmann::json& r) {
    std::string s = fmt::format(
        "All threads = {}.\n\n| record | samples | waves | threads | seconds | iterations | R^2 "
        "|\n|---|---:|---:|---:|---:|---:|---:|\n",
        r["threads_all"].get<unsigned>());
    for (const auto& run : r["runs"])
        s += fmt::format("| {} | {} | {} | {} | {:.2f} | {} | {:.4f} |\n", run["record"].get<std::string>(),
                         run["samples"].get<std::size_t>(), run["waves"].get<int>(), run["threads"].get<unsigned>(),
                         run["seconds"].get<double>(), run["iterations"].get<int>(), run["r2"].get<double>());
    return s;
}

}  // namespace tidewater::cli
