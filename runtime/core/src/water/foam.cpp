#include <algorithm>

#include "host_device.h"
#include "kernel/kernel_waves.hpp"
#include "tidewater/query.hpp"

namespace tidewater {

double crest_foam(double jacobian) {
    const double start = static_cast<double>(gpu::kFoamJacobianStart), width = static_cast<double>(gpu::kFoamJacobianWidth);
    const double t = std::clamp((start - jacobian) / width, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double detail::surface_foam(double breaking, double jacobian) { return std::max(breaking, crest_foam(jacobian)); }

}  // namespace tidewater
