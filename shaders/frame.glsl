// Descriptor set 0 of the render pipelines (see Renderer): frame constants,
// waves, the terrain height texture and the copy of the opaque scene.
#ifndef TIDEWATER_FRAME_GLSL
#define TIDEWATER_FRAME_GLSL

layout(std140, set = 0, binding = 0) uniform Frame { GpuFrame frame; };
layout(std430, set = 0, binding = 1) readonly buffer Waves { GpuWave waves[]; };
layout(set = 0, binding = 2) uniform sampler2D terrain_height;  // R32F, metres
layout(set = 0, binding = 3) uniform sampler2D scene_color;
layout(set = 0, binding = 4) uniform sampler2D scene_depth;
layout(std430, set = 0, binding = 5) readonly buffer ShoreWavesBuf { vec4 shore_waves[]; };
layout(std430, set = 0, binding = 6) readonly buffer ShoreSharedBuf { vec4 shore_shared[]; };

float terrain_height_at(vec2 xz) {
    vec2 uv = (xz - frame.terrain_rect.xy) / frame.terrain_rect.zw;
    return textureLod(terrain_height, uv, 0.0).r;
}

// Sky radiance toward direction d (y up): a zenith-to-horizon gradient plus the sun.
vec3 sky_color(vec3 d) {
    float up = clamp(d.y, -0.2, 1.0);
    vec3 zenith = vec3(0.16, 0.36, 0.72);
    vec3 horizon = vec3(0.72, 0.82, 0.92);
    vec3 sky = mix(horizon, zenith, pow(max(up, 0.0), 0.45));
    if (up < 0.0) sky = mix(horizon, vec3(0.35, 0.42, 0.5), -up * 5.0);
    float s = max(dot(d, frame.sun.xyz), 0.0);
    sky += frame.sun.w * (pow(s, 900.0) * vec3(8.0, 7.0, 5.5) + pow(s, 12.0) * vec3(0.25, 0.2, 0.12));
    return sky;
}

// Distance fog toward the horizon colour.
vec3 apply_fog(vec3 color, float distance, vec3 dir) {
    float f = 1.0 - exp(-distance * 0.00018);
    return mix(color, sky_color(normalize(vec3(dir.x, max(dir.y, 0.02), dir.z))), clamp(f, 0.0, 1.0));
}

vec3 heat_color(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(1.5 * t, 1.5 * t * (1.0 - t) * 2.0, 1.5 * (1.0 - t)), 0.0, 1.0);
}

// Integer-hashed gradient noise: the GLSL twin of tidewater::gradient_noise.
uint tw_hash(int ix, int iz, uint seed) {
    uint x = uint(((ix % 256) + 256) % 256);
    uint z = uint(((iz % 256) + 256) % 256);
    uint h = (x * 0x8da6b343u) ^ (z * 0xd8163841u) ^ (seed * 0xcb1ab31fu);
    h ^= h >> 16; h *= 0x85ebca6bu; h ^= h >> 13; h *= 0xc2b2ae35u; h ^= h >> 16;
    return h;
}
vec2 tw_gradient(uint h) {
    const float d = 0.70710678;
    const vec2 g[8] = vec2[8](vec2(1, 0), vec2(-1, 0), vec2(0, 1), vec2(0, -1), vec2(d, d), vec2(-d, d), vec2(d, -d), vec2(-d, -d));
    return g[h & 7u];
}
// Returns (value, d/dx, d/dz) in lattice units.
vec3 gradient_noise(vec2 p, uint seed) {
    vec2 i = floor(p);
    vec2 f = p - i;
    ivec2 c = ivec2(i);
    vec2 g00 = tw_gradient(tw_hash(c.x, c.y, seed)), g10 = tw_gradient(tw_hash(c.x + 1, c.y, seed));
    vec2 g01 = tw_gradient(tw_hash(c.x, c.y + 1, seed)), g11 = tw_gradient(tw_hash(c.x + 1, c.y + 1, seed));
    float n00 = dot(g00, f), n10 = dot(g10, f - vec2(1, 0)), n01 = dot(g01, f - vec2(0, 1)), n11 = dot(g11, f - vec2(1, 1));
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec2 du = 30.0 * f * f * (f - 1.0) * (f - 1.0);
    float nx0 = mix(n00, n10, u.x), nx1 = mix(n01, n11, u.x);
    vec2 gx0 = mix(g00, g10, u.x) + vec2(du.x * (n10 - n00), 0.0);
    vec2 gx1 = mix(g01, g11, u.x) + vec2(du.x * (n11 - n01), 0.0);
    const float scale = 1.4142135;
    return scale * vec3(mix(nx0, nx1, u.y), mix(gx0, gx1, u.y) + vec2(0.0, du.y * (nx1 - nx0)));
}

// Ripple slope (d/dx, d/dz) at xz relative to O; the origin enters reduced modulo the noise period.
vec2 ripple_slope(vec2 xz) {
    vec2 slope = vec2(0.0);
    float amp = frame.ripple.x;
    if (amp <= 0.0) return slope;
    uint seed = uint(frame.ripple.w);
    int octaves = int(frame.ripple.z);
    for (int i = 1; i <= octaves; ++i) {
        float scale = float(i) * frame.ripple.y;
        vec3 n = gradient_noise((xz + frame.origin_mod.zw) * scale + frame.ripple_drift.xy, seed + uint(i));
        slope += (amp / float(i)) * scale * n.yz;
    }
    return slope;
}

#endif
