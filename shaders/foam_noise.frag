#version 450
// The foam's noise table (foam_cover.glsl): four channels of gradient noise (seeds 41,
// 43: the lace's warp; 47: its broad patches; 37: its fine grain) over kFoamNoiseCells
// lattice cells, which tile, so the table repeats. Drawn once by a full-screen triangle
// (sky.vert), 8 texels a cell.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "noise.glsl"
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;
void main() {
    vec2 p = (0.5 + 0.5 * ndc) * float(kFoamNoiseCells);
    const uint period = kFoamNoiseCells - 1u;
    out_color = vec4(gradient_noise_tiled(p, 41u, period).x, gradient_noise_tiled(p, 43u, period).x,
                     gradient_noise_tiled(p, 47u, period).x, gradient_noise_tiled(p, 37u, period).x);
}
