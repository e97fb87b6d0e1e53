// A frame size given on the command line as WxH.
#pragma once

#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <charconv>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater::cli {

/// "WxH" with 16 <= W, H <= 8192; the error names `option`.
inline Result<VkExtent2D> parse_extent(const std::string& text, const char* option) {
    const auto x = text.find('x');
    unsigned w = 0, h = 0;
    if (x != std::string::npos) {
        const auto a = std::from_chars(text.data(), text.data() + x, w);
        const auto b = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        if (a.ec == std::errc() && a.ptr == text.data() + x && b.ec == std::errc() &&
            b.ptr == text.data() + text.size() && w >= 16 && h >= 16 && w <= 8192 && h <= 8192)
            return VkExtent2D{w, h};
    }
    return Error{ErrorCode::invalid_argument,
                 fmt::format("{}: \"{}\" is not WxH with 16 <= W, H <= 8192", option, text)};
}

}  // namespace tidewater::cli
