// The host target formats the renderer accepts (the table in renderer.hpp) and how it
// treats each (private): whether the shaders write linear colour, the texel size of a
// colour copy, and a depth format's aspects and attachment layout.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace tidewater::render::detail {

struct ColorTarget {
    VkFormat format;
    const char* name;
    /// The shaders write linear colour (the target encodes sRGB, or stores floats the host
    /// tone-maps) rather than display-referred sRGB values.
    bool linear_output;
    std::uint32_t texel_bytes;
};

struct DepthTarget {
    VkFormat format;
    const char* name;
    VkImageAspectFlags aspects;       ///< every aspect, for layout transitions
    VkImageLayout attachment_layout;  ///< the layout the host hands it in and gets it back
    std::uint32_t texel_bytes;        ///< of its depth aspect in a buffer copy
};

/// The accepted formats, or null.
const ColorTarget* find_color_target(VkFormat format);
const DepthTarget* find_depth_target(VkFormat format);

/// A format's name ("VK_FORMAT_R8G8B8A8_UNORM"), or its number for formats outside the table.
std::string format_name(VkFormat format);
/// The accepted colour and depth formats, for messages.
std::string accepted_formats();

}  // namespace tidewater::render::detail
