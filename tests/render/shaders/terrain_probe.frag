#version 450
// Render-test probe in place of terrain.frag: writes one value of the ground under the
// fragment in 24-bit fixed point over the RGB bytes of an RGBA8 UNORM target (which keeps
// them exactly; the readback's alpha is not the shader's). PROBE_FIELD 0: world x relative
// to the render origin, 1: z (both in [-2048, 2048) m); 2: terrain_height_at there, the
// GLSL twin of Terrain::height_at that the parity test checks ([-128, 128) m). White
// (0xffffff) is left to the sky.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 0) out vec4 out_color;

void main() {
    float range = PROBE_FIELD == 2 ? 128.0 : 2048.0;
    float v = PROBE_FIELD == 0 ? world_pos.x : PROBE_FIELD == 1 ? world_pos.z : terrain_height_at(world_pos.xz);
    uint code = uint(clamp((v + range) / (2.0 * range), 0.0, 1.0) * 16777214.0 + 0.5);
    out_color = vec4(unpackUnorm4x8(code).rgb, 1.0);
}
