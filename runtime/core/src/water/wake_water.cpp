#include "tidewater/detail/wake_water.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "host_device.h"
#include "tidewater/constants.hpp"

namespace tidewater::detail {

static_assert(gpu::kWakeGravity == static_cast<float>(kGravity), "the shaders' gravity is the model's");

double wake_age_fade(double age, double max_age) {
    const double start = 0.8 * max_age;
    if (age <= start) return 1.0;
    if (age >= max_age) return 0.0;
    const double x = (max_age - age) / (max_age - start);
    return x * x * (3.0 - 2.0 * x);
}

double wake_reach(double age, double speed, double size) {
    const double margin = 2.0 * size + 60.0;
    if (speed > 0.0) return 0.9 * speed * age + margin;
    const double k_min = 0.05 * std::sqrt(3.0) * kPi / size;
    return 0.5 * std::sqrt(kGravity / k_min) * age + margin;
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
    for (const WakeChain& chain : wakes.chains) {
        if (chain.emitter == exclude && exclude >= 0) continue;
        std::vector<const DisturbancePoint*> alive;
        for (const DisturbancePoint& p : chain.points)
            if (p.emitted <= time && time - p.emitted < chain.max_age) alive.push_back(&p);
        if (alive.size() < 2) continue;  // a chain's waves are its segments
        double head = 0.0, speed = 0.0;
        for (std::size_t i = 0; i + 1 < alive.size(); ++i)
            speed = std::max(speed, glm::length(alive[i + 1]->position - alive[i]->position) / (alive[i + 1]->emitted - alive[i]->emitted));
        glm::dvec4 box(1e300, 1e300, -1e300, -1e300);
        for (std::size_t i = 0; i < alive.size(); ++i) {
            const DisturbancePoint& p = *alive[i];
            const double fade = wake_age_fade(time - p.emitted, chain.max_age);
            push(p, p.strength * fade, p.turbulence * fade, i + 1 < alive.size());
            head = std::max(head, std::abs(p.strength) * kPi / (kGravity * p.source_size * p.source_size) * p.steepness);
            const double reach = wake_reach(time - p.emitted, speed, p.source_size);
            const glm::dvec2 at = p.position - w.origin;
            box = glm::dvec4(std::min(box.x, at.x - reach), std::min(box.y, at.y - reach), std::max(box.z, at.x + reach),
                             std::max(box.w, at.y + reach));
        }
        w.boxes.push_back(box);
        // A chain's waves stay within a few pressure heads of its source.
        w.displacement_bound += 4.0 * head;
    }
    glm::dvec4 splash_box(1e300, 1e300, -1e300, -1e300);
    for (std::size_t i = 0; i < wakes.splashes.size(); ++i) {
        const int emitter = wakes.splash_emitters.empty() ? 0 : wakes.splash_emitters[i];
        const DisturbancePoint& p = wakes.splashes[i];
        if ((emitter == exclude && exclude >= 0) || p.emitted > time || time - p.emitted >= wakes.splash_max_age) continue;
        const double fade = wake_age_fade(time - p.emitted, wakes.splash_max_age);
        push(p, p.strength * fade, p.turbulence * fade, false);
        w.displacement_bound += std::abs(p.strength) * unit_peak(p.source_size) * p.steepness;
        const double reach = wake_reach(time - p.emitted, 0.0, p.source_size);
        const glm::dvec2 at = p.position - w.origin;
        splash_box = glm::dvec4(std::min(splash_box.x, at.x - reach), std::min(splash_box.y, at.y - reach),
                                std::max(splash_box.z, at.x + reach), std::max(splash_box.w, at.y + reach));
    }
    if (splash_box.x <= splash_box.z) w.boxes.push_back(splash_box);
    return w;
}

template PreparedWakes<float> prepare_wakes<float>(const Wakes&, double, int);
template PreparedWakes<double> prepare_wakes<double>(const Wakes&, double, int);

}  // namespace tidewater::detail
