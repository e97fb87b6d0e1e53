// Flow-mapped detail: the normal detail a current carries (seeds 001 and 004), and the
// CPU twin of shaders/flow_detail.glsl, which a GPU test holds it to.
//
// Two layers of gradient noise are advected by the current. Each runs a sawtooth
// progress p in [0, 1) over one period T, so a layer never drifts more than
// speed * |v| * T before it starts again; its weight is the triangle 1 - |1 - 2p|,
// zero at the restart, and the second layer runs half a period behind, so the two
// weights sum to one. At each restart the layer's texture coordinates jump by a fixed
// offset (the UV jump), so the same pattern does not come back cycle after cycle. A
// per-texel time offset from a coarser noise staggers the restarts across the water.
//
// The layers are blended as (wA A + wB B) / sqrt(wA^2 + wB^2): for two uncorrelated
// layers of equal variance this keeps the variance of the result constant, where a
// plain linear blend loses 1 - sqrt(0.5) = 29% of the contrast at w = 0.5 and pulses.
//
// Units: metres, seconds; slopes are d height / d x and d height / d z.
// Threading: pure functions.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>

#include "tidewater/result.hpp"

namespace tidewater {

/// A preset's "flow" settings. Strength 0 turns flow detail off.
struct FlowDetailSpec {
    double tiling = 0.35;           ///< noise features per metre, 1/m, in [0.01, 20]
    double speed = 1.0;             ///< how fast the detail moves, as a multiple of the current, [0, 4]
    double strength = 0.0;          ///< slope amplitude of the detail, [0, 1]; 0 = off
    double offset = -0.5;           ///< where in a cycle the detail is undistorted, [-1, 0] (-0.5: mid-cycle)
    double period = 2.0;            ///< one cycle of a layer, s, in [0.1, 60]
    glm::dvec2 jump{0.24, 0.2083};  ///< texture-coordinate jump per cycle, noise cells, each in [-0.5, 0.5]
    std::uint32_t seed = 11;
};

Status validate(const FlowDetailSpec& spec, const std::string& context);

/// The two layers at one point and instant.
struct FlowDetailSample {
    glm::dvec2 slope{0.0};  ///< the blended detail slope (strength included)
    double weight_a = 0.0;  ///< triangle weights, summing to one
    double weight_b = 0.0;
    glm::dvec2 slope_a{0.0};  ///< each layer's slope (strength included), before blending
    glm::dvec2 slope_b{0.0};
};

/// The detail at world point p (x, z) in a current `flow` (m/s) at time t (s).
FlowDetailSample flow_detail(const FlowDetailSpec& spec, glm::dvec2 p, glm::dvec2 flow, double time);

/// What the shader takes per frame, formed in double so that float keeps its precision
/// at any time: frac(t / T), and floor(t / T) * jump reduced modulo the noise lattice's
/// period (256 cells, where it repeats).
struct FlowDetailClock {
    double cycle_fraction = 0.0;  ///< in [0, 1)
    glm::dvec2 jump_base{0.0};    ///< noise cells, in [0, 256)
};
FlowDetailClock flow_detail_clock(const FlowDetailSpec& spec, double time);

}  // namespace tidewater
