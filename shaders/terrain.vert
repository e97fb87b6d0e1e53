#version 450
// The terrain's level-of-detail patch (CDLOD, runtime/render/src/terrain_lod.hpp): one
// instance per selected node. Over the last part of its level's range a vertex on an odd
// grid line slides onto its even neighbour, so that at the range's end the patch is the
// next level's grid and the two meet without a crack or a pop.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
layout(location = 0) in vec2 in_grid;  // 0 .. kTerrainPatchQuads
layout(location = 1) in vec4 in_node;  // GpuTerrainNode.rect
layout(location = 2) in vec4 in_morph; // GpuTerrainNode.morph
layout(location = 0) out vec3 world_pos;
void main() {
    vec2 quad = vec2(in_node.z, in_morph.w) / float(kTerrainPatchQuads);
    vec2 xz = in_node.xy + in_grid * quad;
    // The selection's distance: horizontal, with the camera's height above the ground's band.
    vec2 d = xz - frame.camera.xz;
    float distance = sqrt(dot(d, d) + in_morph.z);
    float morph = clamp((distance - in_morph.x) * in_morph.y, 0.0, 1.0);
    xz -= fract(in_grid * 0.5) * 2.0 * quad * morph;
    world_pos = vec3(xz.x, terrain_height_at(xz), xz.y);
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
