#include "phase_cells.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "tidewater/gerstner.hpp"

namespace tidewater::render::detail {

PhaseCells build_phase_cells(const WaveSet& set, double local_time, std::span<const glm::dvec2> points) {
    PhaseCells out;
    const auto waves = set.waves();
    std::vector<double> offsets(waves.size());
    phase_offsets_at(set, local_time, offsets);
    std::unordered_map<std::uint64_t, std::uint32_t> index;
    std::vector<glm::dvec2> origins;
    out.points.reserve(points.size());
    for (const glm::dvec2& p : points) {
        const double cx = std::floor(p.x / kPhaseCellSize), cz = std::floor(p.y / kPhaseCellSize);
        const auto key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(static_cast<std::int32_t>(cx))) << 32) |
                         static_cast<std::uint32_t>(static_cast<std::int32_t>(cz));
        auto [it, inserted] = index.try_emplace(key, static_cast<std::uint32_t>(origins.size()));
        if (inserted) origins.push_back({cx * kPhaseCellSize, cz * kPhaseCellSize});
        const glm::dvec2 origin = origins[it->second];
        out.points.push_back(
            {glm::vec2(static_cast<float>(p.x - origin.x), static_cast<float>(p.y - origin.y)), it->second, 0u});
    }
    out.cell_count = origins.size();
    out.origins = origins;
    out.base_phase.resize(origins.size() * waves.size());
    for (std::size_t c = 0; c < origins.size(); ++c) {
        for (std::size_t i = 0; i < waves.size(); ++i) {
            const Wave& w = waves[i];
            const double phase = w.k * (w.dir_x * origins[c].x + w.dir_z * origins[c].y) + offsets[i];
            out.base_phase[c * waves.size() + i] = static_cast<float>(wrap_angle(phase));
        }
    }
    return out;
}

std::vector<gpu::GpuWave> gpu_waves(const WaveSet& set) {
    std::vector<gpu::GpuWave> out;
    for (const Wave& w : set.waves()) {
        gpu::GpuWave g;
        g.dir_k_amp = {static_cast<float>(w.dir_x), static_cast<float>(w.dir_z), static_cast<float>(w.k),
                       static_cast<float>(w.amplitude)};
        g.steep_omega = {static_cast<float>(w.steepness), static_cast<float>(w.omega), 0.0f, 1.0f};
        const double turn = w.omega * static_cast<double>(gpu::kFoamLagStep);
        g.lag_turn = {static_cast<float>(std::sin(turn)), static_cast<float>(std::cos(turn)), 0.0f, 0.0f};
        out.push_back(g);
    }
    return out;
}

}  // namespace tidewater::render::detail
