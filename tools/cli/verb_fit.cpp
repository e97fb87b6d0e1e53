// tidewater fit: a preset (and a report) from measured surface data. Both files are
// written only when the fit succeeds, and each appears whole or not at all.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "data_options.hpp"
#include "fit_farm.hpp"
#include "fit_products.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

#if defined(TIDEWATER_HAVE_CALIBRATION)
/// Writes `text` to each path given, all or none.
Status write_all(const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<std::unique_ptr<AtomicFile>> staged;
    for (const auto& [path, text] : files) {
        if (path.empty()) continue;
        staged.push_back(std::make_unique<AtomicFile>(path));
        if (!staged.back()->status()) return staged.back()->status();
        staged.back()->stream() << text;
    }
    for (auto& f : staged)
        if (auto st = f->commit(); !st) return st;
    return {};
}

int run_fit(const FitArgs& a) {
    constexpr const char* verb = "fit";
    if (a.data.empty()) return fail(verb, "give --data FILE");
    if (a.preset.empty() && a.report.empty()) return fail(verb, "give --preset and/or --report to write");
    if (auto kind = parse_kind(a.kind); !kind) return fail(verb, kind.error().message);
    if (a.method != "phase" && a.method != "spectral")
        return fail(verb, fmt::format("--method {}: use phase or spectral", a.method));
    auto say = [&](const std::string& s) {
        if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
    };
    Result<FitProducts> fit = Error{ErrorCode::internal, "no fit"};
    if (is_spectral_file(a)) {
        if (a.method != "spectral") return fail(verb, "a spectral file has no phases to fit: use --method spectral");
        auto records = read_spectral_file(a);
        if (!records) return fail(verb, records.error().message);
        if (a.record_index < 0 || a.record_index >= static_cast<int>(records->size()))
            return fail(verb,
                        fmt::format("--record {}: the file has spectra 0 to {}", a.record_index, records->size() - 1));
        fit = fit_spectral_record(a, (*records)[static_cast<std::size_t>(a.record_index)], a.record_index);
    } else {
        fit = fit_series(a, say);
    }
    if (!fit) return fail(verb, fit.error().message);
    if (auto st = write_all({{a.preset, fit->preset.dump(2) + "\n"},
                             {a.report, fit->report.dump(2) + "\n"},
                             {a.plot, fit->plot},
                             {a.series, fit->series}});
        !st)
        return fail(verb, st.error().message);
    if (fit->report.contains("spectral_fit") && is_spectral_file(a)) {
        std::printf("fitted a JONSWAP to %s #%d: Hs %.3f m, Tp %.2f s, gamma %.2f; preset of %d waves\n",
                    a.data.c_str(), a.record_index, fit->summary.hs_m, fit->summary.tp_s,
                    fit->report["spectral_fit"]["gamma"].get<double>(), fit->summary.waves);
    } else {
        std::printf("fitted %d waves to %s: model Hs %.3f m, Tp %.2f s%s\n", fit->summary.waves,
                    fit->report["source"].get<std::string>().c_str(), fit->report["model"]["hs_m"].get<double>(),
                    fit->report["model"]["tp_s"].get<double>(),
                    fit->report.contains("fit") ? fmt::format(", R^2 {:.4f}", fit->summary.r2).c_str() : "");
    }
    return 0;
}
#endif

}  // namespace

Verb add_fit_verb(CLI::App& app) {
    auto a = std::make_shared<FitArgs>();
    auto farm = std::make_shared<FitFarmArgs>();
    CLI::App* cmd =
        app.add_subcommand("fit", "Fit a wave preset to measured surface data (gauge, buoy or profile) with Ceres");
    add_data_options(cmd, *a);
    cmd->add_option("--record", a->record_index, "Spectral files: which spectrum (0 = the first in the file)")
        ->capture_default_str();
    cmd->add_option("--window", a->window,
                    "A:B: fit only A <= t < B, seconds (metres for a profile) from the first sample");
    cmd->add_option("--depth", a->depth, "Water depth, m, for finite-depth dispersion (0 = deep water)");
    cmd->add_option("--method", a->method, "phase (phase-resolved waves) or spectral (JONSWAP, then a preset from it)")
        ->capture_default_str();
    cmd->add_option("--waves", a->waves, "Number of waves (phase: 0 = chosen by BIC; spectral: default 32)");
    cmd->add_option("--max-waves", a->max_waves, "Upper bound for the BIC choice")->capture_default_str();
    cmd->add_option("--threads", a->threads, "Ceres threads (0 = all)")->capture_default_str();
    cmd->add_option("--seed", a->seed, "Spectral presets: seed of the wave phases")->capture_default_str();
    cmd->add_option("--preset", a->preset, "Write the preset JSON here");
    cmd->add_option("--report", a->report, "Write the report JSON here");
    cmd->add_option("--series", a->series, "Phase fits: write axis, measured and model CSV here");
    cmd->add_option("--plot", a->plot,
                    "Write an SVG chart here: measured vs model series (phase) or spectrum (spectral)");
    cmd->add_option("--name", a->name, "Preset name (default: the data file's stem)");
    cmd->add_flag("--quiet", a->quiet, "No progress lines");
    // A batch of fits as a farmed job (docs/scale-out.md).
    cmd->add_option("--manifest", farm->manifest,
                    "A job's manifest (JSON): its units, one record file each, fitted into --out DIR");
    cmd->add_option("--out", farm->out, "The farmed job's folder: units/N/ per unit, library/ after the merge");
    cmd->add_option("--task", farm->task, "Run unit N of the manifest only (for example $SLURM_ARRAY_TASK_ID)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--status", farm->status, "List the units not done (missing or failed) and the tasks to run again");
    cmd->add_flag("--merge", farm->merge, "Once every unit is done: write the preset library and its summary.csv");
#if defined(TIDEWATER_HAVE_CALIBRATION)
    return {cmd, [a, farm] {
                if (!farm->manifest.empty()) return run_fit_farm(*farm, *a);
                if (!farm->out.empty() || farm->task >= 0 || farm->status || farm->merge)
                    return fail("fit", "--out, --task, --status and --merge belong to a farmed job: give --manifest");
                return run_fit(*a);
            }};
#else
    return {
        cmd, [] {
            return fail(
                "fit",
                "this build has no calibration: install Ceres and netCDF (apt-get install libceres-dev libnetcdf-dev) "
                "and configure again with -DTIDEWATER_BUILD_CALIBRATION=ON");
        }};
#endif
}

}  // namespace tidewater::cli
