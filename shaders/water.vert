#version 450
// Water patch corners from the instance index: a regular grid (the ocean) or the
// draw's patch list (lakes and rivers: only patches that hold their water).
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_draw.glsl"
layout(location = 0) out vec2 patch_xz;
void main() {
    GpuBodyDraw d = draws[draw_push.draw_index];
    uint px, pz;
    if (d.patch_grid.w > 0.0) {
        uint n = uint(d.patch_grid.w);
        px = uint(gl_InstanceIndex) % n;
        pz = uint(gl_InstanceIndex) / n;
    } else {
        uint code = patch_list[uint(d.extra.y) + uint(gl_InstanceIndex)];
        px = code & 0xffffu;
        pz = code >> 16;
    }
    vec2 corner = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
    patch_xz = d.patch_grid.xy + (vec2(px, pz) + corner) * d.patch_grid.z;
}
