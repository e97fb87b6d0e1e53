#include "tidewater/whitecaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "tidewater/constants.hpp"
#include "tidewater/detail/surface_foam.hpp"
#include "tidewater/query.hpp"
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
    struct Particle {
        double jacobian;
        std::array<double, detail::kFoamLags> lagged;  // its Jacobian earlier (the foam it remembers)
        double area;  // a particle stands for the rest area it came from; drawn, it covers J times that
    };
    std::vector<Particle> particles;
    particles.reserve(static_cast<std::size_t>(kParticles) * kInstants);
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
            particles.push_back({j, detail::lagged_jacobians(water.lagged(0.0, 0.0)), std::max(j, 0.0)});
        }
    }
    double total = 0.0;
    for (const Particle& p : particles) total += p.area;
    if (!(total > 0.0)) return 1.0;
    // Fresh foam alone (foam >= 1/2 exactly where J < J*) covers `fraction` from the
    // fraction's quantile of J: remembered foam only adds, so the answer lies below it.
    std::vector<std::pair<double, double>> by_jacobian;
    by_jacobian.reserve(particles.size());
    for (const Particle& p : particles) by_jacobian.emplace_back(p.jacobian, p.area);
    std::sort(by_jacobian.begin(), by_jacobian.end());
    double hi = by_jacobian.back().first, below = 0.0;
    for (const auto& [j, area] : by_jacobian) {
        below += area;
        if (below >= fraction * total) {
            hi = j;
            break;
        }
    }
    double lo = std::min(by_jacobian.front().first, hi);
    // Foam grows with J*: only particles with some foam at J* = hi can reach 1/2 below it.
    std::vector<const Particle*> candidates;
    for (const Particle& p : particles) {
        bool any = crest_foam(p.jacobian, hi) > 0.0;
        for (double lagged : p.lagged) any = any || crest_foam(lagged, hi) > 0.0;
        if (any) candidates.push_back(&p);
    }
    const auto coverage = [&](double jstar) {
        double area = 0.0;
        for (const Particle* p : candidates)
            if (detail::surface_foam(0.0, p->jacobian, p->lagged, jstar) >= 0.5) area += p->area;
        return area / total;
    };
    for (int it = 0; it < 48 && hi - lo > 1e-9; ++it) {
        const double mid = 0.5 * (lo + hi);
        (coverage(mid) >= fraction ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace tidewater
