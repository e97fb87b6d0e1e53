// Reading a pipeline's statistics (private): VK_KHR_pipeline_executable_properties, for
// pipelines built with VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR (create_pipeline does
// where the device has pipeline_executable_info).
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>
#include <vector>

#include "render_pipelines.hpp"
#include "tidewater/render/renderer.hpp"
#include "vk_device.hpp"

namespace tidewater::render::detail {

/// Every executable of `pipeline` with its statistics, named `name`; appended to `out`.
Status read_pipeline_statistics(const Device& ctx, VkPipeline pipeline, std::string_view name,
                                std::vector<PipelineStageStatistics>& out);

/// The statistics of every pipeline in `draws` that exists, by the renderer's names.
Result<std::vector<PipelineStageStatistics>> draw_pipeline_statistics(const Device& ctx, const DrawPipelines& draws);

}  // namespace tidewater::render::detail
