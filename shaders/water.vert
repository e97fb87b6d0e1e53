#version 450
// Water patch corners from the instance index: no vertex buffer.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
layout(location = 0) out vec2 patch_xz;
void main() {
    uint n = uint(frame.water_patch.y);
    uint px = uint(gl_InstanceIndex) % n, pz = uint(gl_InstanceIndex) / n;
    vec2 corner = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
    patch_xz = frame.water_patch.zw + (vec2(px, pz) + corner) * frame.water_patch.x;
}
