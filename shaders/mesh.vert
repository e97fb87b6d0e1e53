#version 450
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
// A mesh with per-vertex normals (the floating bodies), relative to a push-constant origin.
layout(location = 0) in vec3 in_position;  // relative to the mesh origin
layout(location = 1) in vec3 in_normal;
layout(push_constant) uniform Push { layout(offset = kPushMeshOrigin) vec4 mesh_origin; };  // xyz: mesh origin relative to O
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 normal;
void main() {
    world_pos = in_position + mesh_origin.xyz;
    normal = in_normal;
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
