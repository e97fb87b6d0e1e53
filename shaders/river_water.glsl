// A river's water at a rest position: the GLSL twin of RiverWater and PlumeWater in
// runtime/core/src/water/river_water.hpp. The river's waves run in its channel frame
// (k_s downstream, k_n across to the left); at the rest position they turn with the
// downstream tangent there, die out over the last RIVER_BANK_RAMP of water and over
// the still water the river runs into, and ride the falling surface (one more term of
// the sums: its height above the mouth level and its gradient).
//
// The includer declares river_texels[] (kRiverQueryStride floats per texel of this
// river, from RIVER_FIRST_TEXEL), river_channel[] (s, n, flow x, z per texel, from the
// same index) and river_waves[] (GpuRiverWave), and defines RIVER_NX, RIVER_NZ,
// RIVER_TEXEL, RIVER_FIRST_TEXEL, RIVER_FIRST_WAVE, RIVER_WAVE_COUNT and RIVER_BANK_RAMP.
#ifndef TIDEWATER_RIVER_WATER_GLSL
#define TIDEWATER_RIVER_WATER_GLSL

// Bilinear taps of the river's rectangular grid (tidewater::detail::grid_taps).
struct RiverTap {
    uint k00, k10, k01, k11;
    vec4 w;  // weights of k00, k10, k01, k11
    vec2 f;  // the fractions (u, v) in the cell
};

// `rel` is the position relative to the river grid's outer corner, m.
RiverTap river_tap(vec2 rel) {
    int nx = int(RIVER_NX), nz = int(RIVER_NZ);
    vec2 uv = clamp(rel / RIVER_TEXEL - 0.5, vec2(0.0), vec2(float(nx - 1), float(nz - 1)));
    ivec2 ij = min(ivec2(uv), ivec2(max(nx - 2, 0), max(nz - 2, 0)));
    vec2 f = uv - vec2(ij);
    RiverTap t;
    t.k00 = uint(ij.y * nx + ij.x);
    t.k10 = t.k00 + (nx > 1 ? 1u : 0u);
    t.k01 = t.k00 + (nz > 1 ? uint(nx) : 0u);
    t.k11 = t.k01 + (nx > 1 ? 1u : 0u);
    t.w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    t.f = f;
    return t;
}
float river_field(RiverTap t, uint field) {
    uint base = RIVER_FIRST_TEXEL * kRiverQueryStride + field;
    return t.w.x * river_texels[base + t.k00 * kRiverQueryStride] + t.w.y * river_texels[base + t.k10 * kRiverQueryStride] +
           t.w.z * river_texels[base + t.k01 * kRiverQueryStride] + t.w.w * river_texels[base + t.k11 * kRiverQueryStride];
}

// Channel coordinates (s, n, m) and current (m/s) at a tap: the current weighted by the
// texels' water columns too, so that depth times current is the bilinear h u where the
// four are wet (tidewater::detail::sample_river's twin).
vec4 river_channel_at(RiverTap t) {
    uint first = RIVER_FIRST_TEXEL;
    vec4 c00 = river_channel[first + t.k00], c10 = river_channel[first + t.k10];
    vec4 c01 = river_channel[first + t.k01], c11 = river_channel[first + t.k11];
    uint depth = RIVER_FIRST_TEXEL * kRiverQueryStride + kRiverQueryDepth;
    vec4 column = max(vec4(river_texels[depth + t.k00 * kRiverQueryStride], river_texels[depth + t.k10 * kRiverQueryStride],
                           river_texels[depth + t.k01 * kRiverQueryStride], river_texels[depth + t.k11 * kRiverQueryStride]),
                      vec4(0.0));
    vec4 wh = t.w * column;
    float water = wh.x + wh.y + wh.z + wh.w;
    vec2 sn = t.w.x * c00.xy + t.w.y * c10.xy + t.w.z * c01.xy + t.w.w * c11.xy;
    vec2 flow = water > 0.0 ? (wh.x * c00.zw + wh.y * c10.zw + wh.z * c01.zw + wh.w * c11.zw) / water : vec2(0.0);
    return vec4(sn, flow);
}

// A river wave's phase at channel coordinates sn (the CPU's base_phases in the channel
// frame, with the offset reduced on the host).
float river_wave_phase(GpuRiverWave w, vec2 sn) {
    return fma(w.k_amp.x, sn.x, fma(w.k_amp.y, sn.y, w.omega_phase.y));
}

// The still water's share at the last evaluated rest position (PlumeWater's weight).
float g_river_still_weight = 0.0;
// The still water column there, m.
float g_river_depth = 0.0;

// The river's sums at rest position `rel` (m, from the river grid's corner), with rest
// offset `e` from the point whose channel coordinates are `sn` (the point the phases
// are formed at). `lod` fades the waves the mesh and pixel cannot resolve (render LOD;
// queries pass no_wave_lod()).
SurfaceSums river_water_at(vec2 rel, vec2 e, vec2 sn, WaveLod lod) {
    RiverTap t = river_tap(rel);
    uint base = RIVER_FIRST_TEXEL * kRiverQueryStride;
    float surface = river_field(t, kRiverQuerySurface);
    float depth = river_field(t, kRiverQueryDepth);
    vec2 tangent = vec2(river_field(t, kRiverQueryTangentX), river_field(t, kRiverQueryTangentZ));
    float weight = river_field(t, kRiverQueryWaveWeight);
    g_river_still_weight = river_field(t, kRiverQueryStillWeight);
    g_river_depth = depth;
    // The surface's gradient: the bilinear form's derivatives in the cell.
    float s00 = river_texels[base + t.k00 * kRiverQueryStride], s10 = river_texels[base + t.k10 * kRiverQueryStride];
    float s01 = river_texels[base + t.k01 * kRiverQueryStride], s11 = river_texels[base + t.k11 * kRiverQueryStride];
    vec2 surface_slope = vec2((1.0 - t.f.y) * (s10 - s00) + t.f.y * (s11 - s01), (1.0 - t.f.x) * (s01 - s00) + t.f.x * (s11 - s10)) / RIVER_TEXEL;

    float len2 = dot(tangent, tangent);
    tangent *= inversesqrt(len2 > 0.0 ? len2 : 1.0);
    vec2 left = vec2(-tangent.y, tangent.x);
    float depth_ramp = depth > 0.0 ? (depth < RIVER_BANK_RAMP ? depth / RIVER_BANK_RAMP : 1.0) : 0.0;
    float ramp = depth_ramp * weight;
    SurfaceSums s = surface_zero();
    for (uint i = 0u; i < RIVER_WAVE_COUNT; ++i) {
        GpuRiverWave w = river_waves[RIVER_FIRST_WAVE + i];
        vec2 kvec = w.k_amp.x * tangent + w.k_amp.y * left;
        float theta = fma(kvec.x, e.x, fma(kvec.y, e.y, river_wave_phase(w, sn)));
        float a = w.k_amp.z * ramp;
        vec2 shares = a > 0.0 ? wave_lod_shares(kvec, lod) : vec2(1.0);
        add_wave_compressing(s, kvec, a * shares.x, w.k_amp.w, w.omega_phase.x, theta, shares.y);
    }
    s.eta += surface;
    s.slope += surface_slope;
    return s;
}

// s += w * b: another water's sums, scaled (tidewater::detail::add_scaled).
void add_scaled(inout SurfaceSums s, SurfaceSums b, float w) {
    s.disp += w * b.disp;
    s.m += w * b.m;
    s.eta += w * b.eta;
    s.slope += w * b.slope;
    s.velocity += w * b.velocity;
}

#endif
