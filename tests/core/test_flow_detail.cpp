// Flow-mapped detail (seeds 001 and 004) on its CPU twin: the weights, frame-to-frame
// continuity and a contrast that does not pulse. GPU parity is in tests/render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "tidewater/tidewater.hpp"

namespace tidewater {
namespace {

FlowDetailSpec river_spec() {
    auto preset = load_preset("river_flowing");
    EXPECT_TRUE(preset.ok());
    return preset->flow;
}

TEST(FlowDetail, TheRiverPresetCarriesDetail) {
    const FlowDetailSpec s = river_spec();
    EXPECT_GT(s.strength, 0.0);
    EXPECT_TRUE(validate(s, "test").ok());
}

TEST(FlowDetail, WeightsSumToOneAndVanishAtEachRestart) {
    const FlowDetailSpec s = river_spec();
    double min_weight = 1.0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec2 p{0.37 * i, -0.11 * i};
        const double t = 0.013 * i;
        const FlowDetailSample d = flow_detail(s, p, {1.5, 0.3}, t);
        ASSERT_NEAR(d.weight_a + d.weight_b, 1.0, 1e-12) << "at " << i;
        min_weight = std::min({min_weight, d.weight_a, d.weight_b});
    }
    EXPECT_LT(min_weight, 0.01);  // each layer restarts unseen
}

// The largest |d(gradient)/dx| of the noise, lattice units: bounds how fast a layer's
// slope changes as it is advected.
double noise_hessian_bound(std::uint32_t seed) {
    double h = 0.0;
    const double e = 1e-4;
    for (int j = 0; j < 200; ++j)
        for (int i = 0; i < 200; ++i) {
            const glm::dvec2 p{0.0503 * i, 0.0497 * j};
            const glm::dvec2 g = gradient_noise(p, seed).gradient;
            h = std::max(h, glm::length(gradient_noise(p + glm::dvec2(e, 0.0), seed).gradient - g) / e);
            h = std::max(h, glm::length(gradient_noise(p + glm::dvec2(0.0, e), seed).gradient - g) / e);
        }
    return h;
}

TEST(FlowDetail, AFrameChangesTheDetailOnlyAsFarAsTheCurrentCarriesIt) {
    // At 60 Hz the detail at a point changes by advection (the layers move |v| speed dt)
    // and by the cross-fade (weights change by 2 dt / T). A restart with a visible weight
    // would pop by a whole layer's slope and break the bound.
    const FlowDetailSpec s = river_spec();
    const double dt = 1.0 / 60.0;
    const double hessian = 1.25 * std::max(noise_hessian_bound(s.seed),
                                           noise_hessian_bound(s.seed + 1));  // margin for the sampled maximum
    for (const glm::dvec2 flow : {glm::dvec2(0.0, 0.0), glm::dvec2(0.8, 0.1), glm::dvec2(-2.5, 1.4)}) {
        const double advection =
            std::sqrt(2.0) * hessian * s.tiling * s.tiling * s.strength * glm::length(flow) * s.speed * dt;
        double worst_ratio = 0.0;
        for (int k = 0; k < 64; ++k) {
            const glm::dvec2 p{3.1 * k, 1.7 * k - 40.0};
            FlowDetailSample before = flow_detail(s, p, flow, 100.0);
            for (int f = 1; f <= 3 * 120; ++f) {  // three periods of 2 s
                const FlowDetailSample after = flow_detail(s, p, flow, 100.0 + f * dt);
                // Layer slopes on either side of the frame (a restarting layer changes pattern).
                const double a = std::max(glm::length(before.slope_a), glm::length(after.slope_a));
                const double b = std::max(glm::length(before.slope_b), glm::length(after.slope_b));
                // |dD/dw| <= sqrt(2) (a + b) + 2 sqrt(2) max(a, b) with N = sqrt(wA^2 + wB^2) >= sqrt(0.5).
                const double crossfade = (2.0 * dt / s.period) * (2.0 * (a + b) + 3.0 * std::max(a, b));
                const double change = glm::length(after.slope - before.slope);
                worst_ratio = std::max(worst_ratio, change / (advection + crossfade + 1e-12));
                before = after;
            }
        }
        EXPECT_LE(worst_ratio, 1.0) << "flow " << flow.x << ", " << flow.y;
        EXPECT_GT(worst_ratio, 0.05) << "the bound is so loose that it tests nothing";
    }
}

/// RMS detail slope over a 270 m square (about 120^2 noise cells, so the estimate itself
/// varies by well under 1%) at each of 40 instants of one period:
/// (max - min) / mean.
double rms_variation_over_a_cycle(const FlowDetailSpec& s, glm::dvec2 flow) {
    const int steps = 40;
    std::vector<double> rms;
    for (int k = 0; k < steps; ++k) {
        const double t = 50.0 + s.period * k / steps;
        double sum = 0.0;
        int n = 0;
        for (int j = 0; j < 128; ++j)
            for (int i = 0; i < 128; ++i) {
                const glm::dvec2 v = flow_detail(s, {2.11 * i, 2.13 * j}, flow, t).slope;
                sum += glm::dot(v, v);
                ++n;
            }
        rms.push_back(std::sqrt(sum / n));
    }
    const auto [lo, hi] = std::minmax_element(rms.begin(), rms.end());
    double mean = 0.0;
    for (double r : rms) mean += r / steps;
    return (*hi - *lo) / mean;
}

TEST(FlowDetail, ContrastDoesNotPulseOverACycle) {
    const FlowDetailSpec s = river_spec();
    EXPECT_LT(rms_variation_over_a_cycle(s, {1.2, 0.2}), 0.03);
}

TEST(FlowDetail, ContrastIsTheSameAtEveryPointOfAFade) {
    // Each texel's samples are binned by where it is in its fade (layer A's weight); the
    // RMS slope of each bin over many texels and instants. The normalised blend is flat;
    // a plain linear blend of the same layers dips to sqrt(0.5) mid-fade.
    const FlowDetailSpec s = river_spec();
    constexpr int kBins = 10;
    double normalised[kBins] = {}, linear[kBins] = {};
    int count[kBins] = {};
    for (int k = 0; k < 24; ++k)
        for (int j = 0; j < 120; ++j)
            for (int i = 0; i < 120; ++i) {
                const FlowDetailSample d = flow_detail(s, {2.11 * i, 2.13 * j}, {0.9, -0.4}, 20.0 + 0.37 * k);
                const int bin = std::min(kBins - 1, static_cast<int>(d.weight_a * kBins));
                const glm::dvec2 plain = d.weight_a * d.slope_a + d.weight_b * d.slope_b;
                normalised[bin] += glm::dot(d.slope, d.slope);
                linear[bin] += glm::dot(plain, plain);
                ++count[bin];
            }
    double lo = 1e9, hi = 0.0;
    for (int b = 0; b < kBins; ++b) {
        ASSERT_GT(count[b], 1000) << "bin " << b;
        const double r = std::sqrt(normalised[b] / count[b]);
        lo = std::min(lo, r);
        hi = std::max(hi, r);
    }
    EXPECT_LT((hi - lo) / lo, 0.03);
    // The plain blend of uncorrelated layers has variance (w^2 + (1 - w)^2) sigma^2: averaged
    // over the middle bins (w in [0.4, 0.6)) 0.5067, over the end bins 0.9067, so the
    // middle's RMS is sqrt(0.5067 / 0.9067) = 0.748 of the ends' (0.707 at w = 0.5 exactly).
    const double ends = std::sqrt((linear[0] / count[0] + linear[kBins - 1] / count[kBins - 1]) / 2.0);
    const double middle =
        std::sqrt((linear[kBins / 2 - 1] / count[kBins / 2 - 1] + linear[kBins / 2] / count[kBins / 2]) / 2.0);
    EXPECT_NEAR(middle / ends, 0.748, 0.03);
}

TEST(FlowDetail, RefusesOutOfRangeSettings) {
    FlowDetailSpec s;
    s.period = 0.0;
    const Status st = validate(s, "preset.json /flow");
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("/flow/period"), std::string::npos) << st.error().message;
    s = FlowDetailSpec{};
    s.jump = {0.9, 0.1};
    EXPECT_FALSE(validate(s, "x").ok());
    s = FlowDetailSpec{};
    s.tiling = std::nan("");
    EXPECT_FALSE(validate(s, "x").ok());
}

}  // namespace
}  // namespace tidewater
