// A square part of the world (internal): what a shore model or a lake's basin covers.
// Units: metres.
#pragma once

#include <glm/vec2.hpp>

namespace tidewater {

struct SquareRegion {
    glm::dvec2 center{0.0};
    double half_size = 0.0;  ///< > 0
};

}  // namespace tidewater
