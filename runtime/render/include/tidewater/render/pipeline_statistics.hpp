// The renderer's pipeline statistics (PipelineStageStatistics, renderer.hpp) from a device
// that cannot draw, such as a driver's null device.
//
// Threading: compile_pipeline_statistics builds pipelines on the
// device it is given and must not run while another thread uses that device's queue
// (it submits nothing).
#pragma once

#include <vector>

#include "tidewater/render/renderer.hpp"
#include "tidewater/result.hpp"

namespace tidewater::render {

/// Builds the renderer's pipelines as RendererInitInfo `init` asks (its formats, samples,
/// per-sample water, wireframe, quality tier) on `init.device`, draws nothing, and returns the
/// statistics of every stage. For devices that cannot draw, such as a driver's null
/// device. Fails with ErrorCode::unsupported, saying so, where the device has no
/// pipeline_executable_info.
Result<std::vector<PipelineStageStatistics>> compile_pipeline_statistics(const RendererInitInfo& init);

}  // namespace tidewater::render
