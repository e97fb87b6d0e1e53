#version 450
// Displaces each water vertex by its body's water at its rest position: the same
// evaluation the CPU queries solve for (water_point.glsl; the ocean's and lakes'
// waves in water_body.glsl, a river's in river_water.glsl with the still water it
// runs into fading in at its mouth), with far, short waves faded for LOD.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_lod.glsl"
#include "water_draw.glsl"
uint g_wave_first = 0u, g_wave_count = 0u;
#define SHORE_LAYER_BASE g_draw.shore_base.x
#define WAVE_FIRST g_wave_first
#define WAVE_COUNT g_wave_count
#define WAVE_BASE_PHASE(i) waves[WAVE_FIRST + (i)].steep_omega.z
#include "water_quality.glsl"
#define WAVE_DRAWN(w) (!wave_left_to_variance(w))
#include "shore_fields.glsl"
#include "water_point.glsl"
#include "water_body.glsl"
#include "river_water.glsl"
#define WAKE_COUNT uint(frame.wakes.x)
#define WAKE_TURBULENT uint(frame.wakes.y)
#include "wake_point.glsl"
layout(quads, fractional_odd_spacing, ccw) in;
layout(location = 0) in vec2 control_xz[];
layout(location = 1) in vec4 corner_hidden[];
layout(location = 2) in vec4 corner_hidden_lagged[];
layout(location = 3) in vec4 corner_hidden_lagged_slope[];
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 geo_normal;
layout(location = 2) out vec2 rest_xz;
layout(location = 3) out float jacobian;
layout(location = 4) out float eta;
layout(location = 5) out float wake_eta;    // the wakes' share of eta (m)
layout(location = 6) out vec2 shore_info;  // x: signed shore distance (m), y: breaking 0..1
layout(location = 7) out float rest_level; // the still surface here, world y (m)
layout(location = 8) out vec2 current;     // a river's current (m/s)
layout(location = 9) out vec4 lagged_jacobian;  // the waves' Jacobian at the rest position 0.5, 1, 1.5, 2 s ago
// The waves the pixels cannot resolve, from the patch's corners (water.tesc; foam_filter.glsl).
layout(location = 10) out vec4 hidden;
layout(location = 11) out vec4 hidden_lagged;
layout(location = 12) out vec4 hidden_lagged_slope;

vec4 across_patch(vec4 c0, vec4 c1, vec4 c2, vec4 c3, vec2 uv) { return mix(mix(c0, c1, uv.x), mix(c2, c3, uv.x), uv.y); }

void main() {
    g_draw = draws[draw_push.draw_index];
    g_wave_first = uint(g_draw.body.z);
    g_wave_count = uint(g_draw.body.w);
    vec2 uv = gl_TessCoord.xy;
    rest_xz = mix(mix(control_xz[0], control_xz[1], uv.x), mix(control_xz[2], control_xz[3], uv.x), uv.y);
    hidden = across_patch(corner_hidden[0], corner_hidden[1], corner_hidden[2], corner_hidden[3], uv);
    hidden_lagged = across_patch(corner_hidden_lagged[0], corner_hidden_lagged[1], corner_hidden_lagged[2], corner_hidden_lagged[3], uv);
    hidden_lagged_slope = across_patch(corner_hidden_lagged_slope[0], corner_hidden_lagged_slope[1], corner_hidden_lagged_slope[2],
                                       corner_hidden_lagged_slope[3], uv);
    WaveLod lod = wave_lod_at(rest_xz, g_draw.body.y, g_draw.lod.x);
    bool shore = g_draw.shore.w > 0.0;
    SurfaceSums s;
    rest_level = g_draw.body.y;
    current = vec2(0.0);
    // The foam particles remember comes from the still water's waves (a river's own ride
    // its current and keep none; wakes make their own foam).
    g_track_lags = kFoamLagsShown > 0u;
    LaggedCompression lagged = lagged_zero();
    if (uint(g_draw.body.x) == kBodyRiver) {
        vec2 rel = rest_xz - g_draw.grid.xy;
        RiverTap tap = river_tap(rel);
        vec4 channel = river_channel_at(tap);
        s = river_water_at(rel, vec2(0.0), channel.xy, lod);
        if (g_wave_count > 0u) {
            add_scaled(s, water_at(rest_xz, rest_xz - g_draw.shore.xy, shore, lod), g_river_still_weight);
            add_scaled(lagged, g_lagged, g_river_still_weight);
        }
        rest_level += river_field(tap, kRiverQuerySurface);
        current = channel.zw;
    } else {
        s = water_at(rest_xz, rest_xz - g_draw.shore.xy, shore, lod);
        lagged = g_lagged;
    }
    lagged_jacobian = lagged_jacobians(lagged);
    // Wakes ride the ocean and the lakes (rivers carry none), as in the CPU queries.
    wake_eta = 0.0;
    if (uint(g_draw.body.x) != kBodyRiver && WAKE_COUNT > 0u && wakes_reach(rest_xz)) {
        SurfaceSums wake = wakes_at(rest_xz);
        add_scaled(s, wake, 1.0);
        wake_eta = wake.eta;
    }
    shore_info = vec2(g_shore_fields.w, g_shore_fields.y);
    eta = s.eta - (rest_level - g_draw.body.y);
    jacobian = surface_jacobian(s);
    geo_normal = surface_normal(s);
    world_pos = vec3(rest_xz.x + s.disp.x, g_draw.body.y + s.eta, rest_xz.y + s.disp.y);
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
