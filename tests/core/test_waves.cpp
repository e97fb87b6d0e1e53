// Wave-set validation and the fold-free rule.
#include <cmath>
#include <limits>

#include "test_helpers.hpp"
#include "tidewater/gerstner.hpp"

namespace tidewater {
namespace {

Result<WaveSet> make(std::vector<WaveSpec> specs, FoldPolicy policy = FoldPolicy::reject,
                     std::vector<std::string>* warnings = nullptr) {
    return WaveSet::create(specs, policy, "scene.json: /ocean/waves", warnings);
}

TEST(WaveSet, DerivesDeepWaterQuantities) {
    auto set = make({{90.0, 20.0, 0.5, 0.4, 1.0}});
    ASSERT_TRUE(set.ok());
    const Wave& w = set->waves()[0];
    EXPECT_NEAR(w.dir_x, 0.0, 1e-15);
    EXPECT_NEAR(w.dir_z, 1.0, 1e-15);
    EXPECT_NEAR(w.k, kTwoPi / 20.0, 1e-15);
    EXPECT_NEAR(w.omega * w.omega, kGravity * w.k, 1e-12);
    EXPECT_NEAR(w.period(), std::sqrt(kTwoPi * 20.0 / kGravity), 1e-12);
    EXPECT_NEAR(w.phase_speed(), std::sqrt(kGravity * 20.0 / kTwoPi), 1e-12);
}

struct BadWave {
    WaveSpec spec;
    const char* field;
};

TEST(WaveSet, RejectsOutOfRangeValuesNamingTheField) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const BadWave cases[] = {
        {{0, 0.0, 0.1, 0.5, 0}, "wavelength"}, {{0, -3.0, 0.1, 0.5, 0}, "wavelength"},
        {{0, nan, 0.1, 0.5, 0}, "wavelength"}, {{0, 10, -0.1, 0.5, 0}, "amplitude"},
        {{0, 10, inf, 0.5, 0}, "amplitude"},   {{0, 10, 0.1, 1.01, 0}, "steepness"},
        {{0, 10, 0.1, -0.1, 0}, "steepness"},  {{nan, 10, 0.1, 0.5, 0}, "direction"},
        {{0, 10, 0.1, 0.5, inf}, "phase"},
    };
    for (const BadWave& c : cases) {
        auto set = make({{0, 50, 0.1, 0.5, 0}, c.spec});
        ASSERT_FALSE(set.ok()) << c.field;
        EXPECT_EQ(set.error().code, ErrorCode::schema_error);
        const std::string& m = set.error().message;
        EXPECT_NE(m.find(std::string("scene.json: /ocean/waves/1/") + c.field), std::string::npos) << m;
        EXPECT_NE(m.find("allowed"), std::string::npos) << m;
    }
}

TEST(WaveSet, RejectsMoreThanTheMaximumWaveCount) {
    std::vector<WaveSpec> many(kMaxWaves + 1, WaveSpec{0, 100, 0.01, 0.1, 0});
    auto set = make(many);
    ASSERT_FALSE(set.ok());
    EXPECT_NE(set.error().message.find("at most 64"), std::string::npos);
    many.pop_back();
    EXPECT_TRUE(make(many).ok());
}

TEST(WaveSet, FoldRuleRejectsOrClampsWithWarning) {
    // k*A = 0.6 each, Q = 1: sum = 1.2 > 1.
    const double lambda = 10.0, a = 0.6 * lambda / kTwoPi;
    std::vector<WaveSpec> specs{{0, lambda, a, 1.0, 0}, {45, lambda, a, 1.0, 0}};
    auto rejected = make(specs);
    ASSERT_FALSE(rejected.ok());
    EXPECT_EQ(rejected.error().code, ErrorCode::fold_violation);
    EXPECT_NE(rejected.error().message.find("1.2000"), std::string::npos) << rejected.error().message;
    EXPECT_NE(rejected.error().message.find("clamp"), std::string::npos);

    std::vector<std::string> warnings;
    auto clamped = make(specs, FoldPolicy::clamp, &warnings);
    ASSERT_TRUE(clamped.ok());
    EXPECT_NEAR(clamped->fold_measure(), 1.0, 1e-12);
    EXPECT_NEAR(clamped->waves()[0].steepness, 1.0 / 1.2, 1e-12);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("scaled"), std::string::npos);

    // Exactly at the limit is allowed.
    specs[1].amplitude = 0.4 * lambda / kTwoPi;
    EXPECT_TRUE(make(specs).ok());
}

TEST(WaveSet, SummaryMeasures) {
    auto set = make({{0, 10, 0.3, 0.5, 0}, {90, 20, 0.4, 0.25, 0}});
    ASSERT_TRUE(set.ok());
    EXPECT_NEAR(set->max_elevation(), 0.7, 1e-15);
    EXPECT_NEAR(set->max_horizontal_displacement(), 0.15 + 0.1, 1e-15);
    EXPECT_NEAR(set->significant_wave_height(), 4.0 * std::sqrt(0.5 * (0.09 + 0.16)), 1e-12);
    // The mean square slope is what the surface shows: |d eta / d x0|^2 averaged over a
    // 40 m square (whole wavelengths of both waves) is the sum of (kA)^2 / 2, within 1%.
    double sum = 0.0;
    int n = 0;
    for (double z = 0.05; z < 40.0; z += 0.1)
        for (double x = 0.05; x < 40.0; x += 0.1) {
            const glm::dvec2 slope = evaluate_lagrangian(*set, {x, z}, 3.0).slope;
            sum += slope.x * slope.x + slope.y * slope.y;
            ++n;
        }
    const double k1 = kTwoPi / 10.0, k2 = kTwoPi / 20.0;
    EXPECT_NEAR(set->mean_square_slope(), 0.5 * (k1 * k1 * 0.09 + k2 * k2 * 0.16), 1e-12);
    EXPECT_NEAR(sum / n, set->mean_square_slope(), 0.01 * set->mean_square_slope());
}

}  // namespace
}  // namespace tidewater
