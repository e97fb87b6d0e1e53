// Shared helpers for the core tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include "tidewater/tidewater.hpp"

namespace tidewater::test {

/// A fresh folder under the system's temporary directory named after the running test,
/// removed afterwards.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& prefix = "tidewater_test_") {
        path =
            std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

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

/// The full surface at `pts` and `time`, solved on `threads` threads.
inline std::vector<SurfacePoint> surface_on_threads(const WaterBody& body, double time,
                                                    const std::vector<glm::dvec2>& pts, unsigned threads) {
    std::vector<SurfacePoint> out(pts.size());
    QueryOptions o;
    o.threads = threads;
    EXPECT_TRUE(query_surface(body, time, pts, out, o).ok());
    return out;
}

/// The same bits for every point: height, normal, velocity and foam.
inline void expect_bitwise_equal(const std::vector<SurfacePoint>& a, const std::vector<SurfacePoint>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(std::memcmp(&a[i].height, &b[i].height, sizeof(double)), 0) << i;
        ASSERT_EQ(std::memcmp(&a[i].normal, &b[i].normal, sizeof(glm::dvec3)), 0) << i;
        ASSERT_EQ(std::memcmp(&a[i].velocity, &b[i].velocity, sizeof(glm::dvec3)), 0) << i;
        ASSERT_EQ(std::memcmp(&a[i].foam, &b[i].foam, sizeof(double)), 0) << i;
    }
}

}  // namespace tidewater::test
