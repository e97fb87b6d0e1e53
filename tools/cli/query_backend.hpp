// The engine behind `tidewater query --backend gpu`: the GPU compute shader on a
// standalone Vulkan device when the renderer is built, answering a whole scene (rivers,
// lakes and the ocean) with the contract of query_world.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater::cli {

using QueryBackend = std::function<Status(const Scene&, double, std::span<const glm::dvec2>, std::span<WorldPoint>)>;

Result<QueryBackend> make_gpu_query_backend();

}  // namespace tidewater::cli
