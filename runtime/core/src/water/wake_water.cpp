#include "tidewater/detail/wake_water.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "host_device.h"
#include "tidewater/constants.hpp"

namespace tidewater::detail {

static_assert(gpu::kGravityAcceleration == static_cast<float>(kGravity), "the shaders' gravity is the model's");

double wake_age_fade(double age, double max_age) {
    const double start = 0.8 * max_age;
    if (age <= start) return 1.0;
    if (age >= max_age) return 0.0;
    const double x = (max_age - age) / (max_age - start);
    return x * x * (3.0 - 2.0 * x);
}

double wake_reach(double age, double speed, double size) {
    const double margin = double(gpu::kWakeReachSizes) * size + double(gpu::kWakeReachMargin);
    if (speed > 0.0) return double(gpu::kWakeReachSpeedShare) * speed * age + margin;
    const double k_min = double(gpu::kWakeSplashLongest) * std::sqrt(3.0) * kPi / size;
    return 0.5 * std::sqrt(kGravity / k_min) * age + margin;
}

glm::dvec3 wake_reach_disc(glm::dvec2 a, double age_a, double size_a, glm::dvec2 b, double age_b, double size_b) {
    const double length = glm::length(b - a), duration = age_a - age_b;
    const double speed = duration > 0.0 ? length / duration : 0.0;
    const double radius = wake_reach(std::max(age_a, age_b), speed, std::max(size_a, size_b)) + 0.5 * length;
    return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), radius * radius};
}

namespace {

/// The highest a unit impulse of source size b lifts the water anywhere, m per m^4/s:
/// k^(3/2) F(k) peaks at k = sqrt(3) pi / b, and r >= b / (2 pi).
double unit_peak(double b) {
    const double k = std::sqrt(3.0) * kPi / b;
    return k * std::sqrt(k) * std::exp(-0.75) * (2.0 * kPi / b) / (std::sqrt(2.0) * kPi * std::sqrt(kGravity));
}

}  // namespace

template <typename Scalar>
PreparedWakes<Scalar> prepare_wakes(const Wakes& wakes, double time, int exclude) {
    PreparedWakes<Scalar> w;
    bool placed = false;
    auto push = [&](const DisturbancePoint& p, double strength, double turbulence, bool linked) {
        if (!placed) {
            w.origin = p.position;
            placed = true;
        }
        w.x.push_back(static_cast<Scalar>(p.position.x - w.origin.x));
        w.z.push_back(static_cast<Scalar>(p.position.y - w.origin.y));
        w.age.push_back(static_cast<Scalar>(time - p.emitted));
        w.strength.push_back(static_cast<Scalar>(strength));
        w.size.push_back(static_cast<Scalar>(p.source_size));
        w.steepness.push_back(static_cast<Scalar>(p.steepness));
        w.turbulence.push_back(static_cast<Scalar>(turbulence));
        w.linked.push_back(linked ? 1 : 0);
    };
    // The disc where the segment from point `i` to the next (or lone point `i`) is felt.
    auto push_disc = [&](glm::dvec3 disc) {
        w.reach_x.push_back(static_cast<Scalar>(disc.x - w.origin.x));
        w.reach_z.push_back(static_cast<Scalar>(disc.y - w.origin.y));
        w.reach2.push_back(static_cast<Scalar>(disc.z));
    };
    for (const WakeChain& chain : wakes.chains) {
        if (chain.emitter == exclude && exclude >= 0) continue;
        std::vector<const DisturbancePoint*> alive;
        for (const DisturbancePoint& p : chain.points)
            if (p.emitted <= time && time - p.emitted < chain.max_age) alive.push_back(&p);
        if (alive.size() < 2) continue;  // a chain's waves are its segments
        double head = 0.0, speed = 0.0;
        for (std::size_t i = 0; i + 1 < alive.size(); ++i)
            speed = std::max(speed, glm::length(alive[i + 1]->position - alive[i]->position) /
                                        (alive[i + 1]->emitted - alive[i]->emitted));
        glm::dvec4 box(1e300, 1e300, -1e300, -1e300);
        for (std::size_t i = 0; i < alive.size(); ++i) {
            const DisturbancePoint& p = *alive[i];
            const double fade = wake_age_fade(time - p.emitted, chain.max_age);
            push(p, p.strength * fade, p.turbulence * fade, i + 1 < alive.size());
            if (i + 1 < alive.size()) {
                const DisturbancePoint& q = *alive[i + 1];
                push_disc(wake_reach_disc(p.position, time - p.emitted, p.source_size, q.position, time - q.emitted,
                                          q.source_size));
            } else {
                push_disc({p.position, 0.0});  // a chain's last point opens no segment
            }
            head =
                std::max(head, std::abs(p.strength) * kPi / (kGravity * p.source_size * p.source_size) * p.steepness);
            const double reach = wake_reach(time - p.emitted, speed, p.source_size);
            const glm::dvec2 at = p.position - w.origin;
            box = glm::dvec4(std::min(box.x, at.x - reach), std::min(box.y, at.y - reach),
                             std::max(box.z, at.x + reach), std::max(box.w, at.y + reach));
        }
        w.boxes.push_back(box);
        // A chain's waves stay within a few pressure heads of its source.
        w.displacement_bound += 4.0 * head;
    }
    glm::dvec4 splash_box(1e300, 1e300, -1e300, -1e300);
    for (std::size_t i = 0; i < wakes.splashes.size(); ++i) {
        const int emitter = wakes.splash_emitters.empty() ? 0 : wakes.splash_emitters[i];
        const DisturbancePoint& p = wakes.splashes[i];
        if ((emitter == exclude && exclude >= 0) || p.emitted > time || time - p.emitted >= wakes.splash_max_age)
            continue;
        const double fade = wake_age_fade(time - p.emitted, wakes.splash_max_age);
        push(p, p.strength * fade, p.turbulence * fade, false);
        const double age = time - p.emitted;
        push_disc(wake_reach_disc(p.position, age, p.source_size, p.position, age, p.source_size));
        w.displacement_bound += std::abs(p.strength) * unit_peak(p.source_size) * p.steepness;
        const double reach = wake_reach(time - p.emitted, 0.0, p.source_size);
        const glm::dvec2 at = p.position - w.origin;
        splash_box = glm::dvec4(std::min(splash_box.x, at.x - reach), std::min(splash_box.y, at.y - reach),
                                std::max(splash_box.z, at.x + reach), std::max(splash_box.w, at.y + reach));
    }
    if (splash_box.x <= splash_box.z) w.boxes.push_back(splash_box);
    w.blocks = wake_block_discs(w.reach_x, w.reach_z, w.reach2, w.linked);
    return w;
}

template <typename Scalar>
std::vector<glm::dvec3> wake_block_discs(const std::vector<Scalar>& x, const std::vector<Scalar>& z,
                                         const std::vector<Scalar>& r2, const std::vector<unsigned char>& linked) {
    std::vector<glm::dvec3> blocks;
    const std::size_t n = x.size();
    for (std::size_t begin = 0; begin < n; begin += gpu::kWakeBlockPoints) {
        const std::size_t end = std::min(n, begin + gpu::kWakeBlockPoints);
        std::vector<std::size_t> terms;  // the reach discs of the terms points begin..end add
        for (std::size_t i = begin; i < end; ++i) {
            const bool after = i > 0 && linked[i - 1], before = linked[i] != 0;
            if (after || !before) terms.push_back(after ? i - 1 : i);
        }
        glm::dvec2 lo(1e300), hi(-1e300);
        for (std::size_t t : terms) {
            lo = glm::min(lo, glm::dvec2(x[t], z[t]));
            hi = glm::max(hi, glm::dvec2(x[t], z[t]));
        }
        const glm::dvec2 centre = terms.empty() ? glm::dvec2(0.0) : 0.5 * (lo + hi);
        double radius = -1.0;  // no terms: felt nowhere
        for (std::size_t t : terms)
            radius = std::max(radius, glm::length(glm::dvec2(x[t], z[t]) - centre) + std::sqrt(double(r2[t])) + 1.0);
        blocks.push_back({centre.x, centre.y, radius < 0.0 ? -1.0 : radius * radius});
    }
    return blocks;
}

template std::vector<glm::dvec3> wake_block_discs<float>(const std::vector<float>&, const std::vector<float>&,
                                                         const std::vector<float>&, const std::vector<unsigned char>&);
template std::vector<glm::dvec3> wake_block_discs<double>(const std::vector<double>&, const std::vector<double>&,
                                                          const std::vector<double>&,
                                                          const std::vector<unsigned char>&);
template PreparedWakes<float> prepare_wakes<float>(const Wakes&, double, int);
template PreparedWakes<double> prepare_wakes<double>(const Wakes&, double, int);

}  // namespace tidewater::detail
