#version 450
// GPU surface queries: the Eulerian Newton solve of runtime/core's query
// kernel, one point per invocation. Phases arrive reduced per phase cell, so
// float keeps micro-radian accuracy anywhere in the world.
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

#include "gerstner.glsl"

const int kMaxNewtonIterations = 48;

#define SHORE_RESOLUTION params.shore_resolution
#define SHORE_TEXEL params.shore_texel
#include "shore_fields.glsl"

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= params.point_count) return;
    GpuQueryPoint p = points[id];
    uint row = p.cell * params.wave_count;

    vec2 e = vec2(0.0);            // rest position minus the point
    GerstnerSums s = gerstner_zero();
    vec2 step_e = vec2(0.0);
    float det = 1.0;
    float iterations = 0.0;
    float converged = 0.0;
    bool shore = params.shore_resolution > 0u;
    vec2 last_e = e;
    float last_f2 = 3.0e38;
    uint texels = params.shore_resolution * params.shore_resolution;
    vec4 shared_fields = vec4(1e9, 1e9, 0.0, 1.0);
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        s = gerstner_zero();
        ShoreTap tap;
        if (shore) {
            tap = shore_tap(cell_origin[p.cell] + p.local + e);
            shared_fields = tap_shared(tap);
        }
        for (uint i = 0u; i < params.wave_count; ++i) {
            GpuWave w = waves[i];
            // Same association as the CPU kernel: base + kz*ez + kx*ex (fma order).
            float theta = fma(w.dir_k_amp.x * w.dir_k_amp.z, p.local.x + e.x,
                              fma(w.dir_k_amp.y * w.dir_k_amp.z, p.local.y + e.y, base_phase[row + i]));
            // The wave as the shore shapes it here: phase residual, amplitude, local wavevector.
            if (shore && !shore_local_wave(tap, shared_fields, i, texels, w, theta)) continue;
            gerstner_accumulate(s, w, theta);
        }
        iterations += 1.0;
        float jxx = 1.0 - s.m.x, jxz = -s.m.y, jzz = 1.0 - s.m.z;
        det = jxx * jzz - jxz * jxz;
        vec2 f = e + s.disp;
        step_e = vec2(jxz * f.y - jzz * f.x, jxz * f.x - jxx * f.y) / det;
        if (dot(f, f) <= params.tolerance * params.tolerance) {
            converged = 1.0;
            break;
        }
        if (it + 1 == kMaxNewtonIterations) break;  // report the last evaluation unconverged
        // Shore fields change within a texel near the waterline: step back halfway when |F| grows.
        if (shore && dot(f, f) > last_f2) {
            e = 0.5 * (e + last_e);
            continue;
        }
        last_f2 = dot(f, f);
        last_e = e;
        e += step_e;
        float r2 = dot(e, e);
        if (r2 > params.max_offset * params.max_offset) e *= sqrt(params.max_offset * params.max_offset / r2);
    }
    GpuQueryResult r;
    // First-order carry to the final step, as on the CPU.
    r.height_normal = vec4(s.eta + dot(s.slope, step_e), gerstner_normal(s));
    r.velocity_jac = vec4(s.velocity, det);
    r.disp_iter = vec4(-(e + step_e), iterations, converged);
    r.shore = vec4(shared_fields.x, shared_fields.w, shared_fields.y, 0.0);
    results[id] = r;
}
