// Phase cells (private): query points grouped into square cells whose
// per-wave phase is reduced in double on the CPU. A shader adds only
// k*D*(point - cell origin) in float, which stays small anywhere in the world.
#pragma once

#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "host_device.h"
#include "tidewater/waves.hpp"

namespace tidewater::render::detail {

inline constexpr double kPhaseCellSize = 64.0;  // m

struct PhaseCells {
    std::vector<gpu::GpuQueryPoint> points;
    std::vector<float> base_phase;    // [cell * wave_count + wave]
    std::vector<glm::dvec2> origins;  // world xz of each cell's origin, m
    std::size_t cell_count = 0;
};

/// Groups `points` into cells and computes every cell's base phases at `local_time`.
PhaseCells build_phase_cells(const WaveSet& set, double local_time, std::span<const glm::dvec2> points);

/// The waves as the shaders read them.
std::vector<gpu::GpuWave> gpu_waves(const WaveSet& set);

}  // namespace tidewater::render::detail
