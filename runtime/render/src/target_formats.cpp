#include "target_formats.hpp"

#include <fmt/format.h>

namespace tidewater::render::detail {

namespace {

constexpr ColorTarget kColorTargets[] = {
    {VK_FORMAT_R8G8B8A8_UNORM, "VK_FORMAT_R8G8B8A8_UNORM", false, 4},
    {VK_FORMAT_B8G8R8A8_UNORM, "VK_FORMAT_B8G8R8A8_UNORM", false, 4},
    {VK_FORMAT_R8G8B8A8_SRGB, "VK_FORMAT_R8G8B8A8_SRGB", true, 4},
    {VK_FORMAT_B8G8R8A8_SRGB, "VK_FORMAT_B8G8R8A8_SRGB", true, 4},
    {VK_FORMAT_R16G16B16A16_SFLOAT, "VK_FORMAT_R16G16B16A16_SFLOAT", true, 8},
};

constexpr DepthTarget kDepthTargets[] = {
    {VK_FORMAT_D32_SFLOAT, "VK_FORMAT_D32_SFLOAT", VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
     4},
    {VK_FORMAT_D16_UNORM, "VK_FORMAT_D16_UNORM", VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
     2},
    {VK_FORMAT_D32_SFLOAT_S8_UINT, "VK_FORMAT_D32_SFLOAT_S8_UINT",
     VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 4},
};

}  // namespace

const ColorTarget* find_color_target(VkFormat format) {
    for (const ColorTarget& t : kColorTargets)
        if (t.format == format) return &t;
    return nullptr;
}

const DepthTarget* find_depth_target(VkFormat format) {
    for (const DepthTarget& t : kDepthTargets)
        if (t.format == format) return &t;
    return nullptr;
}

std::string format_name(VkFormat format) {
    if (const ColorTarget* c = find_color_target(format)) return c->name;
    if (const DepthTarget* d = find_depth_target(format)) return d->name;
    switch (format) {
        case VK_FORMAT_UNDEFINED:
            return "VK_FORMAT_UNDEFINED";
        case VK_FORMAT_R8G8B8A8_SNORM:
            return "VK_FORMAT_R8G8B8A8_SNORM";
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            return "VK_FORMAT_A2B10G10R10_UNORM_PACK32";
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return "VK_FORMAT_R32G32B32A32_SFLOAT";
        case VK_FORMAT_D24_UNORM_S8_UINT:
            return "VK_FORMAT_D24_UNORM_S8_UINT";
        case VK_FORMAT_D16_UNORM_S8_UINT:
            return "VK_FORMAT_D16_UNORM_S8_UINT";
        case VK_FORMAT_X8_D24_UNORM_PACK32:
            return "VK_FORMAT_X8_D24_UNORM_PACK32";
        default:
            break;
    }
    return fmt::format("VkFormat {}", static_cast<int>(format));
}

std::string accepted_formats() {
    std::string colour, depth;
    for (const ColorTarget& t : kColorTargets) colour += (colour.empty() ? "" : ", ") + std::string(t.name);
    for (const DepthTarget& t : kDepthTargets) depth += (depth.empty() ? "" : ", ") + std::string(t.name);
    return fmt::format("colour: {}; depth: {}", colour, depth);
}

}  // namespace tidewater::render::detail
