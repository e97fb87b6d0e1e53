// Caustics: the sun's light on ground under the ocean or a lake, focused and spread by the
// waves over it: the same waves, shore model and ripples the water pass draws. Light refracted by a
// surface of height eta(x) reaches a depth h at x + D grad(eta) (small slopes), D = h' (1 -
// 1/n) with h' the refracted sun's path down to that depth; the light per unit area there
// is 1 / |det(I + D H)|, H the surface's Hessian, taken where that light entered (first
// order in the displacement). Waves a pixel's footprint on the ground cannot resolve leave
// their mean, 1. Needs frame.glsl, water_quality.glsl and water_medium.glsl; defines what water_body.glsl asks
// of its includer (the ocean draw's waves and shore model), so it goes in shaders that
// draw no water.
#ifndef TIDEWATER_CAUSTICS_GLSL
#define TIDEWATER_CAUSTICS_GLSL

uint g_wave_first = 0u, g_wave_count = 0u;
GpuBodyDraw g_caustic_draw;  // the ocean's or the lake's over the point
#define SHORE_LAYER_BASE g_caustic_draw.shore_base.x
#define WAVE_FIRST g_wave_first
#define WAVE_COUNT g_wave_count
#define WAVE_BASE_PHASE(i) waves[WAVE_FIRST + (i)].steep_omega.z
#define WAVE_DRAWN(w) caustic_wave_matters(w)

// A wave whose curvature can change the gain by less than this is not summed.
const float kCausticNegligible = 0.01;
// The ground's depth, D (below) and the pixel's footprint for the point being lit.
float g_caustic_depth = 1.0, g_caustic_reach = 0.0, g_caustic_footprint = 0.0;
// Whether wave w may matter to the gain: D A k^2, its wavenumber grown to shallow water's
// (at most sqrt(g / h) / omega times the deep one) and its amplitude doubled by shoaling,
// and a pixel's footprint resolving it (pixel_keeps above 1e-4 at its deep wavenumber).
bool caustic_wave_matters(GpuWave w) {
    float grow = max(1.0, sqrt(kGravityAcceleration / g_caustic_depth) / max(w.steep_omega.y, 1e-3));
    float k = w.dir_k_amp.z * grow;
    return 2.0 * w.dir_k_amp.w * k * k * g_caustic_reach > kCausticNegligible &&
           w.dir_k_amp.z * g_caustic_footprint < 15.0;
}
#include "shore_fields.glsl"
#include "water_point.glsl"
#include "water_body.glsl"

// Focusing is kept finite at the focal lines (a pixel spans them) and the gain bounded.
const float kCausticMinDeterminant = 0.2;

// Where the sun's light the water leaves is under this share in every channel, its focus
// does not show: the gain is left at 1.
const float kCausticFaintLight = 0.02;

// The gain of the sun's light on ground at `p` (relative to O) `depth` m under the rest
// level of the body drawn by `draw` (the ocean's or a lake's, water_over.glsl), through
// `optics`, whose pixel covers `footprint` m: 1 in calm water, without such a body, and
// where the water leaves too little of the sun's light to show it.
float caustic_gain(vec3 p, float depth, float footprint, uint draw, WaterOptics optics) {
    if (!kCaustics || depth <= 0.0 || frame.sun.y <= 0.0) return 1.0;
    vec3 sun_left = sunlight_under_water(optics, depth);
    if (max(sun_left.r, max(sun_left.g, sun_left.b)) < kCausticFaintLight) return 1.0;
    g_caustic_draw = draws[draw];
    uint kind = uint(g_caustic_draw.body.x);
    if (kind != kBodyOcean && kind != kBodyLake) return 1.0;
    g_wave_first = uint(g_caustic_draw.body.z);
    g_wave_count = uint(g_caustic_draw.body.w);
    // The refracted sun's path down to the ground, and where it entered the water.
    vec3 t = refract(-frame.sun.xyz, vec3(0.0, 1.0, 0.0), 1.0 / kWaterRefractiveIndex);
    float path = depth / max(-t.y, 0.1);
    vec2 entry = p.xz - t.xz * path;
    float d = path * (1.0 - 1.0 / kWaterRefractiveIndex);
    g_caustic_depth = depth;
    g_caustic_reach = d;
    g_caustic_footprint = footprint;
    g_track_curvature = true;
    g_curvature_footprint = footprint;
    water_at(entry, entry - g_caustic_draw.shore.xy, g_caustic_draw.shore.w > 0.0, no_wave_lod());
    g_track_curvature = false;
    vec3 h = g_curvature;
    // The ripples' curvature from their slope's differences over an eighth of their wavelength.
    vec4 ripple = g_caustic_draw.ripple;
    float ripples_seen = resolved(1.0 / ripple.y, footprint);
    if (ripple.x > 0.0 && ripples_seen > 0.0) {
        float step = 0.125 / ripple.y;
        vec2 s0 = ripple_slope(entry, ripple, g_caustic_draw.ripple_offset);
        vec2 sx = ripple_slope(entry + vec2(step, 0.0), ripple, g_caustic_draw.ripple_offset);
        vec2 sz = ripple_slope(entry + vec2(0.0, step), ripple, g_caustic_draw.ripple_offset);
        h += ripples_seen * vec3(sx.x - s0.x, 0.5 * (sx.y - s0.y + sz.x - s0.x), sz.y - s0.y) / step;
    }
    float det = (1.0 + d * h.x) * (1.0 + d * h.z) - d * d * h.y * h.y;
    return 1.0 / max(abs(det), kCausticMinDeterminant);
}

#endif
