// The shore fields packed for the shaders (private): one vec4 per wave and texel
// (phase residual, amplitude factor, wavevector x, z) and one per texel (depth,
// breaking, steepness scale, shore distance). See shaders/shore_fields.glsl.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "tidewater/shore_waves.hpp"

namespace tidewater::render::detail {

struct PackedShore {
    std::vector<glm::vec4> per_wave{glm::vec4(0.0f)};  // placeholders when there is no shore
    std::vector<glm::vec4> shared{glm::vec4(0.0f)};
};

PackedShore pack_shore(const ShoreWaves* shore);

}  // namespace tidewater::render::detail
