#version 450
// GPU surface queries: one point per invocation, the Eulerian solve of
// water_point.glsl over the body's waves (water_body.glsl). Phases arrive reduced
// per phase cell, so float keeps micro-radian accuracy anywhere in the world.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Waves { GpuWave waves[]; };
layout(std430, set = 0, binding = 1) readonly buffer BasePhases { float base_phase[]; };  // [cell * wave_count + i]
layout(std430, set = 0, binding = 2) readonly buffer Points { GpuQueryPoint points[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Results { GpuQueryResult results[]; };
// Shore fields; cell origins relative to the shore grid's corner (m).
layout(std430, set = 0, binding = 4) readonly buffer ShoreWavesBuf { vec4 shore_waves[]; };   // [wave * texels + texel]
layout(std430, set = 0, binding = 5) readonly buffer ShoreShared { vec4 shore_shared[]; };     // [texel]
layout(std430, set = 0, binding = 6) readonly buffer CellOrigins { vec2 cell_origin[]; };
layout(push_constant) uniform Push { GpuQueryParams params; };

#define SHORE_RESOLUTION params.shore_resolution
#define SHORE_TEXEL params.shore_texel
#define WAVE_COUNT params.wave_count
#define WAVE_BASE_PHASE(i) base_phase[g_point.cell * params.wave_count + (i)]
#define TW_WATER_NEWTON
GpuQueryPoint g_point;
#include "shore_fields.glsl"
#include "water_point.glsl"
#include "water_body.glsl"

SurfaceSums water_at_offset(vec2 e) {
    return water_at(g_point.local + e, cell_origin[g_point.cell] + g_point.local + e, params.shore_resolution > 0u, 0.0);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= params.point_count) return;
    g_point = points[id];
    // Depth and shore distance belong to the query point itself (rest offset 0).
    vec4 at_point = params.shore_resolution > 0u ? tap_shared(shore_tap(cell_origin[g_point.cell] + g_point.local)) : kOpenWaterShore;
    NewtonResult n = solve_rest_offset(newton_tolerance(params.max_offset), newton_radius(params.max_offset));
    GpuQueryResult r;
    // First-order carry to the final step, as on the CPU.
    r.height_normal = vec4(n.sums.eta + dot(n.sums.slope, n.step_e), surface_normal(n.sums));
    r.velocity_jac = vec4(n.sums.velocity, surface_jacobian(n.sums));
    r.disp_iter = vec4(-(n.e + n.step_e), n.iterations, n.converged);
    r.shore = vec4(at_point.x, at_point.w, g_shore_fields.y, 0.0);
    results[id] = r;
}
