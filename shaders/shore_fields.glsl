// Sampling the shore fields (tidewater::ShoreWaves) exactly as the CPU does:
// bilinear between texel centres, clamped at the edges. The including shader
// declares the buffers `shore_waves` ([wave * texels + texel]: residual phase,
// amplitude factor, wavevector x, z) and `shore_shared` ([texel]: depth,
// breaking, steepness scale, shore distance), and defines SHORE_RESOLUTION and
// SHORE_TEXEL; it may define SHORE_WAVE_BASE and SHORE_SHARED_BASE, where the model
// starts in those buffers when they hold several (default 0).
#ifndef TIDEWATER_SHORE_FIELDS_GLSL
#define TIDEWATER_SHORE_FIELDS_GLSL
#ifndef SHORE_WAVE_BASE
#define SHORE_WAVE_BASE 0u
#endif
#ifndef SHORE_SHARED_BASE
#define SHORE_SHARED_BASE 0u
#endif

struct ShoreTap {
    uint k00, k10, k01, k11;
    vec4 w;
};

// `rel` is the position relative to the shore grid's outer corner, m.
ShoreTap shore_tap(vec2 rel) {
    int n = int(SHORE_RESOLUTION);
    vec2 uv = clamp(rel / SHORE_TEXEL - 0.5, vec2(0.0), vec2(float(n - 1)));
    ivec2 ij = min(ivec2(uv), ivec2(n - 2));
    vec2 f = uv - vec2(ij);
    ShoreTap t;
    t.k00 = uint(ij.y * n + ij.x);
    t.k10 = t.k00 + 1u;
    t.k01 = t.k00 + uint(n);
    t.k11 = t.k01 + 1u;
    t.w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    return t;
}
vec4 tap_waves(ShoreTap t, uint wave_offset) {
    uint base = SHORE_WAVE_BASE + wave_offset;
    return t.w.x * shore_waves[base + t.k00] + t.w.y * shore_waves[base + t.k10] + t.w.z * shore_waves[base + t.k01] +
           t.w.w * shore_waves[base + t.k11];
}
vec4 tap_shared(ShoreTap t) {
    uint base = SHORE_SHARED_BASE;
    return t.w.x * shore_shared[base + t.k00] + t.w.y * shore_shared[base + t.k10] + t.w.z * shore_shared[base + t.k01] +
           t.w.w * shore_shared[base + t.k11];
}

#endif
