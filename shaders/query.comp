#version 450
// GPU surface queries: one point per invocation, the Eulerian solve of
// water_point.glsl over one evaluation of the water: a body's still water
// (water_body.glsl, with its shore fields), or a river (river_water.glsl) with the
// still water it runs into fading in at its mouth. Phases arrive reduced per phase
// cell, so float keeps micro-radian accuracy anywhere in the world.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"

layout(local_size_x = 64) in;

layout(std430, set = kQuerySet, binding = eQueryWaves) readonly buffer Waves { GpuWave waves[]; };
layout(std430, set = kQuerySet, binding = eQueryBasePhases) readonly buffer BasePhases { float base_phase[]; };  // [cell * wave_count + i]
layout(std430, set = kQuerySet, binding = eQueryPoints) readonly buffer Points { GpuQueryPoint points[]; };
layout(std430, set = kQuerySet, binding = eQueryResults) writeonly buffer Results { GpuQueryResult results[]; };
// Shore fields; cell origins relative to the shore grid's corner plus params.shore_offset (m).
layout(std430, set = kQuerySet, binding = eQueryShoreWaves) readonly buffer ShoreWavesBuf { vec4 shore_waves[]; };   // a run's [(slot * run waves + wave) * kShoreSlotTexels + texel]
layout(std430, set = kQuerySet, binding = eQueryShoreShared) readonly buffer ShoreShared { vec4 shore_shared[]; };     // [slot * kShoreSlotTexels + texel]
layout(std430, set = kQuerySet, binding = eQueryShorePages) readonly buffer ShorePages { uint shore_pages[]; };        // [tile]: its slot, grid after grid
layout(std430, set = kQuerySet, binding = eQueryShoreLayers) readonly buffer ShoreLayers { GpuShoreLayer shore_layers[]; };  // the runs of waves
layout(std430, set = kQuerySet, binding = eQueryCellOrigins) readonly buffer CellOrigins { vec2 cell_origin[]; };
// A river: its query texels, its channel coordinates and current per texel, its waves.
layout(std430, set = kQuerySet, binding = eQueryRiverTexels) readonly buffer RiverTexels { float river_texels[]; };
layout(std430, set = kQuerySet, binding = eQueryRiverChannel) readonly buffer RiverChannel { vec4 river_channel[]; };   // s, n (m), flow x, z (m/s)
layout(std430, set = kQuerySet, binding = eQueryRiverWaves) readonly buffer RiverWaves { GpuRiverWave river_waves[]; };
// Wakes on still water, relative to the cell origins' zero (the chains in order).
layout(std430, set = kQuerySet, binding = eQueryWakePoints) readonly buffer WakePoints { vec4 wake_blocks[kMaxWakeBlocks]; GpuWakePoint wake_points[]; };
layout(push_constant) uniform Push { GpuQueryParams params; };

#define WAVE_COUNT params.wave_count
#define WAVE_BASE_PHASE(i) base_phase[g_point.cell * params.wave_count + (i)]
#define RIVER_NX params.river_nx
#define RIVER_NZ params.river_nz
#define RIVER_TEXEL params.river_texel
#define RIVER_FIRST_TEXEL 0u
#define RIVER_FIRST_WAVE 0u
#define RIVER_WAVE_COUNT params.river_wave_count
#define RIVER_BANK_RAMP params.river_bank_ramp
#define WAKE_COUNT params.wake_count
#define WAKE_TURBULENT params.wake_turbulent
#define TW_WATER_NEWTON
GpuQueryPoint g_point;
vec4 g_channel;  // the query point's channel coordinates and current (river mode)
#include "noise.glsl"
#include "shore_fields.glsl"
#include "water_point.glsl"
#include "water_body.glsl"
#include "river_water.glsl"
#include "flow_detail.glsl"
#include "wake_point.glsl"

bool river_mode() { return params.river_nx > 0u; }

// The still water's sums at rest offset e (its shore fields when it has them).
SurfaceSums still_water_at(vec2 e) {
    vec2 at = cell_origin[g_point.cell] + g_point.local + e;
    return water_at(g_point.local + e, at - params.shore_offset, params.shore_resolution > 0u, no_wave_lod());
}

SurfaceSums water_at_offset(vec2 e) {
    if (!river_mode()) {
        // Wakes ride still water (not rivers or their plumes), as on the CPU.
        SurfaceSums s = still_water_at(e);
        if (params.wake_count > 0u) add_scaled(s, wakes_at(cell_origin[g_point.cell] + g_point.local + e), 1.0);
        return s;
    }
    SurfaceSums s = river_water_at(cell_origin[g_point.cell] + g_point.local + e, e, g_channel.xy, no_wave_lod());
    if (params.still > 0.5) add_scaled(s, still_water_at(e), g_river_still_weight);
    return s;
}

// The open sea's waves are the same everywhere (no shore, river or wakes).
bool water_sums_jacobian_exact() {
    return !river_mode() && params.shore_resolution == 0u && params.wake_count == 0u;
}

// The waves' earlier compression at rest offset e (LaggedCompression): the still
// water's, faded in as its waves are (a river's own waves ride its current and keep none).
vec4 lagged_jacobian_at(vec2 e) {
    if (river_mode() && params.still < 0.5) return vec4(1.0);
    g_track_lags = true;
    still_water_at(e);
    g_track_lags = false;
    if (!river_mode()) return lagged_jacobians(g_lagged);
    LaggedCompression lagged = lagged_zero();
    vec2 rest = cell_origin[g_point.cell] + g_point.local + e;
    add_scaled(lagged, g_lagged, river_field(river_tap(rest), kRiverQueryStillWeight));
    return lagged_jacobians(lagged);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= params.point_count) return;
    g_point = points[id];
    vec2 at = cell_origin[g_point.cell] + g_point.local;
    // Depth and shore distance belong to the query point itself (rest offset 0).
    vec4 at_point = params.shore_resolution > 0u ? tap_shared(shore_tap(at - params.shore_offset)) : kOpenWaterShore;
    RiverTap at_tap = river_tap(at);  // river mode only
    g_channel = river_mode() ? river_channel_at(at_tap) : vec4(0.0);
    NewtonResult n = solve_rest_offset(newton_tolerance(params.max_offset), newton_radius(params.max_offset) + params.wake_radius);
    GpuQueryResult r;
    // First-order carry to the final step, as on the CPU.
    r.height_normal = vec4(n.sums.eta + dot(n.sums.slope, n.step_e), surface_normal(n.sums));
    // The river's current joins the particles' orbital velocity.
    r.velocity_jac = vec4(n.sums.velocity + vec3(g_channel.z, 0.0, g_channel.w), surface_jacobian(n.sums));
    r.disp_iter = vec4(-(n.e + n.step_e), n.iterations, n.converged);
    float depth = river_mode() ? river_field(at_tap, kRiverQueryDepth) : at_point.x;
    float still_surface = river_mode() ? river_field(at_tap, kRiverQuerySurface) : 0.0;
    r.shore = vec4(depth, at_point.w, g_shore_fields.y, still_surface);
    vec2 detail = params.flow.params.z > 0.0 && river_mode() ? flow_detail_slope(at, g_channel.zw, params.flow) : vec2(0.0);
    r.flow = vec4(g_channel.zw, detail);
    r.wake = vec4(0.0);
    if (!river_mode() && params.wake_count > 0u) {
        vec2 rest = at + n.e;
        r.wake = vec4(wakes_at(rest).eta, wakes_foam_at(rest), 0.0, 0.0);
    }
    r.lagged_jac = lagged_jacobian_at(n.e);
    results[id] = r;
}
