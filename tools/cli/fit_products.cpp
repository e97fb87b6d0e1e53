#include "fit_products.hpp"

#if defined(TIDEWATER_HAVE_CALIBRATION)

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tidewater/calibration/output.hpp"
#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/plot.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::cli {

using namespace tidewater::calibration;

namespace {

Error fit_error(std::string message) {
    return Error{ErrorCode::invalid_argument, std::move(message)};
}

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

/// Times at or past this (1973) are taken for seconds since 1970.
constexpr double kUtcTimesFrom = 1.0e8;

/// Cuts `record` to a <= axis < b (--window A:B, from the first sample).
Status cut_window(const std::string& window, MeasuredRecord& record) {
    double lo = 0.0, hi = 0.0;
    char extra = 0;
    if (std::sscanf(window.c_str(), "%lf:%lf%c", &lo, &hi, &extra) != 2 || !std::isfinite(lo) || !std::isfinite(hi) ||
        !(hi > lo))
        return fit_error(fmt::format("--window \"{}\": expected A:B with A < B", window));
    MeasuredRecord cut = record;
    cut.axis.clear(), cut.z.clear(), cut.east.clear(), cut.north.clear();
    for (std::size_t k = 0; k < record.size(); ++k) {
        if (record.axis[k] < lo || record.axis[k] >= hi) continue;
        cut.axis.push_back(record.axis[k]), cut.z.push_back(record.z[k]);
        if (record.kind == RecordKind::buoy) cut.east.push_back(record.east[k]), cut.north.push_back(record.north[k]);
    }
    if (cut.axis.empty())
        return fit_error(
            fmt::format("--window {}: no samples in it (the record spans 0 to {})", window, record.axis.back()));
    cut.axis_origin += cut.axis.front();
    const double first = cut.axis.front();
    for (double& v : cut.axis) v -= first;
    if (auto st = validate_record(cut); !st) return st;
    record = std::move(cut);
    return {};
}

}  // namespace

bool is_spectral_file(const FitArgs& a) {
    const std::string ext = std::filesystem::path(a.data).extension().string();
    return a.format == "cdip-spectra" || a.format == "ndbc" || (a.format.empty() && ext == ".data_spec");
}

Result<std::vector<SpectralRecord>> read_spectral_file(const FitArgs& a) {
    return a.format == "cdip-spectra" ? read_cdip_spectra(a.data) : read_ndbc_spectra(a.data);
}

Result<FitProducts> fit_spectral_record(const FitArgs& a, const SpectralRecord& r, int index) {
    if (a.method != "spectral") return fit_error("a spectral file has no phases to fit: use --method spectral");
    auto fit = fit_jonswap(r.spectrum);
    if (!fit) return fit_error(fmt::format("{}: {}", a.data, fit.error().message));
    auto waves = sample_preset_waves(*fit, a.waves > 0 ? a.waves : 32, a.seed);
    if (!waves) return waves.error();
    const SeaState m = summarize(r.spectrum);
    FitProducts out;
    out.report = {{"source", a.data},
                  {"kind", "spectrum"},
                  {"method", "spectral"},
                  {"record", index},
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
    if (r.spectrum.directional) out.report["measured"]["peak_direction_from_deg"] = fit->peak_from_deg;
    if (r.reported_hs >= 0.0)
        out.report["reported_by_source"] = {
            {"hs_m", r.reported_hs}, {"tp_s", r.reported_tp}, {"dp_from_deg", r.reported_dp}};
    const SeaState model = sea_state_of(*waves);
    out.report["model"] = {{"hs_m", model.hs}, {"tp_s", fit->tp}, {"mean_travel_deg", model.mean_travel_deg}};
    if (!a.plot.empty()) {
        ChartSeries measured{"measured", {}, {}, "#1f77b4"}, fitted{"fitted JONSWAP", {}, {}, "#d62728"};
        for (std::size_t k = 0; k < r.spectrum.frequency.size(); ++k) {
            measured.x.push_back(r.spectrum.frequency[k]), measured.y.push_back(r.spectrum.density[k]);
            fitted.x.push_back(r.spectrum.frequency[k]),
                fitted.y.push_back(jonswap_density(r.spectrum.frequency[k], fit->hs, fit->tp, fit->gamma));
        }
        out.plot = line_chart_svg(
            {measured, fitted},
            fmt::format("{} #{}: Hs {:.2f} m, Tp {:.1f} s, gamma {:.1f}",
                        std::filesystem::path(a.data).filename().string(), index, fit->hs, fit->tp, fit->gamma),
            "frequency, Hz", "variance density, m^2/Hz");
    }
    const std::string name = a.name.empty() ? std::filesystem::path(a.data).stem().string() : a.name;
    out.preset =
        preset_json(name, fmt::format("Sampled from a JONSWAP fitted to {} (spectrum {})", a.data, index), *waves);
    out.start = r.time_utc_s;
    out.start_is_utc = true;
    out.summary = {fit->hs, fit->tp, model.mean_travel_deg, fit->r2, true, static_cast<int>(waves->size())};
    return out;
}

Result<FitProducts> fit_series(const FitArgs& a, const std::function<void(const std::string&)>& say) {
    auto parsed_kind = parse_kind(a.kind);
    if (!parsed_kind) return parsed_kind.error();
    const RecordKind kind = *parsed_kind;
    if (a.method != "phase" && a.method != "spectral")
        return fit_error(fmt::format("--method {}: use phase or spectral", a.method));
    if (a.method == "spectral" && !a.series.empty())
        return fit_error("--series writes a phase fit's samples: it needs --method phase");
    if (!(a.depth >= 0.0) || !std::isfinite(a.depth))
        return fit_error("--depth must be a finite number of metres (0 = deep water)");
    auto record = read_data(a, kind);
    if (!record) return record.error();
    if (a.depth > 0.0) record->depth = a.depth;
    if (!a.window.empty())
        if (auto st = cut_window(a.window, *record); !st) return st.error();
    say(fmt::format("fit: {} samples from {} ({} missing, {} flagged skipped)", record->size(), record->source,
                    record->skipped_missing, record->skipped_flagged));

    FitProducts out;
    nlohmann::json& report = out.report;
    report = {{"source", record->source},
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
    double hs_over_record = -1.0;
    if (a.method == "spectral") {
        auto spectrum = welch_spectrum(*record);
        if (!spectrum) return spectrum.error();
        auto fit = fit_jonswap(*spectrum);
        if (!fit) return fit.error();
        const int count = a.waves > 0 ? a.waves : 32;
        auto sampled = sample_preset_waves(*fit, count, a.seed);
        if (!sampled) return sampled.error();
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
            out.plot = line_chart_svg(
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
        out.summary.r2 = fit->r2;
    } else {
        PhaseFitOptions o;
        o.waves = a.waves;
        o.max_waves = a.max_waves;
        o.threads = a.threads;
        o.progress = say;
        auto fit = fit_phase_resolved(*record, o);
        if (!fit) return fit.error();
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
            out.plot = line_chart_svg(
                {measured, model},
                fmt::format("{}: {} waves, R^2 {:.3f}", std::filesystem::path(record->source).filename().string(),
                            fit->waves.size(), fit->r2),
                kind == RecordKind::profile ? "x, m" : "t, s", kind == RecordKind::buoy ? "heave, m" : "elevation, m");
        }
        if (!a.series.empty()) {
            out.series = kind == RecordKind::profile ? "x_m,measured_m,model_m\n" : "t_s,measured_m,model_m\n";
            for (std::size_t k = 0; k < record->size(); ++k)
                out.series += fmt::format("{:.6f},{:.6f},{:.6f}\n", record->axis[k], record->z[k], fit->model_z[k]);
        }
        out.summary.r2 = fit->r2;
        out.summary.converged = fit->converged;
    }
    SeaState model = sea_state_of(waves);
    // A spectral preset's waves carry equal energy: its Tp is the spectrum's it samples.
    if (report.contains("spectral_fit")) model.tp = report["spectral_fit"]["tp_s"].get<double>();
    report["model"] = {{"hs_m", model.hs}, {"tp_s", model.tp}, {"mean_travel_deg", model.mean_travel_deg}};
    if (hs_over_record >= 0.0) report["model"]["hs_over_record_m"] = hs_over_record;
    const std::string name = a.name.empty() ? std::filesystem::path(a.data).stem().string() : a.name;
    out.preset = preset_json(
        name, fmt::format("Fitted to {} ({} data, {} fit) by tidewater fit", record->source, to_string(kind), a.method),
        waves);
    out.start = record->axis_origin;
    out.start_is_utc = kind != RecordKind::profile && record->axis_origin >= kUtcTimesFrom;
    out.summary.hs_m = model.hs;
    out.summary.tp_s = model.tp;
    out.summary.mean_travel_deg = model.mean_travel_deg;
    out.summary.waves = static_cast<int>(waves.size());
    return out;
}

}  // namespace tidewater::cli

#endif
