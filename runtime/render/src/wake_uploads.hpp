// A frame's wakes as the shaders read them (private): the host's and the scene's boats'.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "host_device.h"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/wakes.hpp"

namespace tidewater::render::detail {

struct WakeUpload {
    std::vector<gpu::GpuWakePoint> points;  ///< chains with turbulence first, positions relative to O
    std::uint32_t turbulent = 0;            ///< how many of the first points belong to them
    double displacement_bound = 0.0;        ///< as detail::PreparedWakes
    std::vector<glm::vec4> boxes;   ///< where they reach, relative to O (at most kMaxWakeBoxes: the rest merged)
    std::vector<glm::vec4> blocks;  ///< per kWakeBlockPoints points: centre xz (relative to O), squared radius, 0
};

/// Bytes of a wake buffer for `points` points: kMaxWakeBlocks block discs, then the points.
std::size_t wake_buffer_bytes(std::size_t points);
/// Writes `upload`'s block discs and points into a mapped wake buffer of at least
/// wake_buffer_bytes(upload.points.size()) bytes.
void write_wake_buffer(const WakeUpload& upload, void* mapped);

/// The wakes of `scene`'s boats and the host's (null: none) at clock time `time`, prepared
/// as the CPU queries prepare them (detail::prepare_wakes) and placed relative to the
/// render origin. Fails, naming the field, on bad host wakes or more than kMaxWakePoints.
Result<WakeUpload> pack_wakes(const Scene& scene, const Wakes* host, double time, glm::dvec2 origin);
/// `wakes` alone (validated), placed relative to `origin`.
Result<WakeUpload> pack_wakes(const Wakes& wakes, double time, glm::dvec2 origin);

}  // namespace tidewater::render::detail
