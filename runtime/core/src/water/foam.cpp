#include <algorithm>
#include <cmath>

#include "host_device.h"
#include "tidewater/detail/surface_foam.hpp"
#include "tidewater/query.hpp"

namespace tidewater {

double crest_foam(double jacobian, double whitecap_jacobian) {
    const double half_width =
        0.5 * static_cast<double>(gpu::kFoamRampFraction) * std::max(1.0 - whitecap_jacobian, 0.0);
    if (!(half_width > 0.0)) return jacobian < whitecap_jacobian ? 1.0 : 0.0;
    const double t = std::clamp((whitecap_jacobian + half_width - jacobian) / (2.0 * half_width), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double detail::foam_memory_weight(std::size_t lag) {
    return std::exp(-static_cast<double>(lag) * static_cast<double>(gpu::kFoamLagStep) /
                    static_cast<double>(gpu::kFoamDecayTime));
}

double detail::remembered_foam(const std::array<double, kFoamLags>& lagged_jacobians, double whitecap_jacobian) {
    // Every full query reads these: formed once, not four exponentials a point.
    static const std::array<double, kFoamLags> weights = [] {
        std::array<double, kFoamLags> w{};
        for (std::size_t l = 0; l < kFoamLags; ++l) w[l] = foam_memory_weight(l + 1);
        return w;
    }();
    double foam = 0.0;
    for (std::size_t l = 0; l < kFoamLags; ++l) foam += crest_foam(lagged_jacobians[l], whitecap_jacobian) * weights[l];
    return foam;
}

double detail::surface_foam(double breaking, double jacobian, const std::array<double, kFoamLags>& lagged_jacobians,
                            double whitecap_jacobian) {
    const double crest = crest_foam(jacobian, whitecap_jacobian) + remembered_foam(lagged_jacobians, whitecap_jacobian);
    return std::max(breaking, std::min(crest, 1.0));
}

}  // namespace tidewater
