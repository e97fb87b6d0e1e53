// Text resources compiled into the library (bundled presets and scenes),
// generated from examples/ by cmake/TidewaterEmbedScript.cmake.
#pragma once

#include <span>
#include <string_view>

namespace tidewater::detail {

struct EmbeddedText {
    std::string_view name;  ///< File stem, e.g. "ocean_rolling".
    std::string_view text;
};

}  // namespace tidewater::detail

namespace tidewater::embedded::presets {
std::span<const tidewater::detail::EmbeddedText> entries();
}
namespace tidewater::embedded::scenes {
std::span<const tidewater::detail::EmbeddedText> entries();
}
