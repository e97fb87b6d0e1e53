#include "wake_uploads.hpp"

#include <algorithm>

#include "tidewater/detail/wake_water.hpp"

namespace tidewater::render::detail {

Result<WakeUpload> pack_wakes(const Scene& scene, const Wakes* host, double time, glm::dvec2 origin) {
    WakeUpload out;
    if (scene.boats.empty() && (host == nullptr || host->point_count() == 0)) return out;
    Wakes wakes;
    if (host != nullptr) {
        if (auto st = host->validate("renderer: FrameInfo::wakes"); !st) return st.error();
        wakes = *host;
    }
    for (std::size_t b = 0; b < scene.boats.size(); ++b) scripted_boat_wake(scene.boats[b], static_cast<int>(b), time, wakes);
    if (auto st = wakes.validate("renderer: wakes"); !st) return st.error();
    // Chains that churn foam first: the fragment shader walks only those for it.
    auto churns = [](const WakeChain& c) {
        return std::any_of(c.points.begin(), c.points.end(), [](const DisturbancePoint& p) { return p.turbulence > 0.0; });
    };
    std::stable_partition(wakes.chains.begin(), wakes.chains.end(), churns);
    Wakes turbulent_only;
    for (const WakeChain& c : wakes.chains)
        if (churns(c)) turbulent_only.chains.push_back(c);
    const auto prepared = tidewater::detail::prepare_wakes<double>(wakes, time);
    out.turbulent = static_cast<std::uint32_t>(tidewater::detail::prepare_wakes<double>(turbulent_only, time).x.size());
    const glm::dvec2 shift = prepared.origin - origin;
    out.points.resize(prepared.x.size());
    for (std::size_t i = 0; i < prepared.x.size(); ++i) {
        gpu::GpuWakePoint& p = out.points[i];
        p.position_age = glm::vec4(static_cast<float>(prepared.x[i] + shift.x), static_cast<float>(prepared.z[i] + shift.y),
                                   static_cast<float>(prepared.age[i]), static_cast<float>(prepared.strength[i]));
        p.shape = glm::vec4(static_cast<float>(prepared.size[i]), static_cast<float>(prepared.steepness[i]),
                            static_cast<float>(prepared.turbulence[i]), prepared.linked[i] ? 1.0f : 0.0f);
    }
    return out;
}

}  // namespace tidewater::render::detail
