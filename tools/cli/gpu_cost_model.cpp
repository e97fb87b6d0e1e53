#include "gpu_cost_model.hpp"

#include <algorithm>
#include <cmath>

namespace tidewater::cli {

const std::vector<ReferenceGpu>& reference_gpus() {
    // Public board figures: compute units x 2 SIMDs, boost clock, memory bandwidth.
    static const std::vector<ReferenceGpu> gpus = {
        {"navi21", "Radeon RX 6800 XT (RDNA2, 72 CUs)", 144, 2.25, 512.0},
        {"gfx1100", "Radeon RX 7900 XTX (RDNA3, 96 CUs)", 192, 2.5, 960.0},
    };
    return gpus;
}

double stage_ms(const ReferenceGpu& gpu, const StageCost& cost, std::uint64_t invocations) {
    if (invocations == 0) return 0.0;
    const double waves = std::ceil(static_cast<double>(invocations) / kWaveLanes);
    const double per_wave = std::max(cost.inverse_throughput, cost.latency / std::max(cost.waves_per_simd, 1.0));
    return waves * per_wave / static_cast<double>(gpu.simds) / (gpu.clock_ghz * 1e6);
}

double copy_ms(const ReferenceGpu& gpu, std::uint64_t bytes) {
    return 2.0 * static_cast<double>(bytes) / (gpu.bandwidth_gb_s * 1e6);
}

}  // namespace tidewater::cli
