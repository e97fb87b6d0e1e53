// A water body's waves at a rest position (GLSL twin of the providers in
// runtime/core/src/water/: open sea, and the shore fields that reshape each wave).
// The includer declares waves[] (GpuWave), the shore buffers of shore_fields.glsl,
// and defines WAVE_COUNT and WAVE_BASE_PHASE(i): wave i's phase at its origin; it may
// define WAVE_FIRST, the body's first wave in waves[] (default 0), and WAVE_DRAWN(w),
// whether it sums GpuWave w (default: every wave).
#ifndef TIDEWATER_WATER_BODY_GLSL
#define TIDEWATER_WATER_BODY_GLSL
#ifndef WAVE_FIRST
#define WAVE_FIRST 0u
#endif
#ifndef WAVE_DRAWN
#define WAVE_DRAWN(w) true
#endif

// The shared shore fields of open water: deep, no breaking, full steepness, no shore
// (what the shore model's open-sea slot holds).
const vec4 kOpenWaterShore = vec4(kShoreFarValue, 0.0, 1.0, kShoreFarValue);

// What the shore fields hold at the last evaluated position: depth (m), breaking,
// steepness scale, shore distance (m).
vec4 g_shore_fields = kOpenWaterShore;

// With g_track_lags set, water_at also sums the waves' earlier compression at the
// position into g_lagged (LaggedCompression; the foam particles remember).
bool g_track_lags = false;
LaggedCompression g_lagged;

// With g_track_curvature set, water_at also sums the surface's curvature at the position
// into g_curvature: the Hessian of eta = sum A sin(theta), (xx, xz, zz) = -sum A sin(theta)
// (Kx Kx, Kx Kz, Kz Kz) (caustics.glsl), each wave weighted by how much of it a footprint
// of g_curvature_footprint m keeps (pixel_keeps' isotropic Gaussian).
bool g_track_curvature = false;
vec3 g_curvature;
float g_curvature_footprint = 0.0;

// The sums at a rest position `rel` (m, from the phase origin) that lies at `shore_rel`
// from the shore grid's corner. `lod` fades the waves the mesh and pixel there cannot
// resolve (render LOD; queries pass no_wave_lod()).
SurfaceSums water_at(vec2 rel, vec2 shore_rel, bool shore, WaveLod lod) {
    SurfaceSums s = surface_zero();
    g_shore_fields = kOpenWaterShore;
    g_lagged = lagged_zero();
    g_curvature = vec3(0.0);
    if (shore) g_shore_fields = tap_shared(shore_tap(shore_rel));
    // The runs of waves in order: the next one's tap is taken where its first wave comes.
    ShoreTap tap;
    GpuShoreLayer layer;
    uint next_layer = 0u, layer_end = 0u;
    for (uint i = 0u; i < WAVE_COUNT; ++i) {
        GpuWave w = waves[WAVE_FIRST + i];
        vec2 kvec = w.dir_k_amp.xy * w.dir_k_amp.z;
        // The same association as the CPU: base + kz z + kx x (fma order).
        float theta = fma(kvec.x, rel.x, fma(kvec.y, rel.y, WAVE_BASE_PHASE(i)));
        float a = w.dir_k_amp.w;
        float q = w.steep_omega.x;
        if (shore) {
            // The wave as the shore shapes it: marched phase, local wavevector, shoaled amplitude.
            // A run of the shore model starts at its first wave, drawn or not.
            if (i == layer_end) {
                layer = shore_layer(next_layer++);
                tap = shore_layer_tap(layer, shore_rel);
                layer_end = layer.waves.x + layer.waves.y;
            }
            if (!WAVE_DRAWN(w)) continue;
            vec4 local = tap_waves(tap, layer, i - layer.waves.x);
            theta += local.x;
            kvec = local.zw;
            // Over the last texel of water (host_device.h): zero on land.
            a *= local.y * (g_shore_fields.x > 0.0 ? clamp(g_shore_fields.w / shore_layers[SHORE_LAYER_BASE].grid.z, 0.0, 1.0) : 0.0);
            q *= g_shore_fields.z;
        } else if (!WAVE_DRAWN(w)) {
            continue;
        }
        vec2 shares = a > 0.0 ? wave_lod_shares(kvec, lod) : vec2(1.0);
        a *= shares.x;
        add_wave_compressing(s, kvec, a, q, w.steep_omega.y, theta, shares.y);
        if (g_track_lags) add_wave_lags(g_lagged, kvec, a * shares.y, q, w.lag_turn.xy, theta);
        if (g_track_curvature) {
            float f = g_curvature_footprint;
            float kept = pixel_keeps(kvec, WaveLod(0.0, 0.0, vec2(1.0, 0.0), f, f));
            g_curvature -= kept * a * sin(theta) * vec3(kvec.x * kvec.x, kvec.x * kvec.y, kvec.y * kvec.y);
        }
    }
    return s;
}

#endif
