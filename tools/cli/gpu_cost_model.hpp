// The GPU cost model of `tidewater gpu-cost` (docs/PERFORMANCE.md, "A GPU cost model"):
// a stage's time on a reference GPU from how many times it runs (pipeline statistics
// queries) and what the driver's compiler says one wave of it costs (pipeline executable
// statistics on RADV's null device).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tidewater::cli {

/// A reference GPU: what the model needs of it.
struct ReferenceGpu {
    std::string family;  ///< RADV_FORCE_FAMILY's name: "navi21", "gfx1100"
    std::string name;    ///< the board the figures are for
    int simds = 0;       ///< compute units x SIMDs per unit
    double clock_ghz = 0.0;
    double bandwidth_gb_s = 0.0;  ///< memory bandwidth, 1e9 bytes/s
};

/// The boards the model is for: an RX 6800 XT (navi21) and an RX 7900 XTX (gfx1100).
const std::vector<ReferenceGpu>& reference_gpus();

/// What the compiler says of one wave of a stage.
struct StageCost {
    double inverse_throughput = 0.0;  ///< busy cycles a wave takes on its SIMD
    double latency = 0.0;             ///< issue plus stall cycles of a wave
    double waves_per_simd = 1.0;      ///< occupancy: waves in flight on a SIMD ("Subgroups per SIMD")
};

/// Lanes per wave the model assumes for every stage.
inline constexpr double kWaveLanes = 64.0;

/// Milliseconds `invocations` of a stage of cost `cost` take on `gpu`: the invocations in
/// waves of kWaveLanes, spread over every SIMD, each wave taking its inverse throughput or,
/// where too few waves are in flight to hide it, its latency shared by the waves in flight.
double stage_ms(const ReferenceGpu& gpu, const StageCost& cost, std::uint64_t invocations);

/// Milliseconds a copy of `bytes` (read once, written once) takes at the GPU's bandwidth.
double copy_ms(const ReferenceGpu& gpu, std::uint64_t bytes);

}  // namespace tidewater::cli
