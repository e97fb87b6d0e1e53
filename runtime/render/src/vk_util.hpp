// VkResult checking (private): every failing call becomes an Error naming the call.
#pragma once

#include <string>
#include <vulkan/vulkan.h>

#include "tidewater/result.hpp"

namespace tidewater::render::detail {

const char* vk_result_name(VkResult result);
Error vk_error(VkResult result, const char* call);

}  // namespace tidewater::render::detail

/// Evaluates a Vulkan call; on failure returns an Error from the enclosing function.
#define TW_VK_TRY(call)                                                     \
    do {                                                                    \
        const VkResult tw_vk_result_ = (call);                              \
        if (tw_vk_result_ != VK_SUCCESS)                                    \
            return ::tidewater::render::detail::vk_error(tw_vk_result_, #call); \
    } while (0)
