#version 450
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_lod.glsl"
#include "water_draw.glsl"
#include "foam_filter.glsl"
layout(vertices = 4) out;
layout(location = 0) in vec2 patch_xz[];
layout(location = 0) out vec2 control_xz[];
// The waves a pixel at this corner cannot resolve (hidden_waves_at), packed.
layout(location = 1) out vec4 corner_hidden[];
layout(location = 2) out vec4 corner_hidden_lagged[];
layout(location = 3) out vec4 corner_hidden_lagged_slope[];

float edge_level(vec2 a, vec2 b) {
    GpuBodyDraw d = draws[draw_push.draw_index];
    return tessellation_level(a, b, d.body.y, d.lod.x);
}

bool outside_frustum() {
    // The displaced surface stays within the rest patch grown by the largest displacement,
    // between the rest level and the highest rest surface (a river's source).
    GpuBodyDraw d = draws[draw_push.draw_index];
    float margin = d.extra.w;
    vec2 lo = min(min(patch_xz[0], patch_xz[1]), min(patch_xz[2], patch_xz[3])) - margin;
    vec2 hi = max(max(patch_xz[0], patch_xz[1]), max(patch_xz[2], patch_xz[3])) + margin;
    vec4 c[8];
    for (int i = 0; i < 8; ++i) {
        vec3 p = vec3((i & 1) != 0 ? hi.x : lo.x, d.body.y + ((i & 2) != 0 ? d.extra.z + margin : -margin), (i & 4) != 0 ? hi.y : lo.y);
        c[i] = frame.view_proj * vec4(p, 1.0);
    }
    bvec4 all_out_a = bvec4(true), all_out_b = bvec4(true);
    for (int i = 0; i < 8; ++i) {
        all_out_a = bvec4(all_out_a.x && c[i].x < -c[i].w, all_out_a.y && c[i].x > c[i].w,
                          all_out_a.z && c[i].y < -c[i].w, all_out_a.w && c[i].y > c[i].w);
        all_out_b.x = all_out_b.x && c[i].w <= 0.0;
    }
    return any(all_out_a) || all_out_b.x;
}

// An ocean ring's patch that lies wholly in the square the draw inside covers.
bool in_ring_hole() {
    GpuBodyDraw d = draws[draw_push.draw_index];
    if (uint(d.body.x) != kBodyOcean || d.grid.z <= 0.0) return false;
    vec2 lo = min(min(patch_xz[0], patch_xz[1]), min(patch_xz[2], patch_xz[3]));
    vec2 hi = max(max(patch_xz[0], patch_xz[1]), max(patch_xz[2], patch_xz[3]));
    return all(greaterThanEqual(lo, d.grid.xy)) && all(lessThanEqual(hi, d.grid.xy + d.grid.z));
}

void main() {
    control_xz[gl_InvocationID] = patch_xz[gl_InvocationID];
    {
        GpuBodyDraw d = draws[draw_push.draw_index];
        mat3x4 hidden = hidden_waves_packed(hidden_waves_at(d, wave_lod_at(patch_xz[gl_InvocationID], d.body.y, d.lod.x)));
        corner_hidden[gl_InvocationID] = hidden[0];
        corner_hidden_lagged[gl_InvocationID] = hidden[1];
        corner_hidden_lagged_slope[gl_InvocationID] = hidden[2];
    }
    if (gl_InvocationID == 0) {
        if (in_ring_hole() || outside_frustum()) {
            gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
            gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
            return;
        }
        // Quad edges: 0: u = 0 (corners 0-2), 1: v = 0 (0-1), 2: u = 1 (1-3), 3: v = 1 (2-3).
        gl_TessLevelOuter[0] = edge_level(patch_xz[0], patch_xz[2]);
        gl_TessLevelOuter[1] = edge_level(patch_xz[0], patch_xz[1]);
        gl_TessLevelOuter[2] = edge_level(patch_xz[1], patch_xz[3]);
        gl_TessLevelOuter[3] = edge_level(patch_xz[2], patch_xz[3]);
        gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
        gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
    }
}
