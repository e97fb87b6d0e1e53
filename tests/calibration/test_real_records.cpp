// Fits to real measured records in ../shared/refdata (skipped when it is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "refdata.hpp"
#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/calibration/spectrum.hpp"

namespace tidewater::calibration {
namespace {

using test::refdata_dir;

double angle_difference(double a, double b) {
    return std::abs(std::remainder(a - b, 360.0));
}

/// "00h00", "00h30", ... for half-hour k of the day.
std::string fmt_stamp(int half) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02dh%02d", half / 2, (half % 2) * 30);
    return buf;
}

// Every half-hour CDIP summarises in each file: our spectral fit of the same x/y/z
// samples against CDIP's own Hs (5%), Tp (10%) and Dp (20 degrees).
TEST(RealRecords, CdipBuoySpectralFitMatchesCdipSummaries) {
    TIDEWATER_REQUIRE_REFDATA("cdip_067_san_nicolas_xyz");
    int compared = 0;
    for (const char* name : {"067.20201225_1200.20201225_1600.nc", "067.20220102_0000.20220102_0600.nc"}) {
        const auto path = refdata_dir() / "cdip_067_san_nicolas_xyz" / name;
        auto summaries = read_cdip_wave_summaries(path);
        ASSERT_TRUE(summaries.ok()) << summaries.error().message;
        for (const CdipWaveSummary& s : *summaries) {
            auto record = read_cdip_xyz(path, s.start_utc_s, s.end_utc_s);
            if (!record.ok() || record->size() < 2000) {
                std::printf("%s %.0f: %s\n", name, s.start_utc_s,
                            record.ok() ? "too few good samples, skipped" : record.error().message.c_str());
                continue;
            }
            auto spectrum = welch_spectrum(*record);
            ASSERT_TRUE(spectrum.ok()) << spectrum.error().message;
            auto fit = fit_jonswap(*spectrum);
            ASSERT_TRUE(fit.ok()) << fit.error().message;
            const SeaState measured = summarize(*spectrum);
            std::printf(
                "%s %.0f: Hs %.3f (CDIP %.3f)  Tp %.2f (CDIP %.2f; spectrum peak %.2f)  Dp %.0f (CDIP %.0f)  gamma "
                "%.1f, shape R^2 %.3f\n",
                name, s.start_utc_s, fit->hs, s.hs, fit->tp, s.tp, measured.tp, fit->peak_from_deg, s.dp, fit->gamma,
                fit->r2);
            EXPECT_NEAR(fit->hs, s.hs, 0.05 * s.hs);
            EXPECT_NEAR(fit->tp, s.tp, 0.10 * s.tp);
            EXPECT_LT(angle_difference(fit->peak_from_deg, s.dp), 20.0);
            ++compared;
        }
    }
    EXPECT_GE(compared, 10);
}

}  // namespace
}  // namespace tidewater::calibration

namespace tidewater::calibration {
namespace {
using test::refdata_dir;

// The 48 Datawell half-hours: the spectral fit's Hs against the buoy's own Hm0 (.his).
// The .his rows are stamped HH:18 and HH:48 while the raw files start at HH:00 and
// HH:30: each row is the half-hour that ends at its stamp (matching that way halves
// the scatter against matching file by file), so the test cuts the same 30 minutes
// from the concatenated raw files.
TEST(RealRecords, DatawellHalfHoursMatchTheBuoysHm0) {
    TIDEWATER_REQUIRE_REFDATA("datawell_waverider_hebtools");
    const auto dir = refdata_dir() / "datawell_waverider_hebtools";
    MeasuredRecord day;
    day.kind = RecordKind::buoy;
    day.source = "Datawell 2005-07-01";
    for (int half = 0; half < 48; ++half) {
        auto record = read_datawell_raw(dir / ("buoy_2005-07-01T" + fmt_stamp(half) + "Z.raw"));
        ASSERT_TRUE(record.ok()) << record.error().message;
        for (std::size_t k = 0; k < record->size(); ++k) {
            day.axis.push_back(1800.0 * half + record->axis[k]);
            day.z.push_back(record->z[k]);
            day.east.push_back(record->east[k]);
            day.north.push_back(record->north[k]);
        }
    }
    // .his rows: date_time,tp,dirp,sprp,tz,hm0(cm),...
    std::ifstream his(dir / "buoy_2005-07.his");
    ASSERT_TRUE(his.good());
    std::vector<double> errors;
    for (std::string line; std::getline(his, line);) {
        std::vector<std::string> v;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) v.push_back(cell);
        ASSERT_GT(v.size(), 5u) << line;
        const double end = 3600.0 * std::stod(v[0].substr(11, 2)) + 60.0 * std::stod(v[0].substr(14, 2)) +
                           std::stod(v[0].substr(17, 6));
        const double hm0 = 0.01 * std::stod(v[5]);
        MeasuredRecord window;
        window.kind = RecordKind::buoy;
        window.source = v[0];
        for (std::size_t k = 0; k < day.size(); ++k)
            if (day.axis[k] >= end - 1800.0 && day.axis[k] < end) {
                window.axis.push_back(day.axis[k] - std::max(0.0, end - 1800.0));
                window.z.push_back(day.z[k]);
                window.east.push_back(day.east[k]);
                window.north.push_back(day.north[k]);
            }
        ASSERT_GT(window.size(), 1000u) << v[0];
        auto spectrum = welch_spectrum(window);
        ASSERT_TRUE(spectrum.ok()) << spectrum.error().message;
        auto fit = fit_jonswap(*spectrum);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        errors.push_back(std::abs(fit->hs - hm0) / hm0);
    }
    ASSERT_EQ(errors.size(), 48u);
    std::vector<double> sorted = errors;
    std::sort(sorted.begin(), sorted.end());
    const double median = 0.5 * (sorted[23] + sorted[24]), worst = sorted.back();
    std::printf("Datawell: Hs against the buoy's Hm0 over 48 half-hours: median error %.2f%%, worst %.2f%%\n",
                100 * median, 100 * worst);
    EXPECT_LT(median, 0.03);
    EXPECT_LT(worst, 0.08);
}

// Fenton's steady-wave solution (H/d = 0.3, 20 Fourier terms): a Gerstner profile fit.
TEST(RealRecords, FentonSteadyWaveProfile) {
    TIDEWATER_REQUIRE_REFDATA("fenton_fourier_reference");
    std::ifstream in(refdata_dir() / "fenton_fourier_reference" / "Surface.res");
    ASSERT_TRUE(in.good());
    MeasuredRecord r;
    r.kind = RecordKind::profile;
    r.source = "Fenton Surface.res";
    r.depth = 1.0;  // lengths are in units of the depth d
    for (std::string line; std::getline(in, line);) {
        std::stringstream cells(line);
        double x = 0.0, eta = 0.0;
        if (line.empty() || line[0] == '#' || !(cells >> x >> eta)) continue;
        if (x == 0.0 && eta == 0.0) continue;  // the file's dummy scaling point
        r.axis.push_back(x);
        r.z.push_back(eta - 1.0);  // from the bed to about the still-water level
    }
    ASSERT_EQ(r.size(), 21u);
    r.axis_origin = r.axis.front();
    for (double& a : r.axis) a -= r.axis_origin;
    auto fit = fit_phase_resolved(r);
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    std::printf("Fenton profile: %zu waves, R^2 %.5f, rmse %.4f d; first wave L = %.3f d, Q = %.2f\n",
                fit->waves.size(), fit->r2, fit->rmse, 2 * 3.14159265358979 / fit->waves[0].k, fit->waves[0].steepness);
    EXPECT_GE(fit->r2, 0.99);
}

// Wave-tank probes 1 to 3 (1 m deep): 30 s around each probe's highest crest.
TEST(RealRecords, WaveTankProbesAroundTheHighestCrest) {
    TIDEWATER_REQUIRE_REFDATA("eagre_wavetank_202002");
    for (int probe = 1; probe <= 3; ++probe) {
        auto all = read_two_column(refdata_dir() / "eagre_wavetank_202002" / ("WAVE_" + std::to_string(probe) + ".dat"),
                                   RecordKind::gauge);
        ASSERT_TRUE(all.ok()) << all.error().message;
        const auto crest = static_cast<std::size_t>(std::max_element(all->z.begin(), all->z.end()) - all->z.begin());
        const double centre = all->axis[crest];
        MeasuredRecord r;
        r.kind = RecordKind::gauge;
        r.source = all->source;
        r.depth = 1.0;
        for (std::size_t k = 0; k < all->size(); ++k)
            if (std::abs(all->axis[k] - centre) < 15.0) {
                r.axis.push_back(all->axis[k]);
                r.z.push_back(all->z[k]);
            }
        r.axis_origin = r.axis.front();
        for (double& a : r.axis) a -= r.axis_origin;
        PhaseFitOptions o;
        o.max_waves = 32;
        auto fit = fit_phase_resolved(r, o);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        std::printf("tank probe %d: %zu waves, R^2 %.4f, rmse %.2f mm, %.2f s\n", probe, fit->waves.size(), fit->r2,
                    1e3 * fit->rmse, fit->seconds);
        EXPECT_LE(fit->waves.size(), 32u);
        EXPECT_GE(fit->r2, 0.95);
    }
}

// Spectral files: CDIP's spectral netCDF and NDBC's text spectra, fitted directly.
TEST(RealRecords, SpectralFilesFitTheirProducersSummaries) {
    TIDEWATER_REQUIRE_REFDATA("cdip_028_santa_monica_spectral");
    auto cdip = read_cdip_spectra(refdata_dir() / "cdip_028_santa_monica_spectral" / "028p0_d24_rt.nc");
    ASSERT_TRUE(cdip.ok()) << cdip.error().message;
    ASSERT_EQ(cdip->size(), 7u);
    for (const SpectralRecord& r : *cdip) {
        auto fit = fit_jonswap(r.spectrum);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        std::printf("CDIP 028 %.0f: Hs %.3f (CDIP %.3f)  Tp %.2f (CDIP %.2f)  Dp %.0f (CDIP %.0f)\n", r.time_utc_s,
                    fit->hs, r.reported_hs, fit->tp, r.reported_tp, fit->peak_from_deg, r.reported_dp);
        EXPECT_NEAR(fit->hs, r.reported_hs, 0.05 * r.reported_hs);
        EXPECT_NEAR(fit->tp, r.reported_tp, 0.10 * r.reported_tp);
        EXPECT_LT(angle_difference(fit->peak_from_deg, r.reported_dp), 20.0);
    }
    TIDEWATER_REQUIRE_REFDATA("ndbc_41010_directional");
    auto ndbc = read_ndbc_spectra(refdata_dir() / "ndbc_41010_directional" / "41010.data_spec");
    ASSERT_TRUE(ndbc.ok()) << ndbc.error().message;
    EXPECT_EQ(ndbc->size(), 149u);
    // NDBC's bulk file (WVHT, 0.1 m resolution) is stamped 10 minutes before each spectrum.
    std::ifstream bulk(refdata_dir() / "ndbc_41010_directional" / "41010.spec");
    std::map<long, double> wvht;
    for (std::string line; std::getline(bulk, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream c(line);
        int y, mo, d, h, mi;
        double hs;
        c >> y >> mo >> d >> h >> mi >> hs;
        wvht[((y * 100L + mo) * 100 + d) * 100 + h] = hs;
    }
    std::vector<double> differences;
    for (const SpectralRecord& r : *ndbc) {
        const auto days = static_cast<long>(std::floor(r.time_utc_s / 86400.0));
        const std::chrono::year_month_day ymd{std::chrono::sys_days{std::chrono::days{days}}};
        const long hour = static_cast<long>(std::fmod(r.time_utc_s, 86400.0) / 3600.0);
        const long key = ((static_cast<int>(ymd.year()) * 100L + static_cast<unsigned>(ymd.month())) * 100 +
                          static_cast<unsigned>(ymd.day())) *
                             100 +
                         hour;
        const auto it = wvht.find(key);
        if (it == wvht.end()) continue;
        auto fit = fit_jonswap(r.spectrum, 0.02, 0.5);
        ASSERT_TRUE(fit.ok()) << fit.error().message;
        differences.push_back(std::abs(fit->hs - it->second));
    }
    ASSERT_GT(differences.size(), 100u);
    std::sort(differences.begin(), differences.end());
    const double median = differences[differences.size() / 2], worst = differences.back();
    std::printf("NDBC 41010: %zu spectra against WVHT (0.1 m steps): median |Hs - WVHT| %.3f m, worst %.3f m\n",
                differences.size(), median, worst);
    EXPECT_LE(median, 0.05);  // within WVHT's rounding
    EXPECT_LT(worst, 0.15);
}

}  // namespace
}  // namespace tidewater::calibration
