#version 450
// Displaces each water vertex by the Gerstner sum the CPU evaluates
// (evaluate_lagrangian), with far, short waves faded by water_lod.glsl.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "gerstner.glsl"
#include "water_lod.glsl"
layout(quads, fractional_odd_spacing, ccw) in;
layout(location = 0) in vec2 control_xz[];
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 geo_normal;
layout(location = 2) out vec2 rest_xz;
layout(location = 3) out float jacobian;
layout(location = 4) out float eta;
layout(location = 5) out float spacing;

void main() {
    vec2 uv = gl_TessCoord.xy;
    rest_xz = mix(mix(control_xz[0], control_xz[1], uv.x), mix(control_xz[2], control_xz[3], uv.x), uv.y);
    spacing = vertex_spacing(camera_distance(rest_xz));
    GerstnerSums s = gerstner_zero();
    uint count = uint(frame.params.y);
    for (uint i = 0u; i < count; ++i) {
        GpuWave w = waves[i];
        float fade = wave_lod_fade(w.steep_omega.w, spacing);
        if (fade <= 0.0) continue;
        w.dir_k_amp.w *= fade;
        float theta = w.dir_k_amp.z * dot(w.dir_k_amp.xy, rest_xz) + w.steep_omega.z;
        gerstner_accumulate(s, w, theta);
    }
    eta = s.eta;
    jacobian = gerstner_jacobian(s);
    geo_normal = gerstner_normal(s);
    world_pos = vec3(rest_xz.x + s.disp.x, frame.params.x + s.eta, rest_xz.y + s.disp.y);
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
