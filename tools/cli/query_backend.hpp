// The engine behind `tidewater query --backend`: the CPU kernel, or the GPU
// compute shader on a standalone Vulkan device when the renderer is built.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "tidewater/query.hpp"

namespace tidewater::cli {

using QueryBackend = std::function<Status(const WaterBody&, double, std::span<const glm::dvec2>, std::span<SurfacePoint>)>;

Result<QueryBackend> make_query_backend(const std::string& name, unsigned threads);

}  // namespace tidewater::cli
