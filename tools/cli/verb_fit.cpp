// tidewater fit: a preset (and a report) from measured surface data. Both files are
// written only when the fit succeeds, and each appears whole or not at all.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "data_options.hpp"
#include "verbs.hpp"

#if defined(TIDEWATER_HAVE_CALIBRATION)
#include "tidewater/calibration/output.hpp"
#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/plot.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/calibration/spectrum.hpp"
#include "tidewater/constants.hpp"
#endif

namespace tidewater::cli {

namespace {

struct FitArgs : DataOptions {
    std::string method = "phase", preset, report, series, plot, name, window;
    double depth = 0.0;
    int waves = 0, max_waves = 32, record_index = 0;
    unsigned threads = 1;
    std::uint64_t seed = 1;
    bool quiet = false;
};

#if defined(TIDEWATER_HAVE_CALIBRATION)
using namespace tidewater::calibration;

nlohmann::json wave_json(const FittedWave& w, RecordKind kind) {
    nlohmann::json j = {
        {"amplitude_m", w.amplitude},       {"period_s", w.period()},
        {"wavenumber_rad_m", w.k},          {"deep_water_wavelength_m", kTwoPi * kGravity / (w.omega * w.omega)},
        {"direction_deg", w.direction_deg}, {"phase_rad", w.phase},
        {"steepness", w.steepness}};
    auto sigma = [](double s) { return s >= 0.0 ? nlohmann::json(s) : nlohmann::json(nullptr); };
    j["amplitude_sigma_m"] = sigma(w.amplitude_sigma);
    j["period_sigma_s"] = sigma(w.period_sigma);
    j["phase_sigma_rad"] = sigma(w.phase_sigma);
    j["steepness_sigma"] = sigma(w.steepness_sigma);
    j["direction_sigma_deg"] = kind == RecordKind::buoy ? sigma(w.direction_sigma_deg)
                                                        : nlohmann::json("fixed: +x (a gauge or profile cannot tell)");
    return j;
}

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

/// A spectrum from a spectral file (CDIP netCDF or NDBC text): JONSWAP fit and a sampled preset.
int run_spectral_file(const FitArgs& a, const std::string& format) {
    constexpr const char* verb = "fit";
    if (a.method != "spectral") return fail(verb, "a spectral file has no phases to fit: use --method spectral");
    auto records = format == "ndbc" ? read_ndbc_spectra(a.data) : read_cdip_spectra(a.data);
    if (!records) return fail(verb, records.error().message);
    if (a.record_index < 0 || a.record_index >= static_cast<int>(records->size()))
        return fail(verb,
                    fmt::format("--record {}: the file has spectra 0 to {}", a.record_index, records->size() - 1));
    const SpectralRecord& r = (*records)[static_cast<std::size_t>(a.record_index)];
    auto fit = fit_jonswap(r.spectrum);
    if (!fit) return fail(verb, fmt::format("{}: {}", a.data, fit.error().message));
    auto waves = sample_preset_waves(*fit, a.waves > 0 ? a.waves : 32, a.seed);
    if (!waves) return fail(verb, waves.error().message);
    const SeaState m = summarize(r.spectrum);
    nlohmann::json report = {{"source", a.data},
                             {"kind", "spectrum"},
                             {"method", "spectral"},
                             {"record", a.record_index},
                             {"record_time_utc_s", r.time_utc_s},
                             {"bins", r.spectrum.frequency.size()},
                             {"measured", {{"hs_m", m.hs}, {"tp_s", m.tp}}},
                             {"spectral_fit",
                              {{"hs_m", fit->hs},
                               {"tp_s", fit->tp},
                               {"gamma", fit->gamma},
                               {"spreading_s", fit->spreading_s},
                               {"mean_travel_deg", fit->mean_travel_deg},
                               {"shape_r2", fit->r2},
                               {"iterations", fit->iterations}}}};
    if (r.spectrum.directional) report["measured"]["peak_direction_from_deg"] = fit->peak_from_deg;
    if (r.reported_hs >= 0.0)
        report["reported_by_source"] = {
            {"hs_m", r.reported_hs}, {"tp_s", r.reported_tp}, {"dp_from_deg", r.reported_dp}};
    const SeaState model = sea_state_of(*waves);
    report["model"] = {{"hs_m", model.hs}, {"tp_s", fit->tp}, {"mean_travel_deg", model.mean_travel_deg}};
    std::string plot;
    if (!a.plot.empty()) {
        ChartSeries measured{"measured", {}, {}, "#1f77b4"}, fitted{"fitted JONSWAP", {}, {}, "#d62728"};
        for (std::size_t k = 0; k < r.spectrum.frequency.size(); ++k) {
            measured.x.push_back(r.spectrum.frequency[k]), measured.y.push_back(r.spectrum.density[k]);
            fitted.x.push_back(r.spectrum.frequency[k]),
                fitted.y.push_back(jonswap_density(r.spectrum.frequency[k], fit->hs, fit->tp, fit->gamma));
        }
        plot = line_chart_svg({measured, fitted},
                              fmt::format("{} #{}: Hs {:.2f} m, Tp {:.1f} s, gamma {:.1f}",
                                          std::filesystem::path(a.data).filename().string(), a.record_index, fit->hs,
                                          fit->tp, fit->gamma),
                              "frequency, Hz", "variance density, m^2/Hz");
    }
    const std::string name = a.name.empty() ? std::filesystem::path(a.data).stem().string() : a.name;
    const nlohmann::json preset = preset_json(
        name, fmt::format("Sampled from a JONSWAP fitted to {} (spectrum {})", a.data, a.record_index), *waves);
    if (auto st = write_all({{a.preset, preset.dump(2) + "\n"}, {a.report, report.dump(2) + "\n"}, {a.plot, plot}});
        !st)
        return fail(verb, st.error().message);
    std::printf("fitted a JONSWAP to %s #%d: Hs %.3f m, Tp %.2f s, gamma %.2f; preset of %zu waves\n", a.data.c_str(),
                a.record_index, fit->hs, fit->tp, fit->gamma, waves->size());
    return 0;
}

int run_fit(const FitArgs& a) {
    constexpr const char* verb = "fit";
    if (a.data.empty()) return fail(verb, "give --data FILE");
    if (a.preset.empty() && a.report.empty()) return fail(verb, "give --preset and/or --report to write");
    auto parsed_kind = parse_kind(a.kind);
    if (!parsed_kind) return fail(verb, parsed_kind.error().message);
    const RecordKind kind = *parsed_kind;
    if (a.method != "phase" && a.method != "spectral")
        return fail(verb, fmt::format("--method {}: use phase or spectral", a.method));
    if (a.method == "spectral" && !a.series.empty())
        return fail(verb, "--series writes a phase fit's samples: it needs --method phase");
    if (!(a.depth >= 0.0) || !std::isfinite(a.depth))
        return fail(verb, "--depth must be a finite number of metres (0 = deep water)");
    const std::string ext = std::filesystem::path(a.data).extension().string();
    if (a.format == "cdip-spectra" || a.format == "ndbc" || (a.format.empty() && ext == ".data_spec"))
        return run_spectral_file(a, a.format == "cdip-spectra" ? "cdip-spectra" : "ndbc");
    auto record = read_data(a, kind);
    if (!record) return fail(verb, record.error().message);
    if (a.depth > 0.0) record->depth = a.depth;
    if (!a.window.empty()) {
        // --window A:B keeps A <= axis < B, in seconds (metres for a profile) from the first sample.
        double lo = 0.0, hi = 0.0;
        char extra = 0;
        if (std::sscanf(a.window.c_str(), "%lf:%lf%c", &lo, &hi, &extra) != 2 || !std::isfinite(lo) ||
            !std::isfinite(hi) || !(hi > lo))
            return fail(verb, fmt::format("--window \"{}\": expected A:B with A < B", a.window));
        MeasuredRecord cut = *record;
        cut.axis.clear(), cut.z.clear(), cut.east.clear(), cut.north.clear();
        for (std::size_t k = 0; k < record->size(); ++k) {
            if (record->axis[k] < lo || record->axis[k] >= hi) continue;
            cut.axis.push_back(record->axis[k]), cut.z.push_back(record->z[k]);
            if (kind == RecordKind::buoy) cut.east.push_back(record->east[k]), cut.north.push_back(record->north[k]);
        }
        if (cut.axis.empty())
            return fail(verb, fmt::format("--window {}: no samples in it (the record spans 0 to {})", a.window,
                                          record->axis.back()));
        cut.axis_origin += cut.axis.front();
        const double first = cut.axis.front();
        for (double& v : cut.axis) v -= first;
        if (auto st = validate_record(cut); !st) return fail(verb, st.error().message);
        *record = std::move(cut);
    }
    auto say = [&](const std::string& s) {
        if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
    };
    say(fmt::format("fit: {} samples from {} ({} missing, {} flagged skipped)", record->size(), record->source,
                    record->skipped_missing, record->skipped_flagged));

    nlohmann::json report = {
        {"source", record->source},
        {"kind", to_string(kind)},
        {"method", a.method},
        {"samples_used", record->size()},
        {"samples_skipped", {{"missing", record->skipped_missing}, {"flagged", record->skipped_flagged}}},
        {"depth_m", std::isfinite(record->depth) ? nlohmann::json(record->depth) : nlohmann::json("deep")},
        {"axis_origin", record->axis_origin},
        {"axes", "x east, z north (runtime); directions of travel in degrees from +x toward +z"}};
    // What was measured: Hs from the variance, and from the spectrum where there is one.
    double mean = 0.0, var = 0.0;
    for (double v : record->z) mean += v;
    mean /= static_cast<double>(record->size());
    for (double v : record->z) var += (v - mean) * (v - mean);
    var /= static_cast<double>(record->size());
    report["measured"] = {{"hs_m", 4.0 * std::sqrt(var)}};
    std::vector<WaveSpec> waves;
    std::string plot_svg, series_csv;
    double hs_over_record = -1.0;
    if (a.method == "spectral") {
        auto spectrum = welch_spectrum(*record);
        if (!spectrum) return fail(verb, spectrum.error().message);
        auto fit = fit_jonswap(*spectrum);
        if (!fit) return fail(verb, fit.error().message);
        const int count = a.waves > 0 ? a.waves : 32;
        auto sampled = sample_preset_waves(*fit, count, a.seed);
        if (!sampled) return fail(verb, sampled.error().message);
        waves = *sampled;
        const SeaState m = summarize(*spectrum);
        report["measured"] = {{"hs_m", m.hs}, {"tp_s", m.tp}};
        if (spectrum->directional)
            report["measured"]["peak_direction_from_deg"] = fit->peak_from_deg,
            report["measured"]["mean_travel_deg"] = m.mean_travel_deg;
        if (!a.plot.empty()) {
            ChartSeries measured{"measured (Welch)", {}, {}, "#1f77b4"}, model{"fitted JONSWAP", {}, {}, "#d62728"};
            for (std::size_t k = 0; k < spectrum->frequency.size(); ++k) {
                const double f = spectrum->frequency[k];
                if (f < 0.025 || f > 0.58) continue;
                measured.x.push_back(f), measured.y.push_back(spectrum->density[k]);
                model.x.push_back(f), model.y.push_back(jonswap_density(f, fit->hs, fit->tp, fit->gamma));
            }
            plot_svg = line_chart_svg(
                {measured, model},
                fmt::format("{}: Hs {:.2f} m, Tp {:.1f} s, gamma {:.1f}",
                            std::filesystem::path(record->source).filename().string(), fit->hs, fit->tp, fit->gamma),
                "frequency, Hz", "variance density, m^2/Hz");
        }
        report["spectral_fit"] = {{"hs_m", fit->hs},
                                  {"tp_s", fit->tp},
                                  {"gamma", fit->gamma},
                                  {"spreading_s", fit->spreading_s},
                                  {"mean_travel_deg", fit->mean_travel_deg},
                                  {"shape_r2", fit->r2},
                                  {"iterations", fit->iterations}};
    } else {
        PhaseFitOptions o;
        o.waves = a.waves;
        o.max_waves = a.max_waves;
        o.threads = a.threads;
        o.progress = say;
        auto fit = fit_phase_resolved(*record, o);
        if (!fit) return fail(verb, fit.error().message);
        nlohmann::json list = nlohmann::json::array();
        for (const FittedWave& w : fit->waves) {
            list.push_back(wave_json(w, kind));
            waves.push_back(to_wave_spec(w));
        }
        nlohmann::json bic = nlohmann::json::array();
        for (auto [n, b] : fit->bic) bic.push_back({{"waves", n}, {"bic", b}});
        report["fit"] = {{"waves", fit->waves.size()},
                         {"rmse_m", fit->rmse},
                         {"r2", fit->r2},
                         {"iterations", fit->iterations},
                         {"converged", fit->converged},
                         {"seconds", fit->seconds},
                         {"bic_of_linear_fits", bic},
                         {"steepness_scaled_to_fold_limit", fit->steepness_scaled}};
        if (kind == RecordKind::buoy) report["fit"]["horizontal_r2"] = fit->horizontal_r2;
        report["waves"] = list;
        double model_mean = 0.0, model_var = 0.0;
        for (double v : fit->model_z) model_mean += v;
        model_mean /= static_cast<double>(fit->model_z.size());
        for (double v : fit->model_z) model_var += (v - model_mean) * (v - model_mean);
        hs_over_record = 4.0 * std::sqrt(model_var / static_cast<double>(fit->model_z.size()));
        if (!a.plot.empty()) {
            ChartSeries measured{"measured", record->axis, record->z, "#1f77b4"},
                model{"fitted preset", record->axis, fit->model_z, "#d62728"};
            plot_svg = line_chart_svg(
                {measured, model},
                fmt::format("{}: {} waves, R^2 {:.3f}", std::filesystem::path(record->source).filename().string(),
                            fit->waves.size(), fit->r2),
                kind == RecordKind::profile ? "x, m" : "t, s", kind == RecordKind::buoy ? "heave, m" : "elevation, m");
        }
        if (!a.series.empty()) {
            series_csv = kind == RecordKind::profile ? "x_m,measured_m,model_m\n" : "t_s,measured_m,model_m\n";
            for (std::size_t k = 0; k < record->size(); ++k)
                series_csv += fmt::format("{:.6f},{:.6f},{:.6f}\n", record->axis[k], record->z[k], fit->model_z[k]);
        }
    }
    SeaState model = sea_state_of(waves);
    // A spectral preset's waves carry equal energy: its Tp is the spectrum's it samples.
    if (report.contains("spectral_fit")) model.tp = report["spectral_fit"]["tp_s"].get<double>();
    report["model"] = {{"hs_m", model.hs}, {"tp_s", model.tp}, {"mean_travel_deg", model.mean_travel_deg}};
    if (hs_over_record >= 0.0) report["model"]["hs_over_record_m"] = hs_over_record;
    const std::string name = a.name.empty() ? std::filesystem::path(a.data).stem().string() : a.name;
    const nlohmann::json preset = preset_json(
        name, fmt::format("Fitted to {} ({} data, {} fit) by tidewater fit", record->source, to_string(kind), a.method),
        waves);
    if (auto st = write_all({{a.preset, preset.dump(2) + "\n"},
                             {a.report, report.dump(2) + "\n"},
                             {a.plot, plot_svg},
                             {a.series, series_csv}});
        !st)
        return fail(verb, st.error().message);
    std::printf("fitted %zu waves to %s: model Hs %.3f m, Tp %.2f s%s\n", waves.size(), record->source.c_str(),
                model.hs, model.tp,
                report.contains("fit") ? fmt::format(", R^2 {:.4f}", report["fit"]["r2"].get<double>()).c_str() : "");
    return 0;
}
#endif

}  // namespace

Verb add_fit_verb(CLI::App& app) {
    auto a = std::make_shared<FitArgs>();
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
#if defined(TIDEWATER_HAVE_CALIBRATION)
    return {cmd, [a] { return run_fit(*a); }};
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
