// Graphics pipeline creation for the renderer (private): dynamic rendering,
// SPIR-V from the embedded shaders.
#pragma once

#include <string_view>
#include <vulkan/vulkan.h>

#include "tidewater/render/device_context.hpp"
#include "tidewater/result.hpp"

namespace tidewater::render::detail {

struct PipelineDesc {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    std::string_view vertex, tess_control, tess_eval, fragment;  // embedded shader names; tess ones optional
    bool terrain_vertices = false;   // position + normal, 24-byte stride
    bool depth_write = true;
    VkPolygonMode polygon_mode = VK_POLYGON_MODE_FILL;
};

Result<VkPipeline> create_pipeline(const DeviceContext& ctx, const PipelineDesc& desc);

}  // namespace tidewater::render::detail
