// SPIR-V compiled from shaders/ at build time (private).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace tidewater::render::detail {

/// The SPIR-V words of a shader by source file name ("query.comp"); empty if unknown.
std::span<const std::uint32_t> embedded_spirv(std::string_view name);

}  // namespace tidewater::render::detail
