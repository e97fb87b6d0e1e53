// VkResult checking (private): every failing call becomes an Error naming the call.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "tidewater/result.hpp"
#include "vk_device.hpp"

namespace tidewater::render::detail {

const char* vk_result_name(VkResult result);
Error vk_error(VkResult result, const char* call);

/// One image layout transition (synchronization 1, core in every Vulkan 1.3 device).
void transition(const VulkanFunctions& vk, VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                VkImageLayout from, VkImageLayout to, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                VkPipelineStageFlags dst_stage, VkAccessFlags dst_access);

/// Full-extent viewport and scissor (both dynamic in every Tidewater pipeline).
void set_viewport(const VulkanFunctions& vk, VkCommandBuffer cmd, VkExtent2D extent);
/// Viewport and scissor over `area` of the targets (a view's rectangle).
void set_viewport(const VulkanFunctions& vk, VkCommandBuffer cmd, VkRect2D area);

}  // namespace tidewater::render::detail

/// Evaluates a Vulkan call; on failure returns an Error from the enclosing function.
#define TW_VK_TRY(call)                                                                                      \
    do {                                                                                                     \
        const VkResult tw_vk_result_ = (call);                                                               \
        if (tw_vk_result_ != VK_SUCCESS) return ::tidewater::render::detail::vk_error(tw_vk_result_, #call); \
    } while (0)
