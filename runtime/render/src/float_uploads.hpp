// A frame's floating bodies as the float pipeline draws them (private): each hull's
// triangles placed at its pose, flat-shaded, relative to the render origin.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "tidewater/render/renderer.hpp"
#include "tidewater/result.hpp"

namespace tidewater::render::detail {

/// At most this many vertices (three per triangle) of floating bodies a frame.
inline constexpr std::uint32_t kMaxFloatVertices = 3u * 32768u;

struct FloatVertex {
    glm::vec3 position;  ///< world, x and z relative to the render origin, m
    glm::vec3 normal;    ///< the face's
};
static_assert(sizeof(FloatVertex) == 24, "the terrain's vertex layout");

struct FloatUpload {
    struct Draw {
        std::uint32_t first = 0, count = 0;  ///< vertices
        glm::vec3 color{0.8f};
    };
    std::vector<FloatVertex> vertices;
    std::vector<Draw> draws;
};

/// The bodies' triangles at their poses, relative to `origin` (world xz). Fails, naming
/// FrameInfo::floats and the body, on a null or malformed hull, a pose that is not
/// finite, or more than kMaxFloatVertices vertices in all.
Result<FloatUpload> pack_floats(std::span<const FloatDraw> floats, glm::dvec2 origin);

}  // namespace tidewater::render::detail
