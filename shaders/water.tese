#version 450
// Displaces each water vertex by the body's waves at its rest position: the same
// evaluation the CPU queries solve for (water_point.glsl, water_body.glsl), with far,
// short waves faded for LOD.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_lod.glsl"
#define SHORE_RESOLUTION uint(frame.shore_rect.w)
#define SHORE_TEXEL frame.shore_rect.z
#define WAVE_COUNT uint(frame.params.y)
#define WAVE_BASE_PHASE(i) waves[i].steep_omega.z
#include "shore_fields.glsl"
#include "water_point.glsl"
#include "water_body.glsl"
layout(quads, fractional_odd_spacing, ccw) in;
layout(location = 0) in vec2 control_xz[];
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 geo_normal;
layout(location = 2) out vec2 rest_xz;
layout(location = 3) out float jacobian;
layout(location = 4) out float eta;
layout(location = 5) out float spacing;
layout(location = 6) out vec2 shore_info;  // x: signed shore distance (m), y: breaking 0..1

void main() {
    vec2 uv = gl_TessCoord.xy;
    rest_xz = mix(mix(control_xz[0], control_xz[1], uv.x), mix(control_xz[2], control_xz[3], uv.x), uv.y);
    spacing = vertex_spacing(camera_distance(rest_xz));
    SurfaceSums s = water_at(rest_xz, rest_xz - frame.shore_rect.xy, frame.shore_rect.w > 0.0, spacing);
    shore_info = vec2(g_shore_fields.w, g_shore_fields.y);
    eta = s.eta;
    jacobian = surface_jacobian(s);
    geo_normal = surface_normal(s);
    world_pos = vec3(rest_xz.x + s.disp.x, frame.params.x + s.eta, rest_xz.y + s.disp.y);
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
