#include "tidewater/whitecaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "tidewater/constants.hpp"
#include "water/open_sea_water.hpp"

namespace tidewater {

double monahan_whitecap_fraction(double wind_speed) {
    if (!(wind_speed > 0.0)) return 0.0;
    return std::min(3.84e-6 * std::pow(wind_speed, 3.41), 1.0);
}

namespace {

/// A uniform double in [0, 1) from a 64-bit counter (SplitMix64): the same on every platform.
double uniform01(std::uint64_t counter) {
    std::uint64_t z = counter * 0x9E3779B97F4A7C15ull + 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

constexpr int kParticles = 8192;
constexpr int kInstants = 8;

}  // namespace

double whitecap_jacobian(const WaveSet& set, double fraction) {
    if (set.empty()) return 1.0;
    fraction = std::clamp(fraction, 0.0, 1.0);
    // The particles spread over four of the longest waves, the instants over its period;
    // they are random so that no wave is sampled at one phase.
    double longest = 0.0, period = 0.0;
    for (const Wave& w : set.waves()) {
        if (w.k > 0.0 && kTwoPi / w.k > longest) {
            longest = kTwoPi / w.k;
            period = kTwoPi / w.omega;
        }
    }
    const double side = 4.0 * longest;
    std::vector<std::pair<double, double>> samples;  // (J, its area weight J)
    samples.reserve(static_cast<std::size_t>(kParticles) * kInstants);
    std::array<double, kMaxWaves> base{};
    std::uint64_t counter = 0;
    for (int t = 0; t < kInstants; ++t) {
        const double time = period * (t + uniform01(counter++)) / kInstants;
        const auto waves = detail::prepare_waves<double>(set, time, 0.0);
        for (int p = 0; p < kParticles; ++p) {
            const double x = side * uniform01(counter++), z = side * uniform01(counter++);
            detail::base_phases(waves, x, z, base.data(), 1);
            const detail::OpenSeaWater<double> water(waves, base.data());
            const double j = detail::surface_frame(water.evaluate<false>(0.0, 0.0)).det;
            // A particle stands for the rest area it came from; drawn, it covers J times that.
            samples.emplace_back(j, std::max(j, 0.0));
        }
    }
    std::sort(samples.begin(), samples.end());
    double total = 0.0;
    for (const auto& s : samples) total += s.second;
    if (!(total > 0.0)) return 1.0;
    double below = 0.0;
    for (const auto& s : samples) {
        below += s.second;
        if (below >= fraction * total) return s.first;
    }
    return samples.back().first;
}

}  // namespace tidewater
