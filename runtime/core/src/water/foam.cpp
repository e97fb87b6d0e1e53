#include <algorithm>

#include "host_device.h"
#include "kernel/kernel_waves.hpp"
#include "tidewater/query.hpp"

namespace tidewater {

double crest_foam(double jacobian, double whitecap_jacobian) {
    const double half_width = 0.5 * static_cast<double>(gpu::kFoamRampFraction) * std::max(1.0 - whitecap_jacobian, 0.0);
    if (!(half_width > 0.0)) return jacobian < whitecap_jacobian ? 1.0 : 0.0;
    const double t = std::clamp((whitecap_jacobian + half_width - jacobian) / (2.0 * half_width), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double detail::surface_foam(double breaking, double jacobian, double whitecap_jacobian) {
    return std::max(breaking, crest_foam(jacobian, whitecap_jacobian));
}

}  // namespace tidewater
