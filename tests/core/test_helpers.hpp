// Shared helpers for the core tests.
#pragma once

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "tidewater/tidewater.hpp"

namespace tidewater::test {

inline WaterBody make_body(std::vector<WaveSpec> waves, double level = 0.0, double time_offset = 0.0) {
    WaterProfile p;
    p.waves = std::move(waves);
    p.time_offset = time_offset;
    auto body = WaterBody::create(p, level, "test");
    EXPECT_TRUE(body.ok()) << (body.ok() ? "" : body.error().message);
    return body.ok() ? std::move(body).value() : WaterBody{};
}

/// A random fold-free set of `n` waves whose sum(Q*k*A) equals `fold` exactly.
inline std::vector<WaveSpec> random_waves(int n, double fold, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<WaveSpec> w(static_cast<std::size_t>(n));
    double sum = 0.0;
    for (auto& s : w) {
        s.direction_deg = 360.0 * u();
        s.wavelength = 2.0 + 80.0 * u();
        s.amplitude = s.wavelength / (2.0 * kPi) * (0.02 + 0.1 * u());  // k*A in [0.02, 0.12]
        s.steepness = 0.3 + 0.7 * u();
        s.phase = 2.0 * kPi * u();
        sum += s.steepness * (2.0 * kPi / s.wavelength) * s.amplitude;
    }
    // Scale amplitudes (not Q, which is capped at 1) so that sum(QkA) hits the target.
    for (auto& s : w) s.amplitude *= fold / sum;
    return w;
}

}  // namespace tidewater::test
