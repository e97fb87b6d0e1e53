#version 450
// Displaces each water vertex by the Gerstner sum the CPU evaluates
// (evaluate_lagrangian), with far, short waves faded by water_lod.glsl.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "gerstner.glsl"
#include "water_lod.glsl"
#define SHORE_RESOLUTION uint(frame.shore_rect.w)
#define SHORE_TEXEL frame.shore_rect.z
#include "shore_fields.glsl"
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
    GerstnerSums s = gerstner_zero();
    uint count = uint(frame.params.y);
    bool shore = frame.shore_rect.w > 0.0;
    uint texels = uint(frame.shore_rect.w) * uint(frame.shore_rect.w);
    ShoreTap tap;
    vec4 shared_fields = vec4(1e9, 0.0, 1.0, 1e9);
    if (shore) {
        tap = shore_tap(rest_xz - frame.shore_rect.xy);
        shared_fields = tap_shared(tap);
    }
    shore_info = vec2(shared_fields.w, shared_fields.y);
    for (uint i = 0u; i < count; ++i) {
        GpuWave w = waves[i];
        float theta = w.dir_k_amp.z * dot(w.dir_k_amp.xy, rest_xz) + w.steep_omega.z;
        if (shore && !shore_local_wave(tap, shared_fields, i, texels, w, theta)) continue;
        // Fade by the local wavelength: waves shortened by the shore fade sooner.
        float fade = wave_lod_fade(6.2831853 / w.dir_k_amp.z, spacing);
        if (fade <= 0.0) continue;
        w.dir_k_amp.w *= fade;
        gerstner_accumulate(s, w, theta);
    }
    eta = s.eta;
    jacobian = gerstner_jacobian(s);
    geo_normal = gerstner_normal(s);
    world_pos = vec3(rest_xz.x + s.disp.x, frame.params.x + s.eta, rest_xz.y + s.disp.y);
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
