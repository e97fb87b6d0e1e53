// Spectra and the spectrum-to-waves sampler against closed forms.
#include <cmath>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

SpectrumSpec pm(double wind) {
    SpectrumSpec s;
    s.kind = SpectrumKind::pierson_moskowitz;
    s.wind_speed = wind;
    return s;
}

// PM closed form: m0 = alpha g^2 / (5 wp^4); numeric Hs within 0.5%.
TEST(Spectrum, PiersonMoskowitzSignificantHeightMatchesClosedForm) {
    for (double wind : {5.0, 10.0, 20.0}) {
        const SpectrumSpec s = pm(wind);
        const double wp = peak_omega(s);
        const double hs = 4.0 * std::sqrt(8.1e-3 * kGravity * kGravity / (5.0 * std::pow(wp, 4)));
        EXPECT_NEAR(spectrum_significant_wave_height(s) / hs, 1.0, 5e-3) << wind;
        // The density peaks at wp.
        EXPECT_GT(spectral_density(s, wp), spectral_density(s, 0.97 * wp));
        EXPECT_GT(spectral_density(s, wp), spectral_density(s, 1.03 * wp));
    }
}

// JONSWAP: m0 is close to the PM-shaped m0 (same alpha, wp) times 1 / (1 - 0.287 ln gamma)
// (Goda's approximation, itself good to a few percent): within 5%.
TEST(Spectrum, JonswapEnergyFollowsPeakEnhancement) {
    for (double gamma : {1.0, 3.3, 7.0}) {
        SpectrumSpec s;
        s.wind_speed = 15.0;
        s.fetch = 3e5;
        s.peak_enhancement = gamma;
        const double alpha = 0.076 * std::pow(s.wind_speed * s.wind_speed / (s.fetch * kGravity), 0.22);
        const double wp = peak_omega(s);
        const double m0_pm = alpha * kGravity * kGravity / (5.0 * std::pow(wp, 4));
        const double expected = 4.0 * std::sqrt(m0_pm / (1.0 - 0.287 * std::log(gamma)));
        EXPECT_NEAR(spectrum_significant_wave_height(s) / expected, 1.0, 0.05) << gamma;
    }
}

// The generated set reproduces the spectrum's Hs within 5% (by construction within 1%).
TEST(Spectrum, GeneratedSetReproducesSignificantWaveHeight) {
    for (SpectrumKind kind : {SpectrumKind::pierson_moskowitz, SpectrumKind::jonswap}) {
        for (int n : {8, 32, 64}) {
            for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
                SpectrumSpec s;
                s.kind = kind;
                s.wind_speed = 11.0;
                s.wave_count = n;
                s.seed = seed;
                auto waves = generate_waves(s, "test");
                ASSERT_TRUE(waves.ok());
                ASSERT_EQ(waves->size(), static_cast<std::size_t>(n));
                auto set = WaveSet::create(*waves, FoldPolicy::reject, "test");
                ASSERT_TRUE(set.ok()) << set.error().message;
                EXPECT_NEAR(set->significant_wave_height() / spectrum_significant_wave_height(s), 1.0, 0.05);
                EXPECT_LE(set->fold_measure(), s.steepness + 1e-12);
            }
        }
    }
}

// Energy-weighted mean frequency of the set equals m1/m0 of the spectrum within 3%.
TEST(Spectrum, GeneratedFrequenciesFollowTheSpectrum) {
    SpectrumSpec s;
    s.wave_count = 64;
    auto waves = generate_waves(s, "test");
    ASSERT_TRUE(waves.ok());
    double e = 0, e_w = 0;
    for (const WaveSpec& w : *waves) {
        e += w.amplitude * w.amplitude;
        e_w += w.amplitude * w.amplitude * deep_water_omega(w.wavelength);
    }
    double m0 = 0, m1 = 0;
    const double wp = peak_omega(s);
    for (int i = 0; i < 200000; ++i) {
        const double w = wp * (0.2 + 29.8 * (i + 0.5) / 200000.0), dw = wp * 29.8 / 200000.0;
        m0 += spectral_density(s, w) * dw;
        m1 += w * spectral_density(s, w) * dw;
    }
    EXPECT_NEAR((e_w / e) / (m1 / m0), 1.0, 0.03);
}

TEST(Spectrum, DeterministicFromSeed) {
    SpectrumSpec s;
    s.seed = 1234;
    auto a = generate_waves(s, "test"), b = generate_waves(s, "test");
    s.seed = 1235;
    auto c = generate_waves(s, "test");
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    bool differs = false;
    for (std::size_t i = 0; i < a->size(); ++i) {
        EXPECT_EQ((*a)[i].phase, (*b)[i].phase);
        EXPECT_EQ((*a)[i].wavelength, (*b)[i].wavelength);
        EXPECT_EQ((*a)[i].direction_deg, (*b)[i].direction_deg);
        differs = differs || (*a)[i].phase != (*c)[i].phase;
    }
    EXPECT_TRUE(differs);
}

// Directions spread about the mean: circular mean within 10 degrees for s = 10 and
// every direction within +-40 degrees for s = 100 (cos^200(a/2) is ~0 beyond that).
TEST(Spectrum, DirectionalSpreading) {
    SpectrumSpec s;
    s.wave_count = 64;
    s.mean_direction_deg = 70.0;
    s.spreading = 10.0;
    auto waves = generate_waves(s, "test");
    ASSERT_TRUE(waves.ok());
    double cx = 0, cz = 0;
    for (const auto& w : *waves) {
        cx += std::cos(w.direction_deg * kPi / 180.0);
        cz += std::sin(w.direction_deg * kPi / 180.0);
    }
    EXPECT_NEAR(std::atan2(cz, cx) * 180.0 / kPi, 70.0, 10.0);
    s.spreading = 100.0;
    waves = generate_waves(s, "test");
    for (const auto& w : *waves) EXPECT_NEAR(w.direction_deg, 70.0, 40.0);
}

TEST(Spectrum, ValidationNamesTheField) {
    SpectrumSpec s;
    s.wind_speed = 0.0;
    auto r = generate_waves(s, "p.json: /spectrum");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("p.json: /spectrum/wind_speed"), std::string::npos) << r.error().message;
    s = SpectrumSpec{};
    s.wave_count = 65;
    r = generate_waves(s, "p.json: /spectrum");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("wave_count"), std::string::npos);
    s = SpectrumSpec{};
    s.steepness = std::nan("");
    EXPECT_FALSE(generate_waves(s, "x").ok());
}

}  // namespace
}  // namespace tidewater
