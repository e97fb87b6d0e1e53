// The engine behind `tidewater query --backend gpu`: the GPU compute shader on a
// standalone Vulkan device when the renderer is built (the CPU answers through
// query_world).
#pragma once

#include <functional>
#include <span>
#include <string>

#include "tidewater/query.hpp"

namespace tidewater::cli {

using QueryBackend = std::function<Status(const WaterBody&, double, std::span<const glm::dvec2>, std::span<SurfacePoint>)>;

Result<QueryBackend> make_gpu_query_backend();

}  // namespace tidewater::cli
