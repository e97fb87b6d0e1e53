// Sampling the shore fields (tidewater::ShoreWaves) exactly as the CPU does:
// bilinear between texel centres, clamped at the edges, from the slot that holds the
// cell's tile (tidewater::ShoreTiles; kShoreTileTexels in host_device.h), on each
// layer's own grid. The including shader declares the buffers `shore_pages` ([tile]:
// its slot, grid after grid), `shore_waves` (a run's [(slot * run waves + wave) *
// kShoreSlotTexels + texel]: residual phase, amplitude factor, wavevector x, z),
// `shore_shared` ([slot * kShoreSlotTexels + texel]: depth, breaking, steepness scale,
// shore distance) and `shore_layers` (GpuShoreLayer: each run of waves' grid and where
// its pages and slots start), and defines SHORE_RESOLUTION and SHORE_TEXEL (the shared
// grid's); it may define SHORE_LAYER_BASE, SHORE_SHARED_BASE and SHORE_PAGE_BASE, where
// the model starts in those buffers when they hold several (default 0).
#ifndef TIDEWATER_SHORE_FIELDS_GLSL
#define TIDEWATER_SHORE_FIELDS_GLSL
#ifndef SHORE_PAGE_BASE
#define SHORE_PAGE_BASE 0u
#endif
#ifndef SHORE_LAYER_BASE
#define SHORE_LAYER_BASE 0u
#endif
#ifndef SHORE_SHARED_BASE
#define SHORE_SHARED_BASE 0u
#endif

struct ShoreTap {
    uint slot;  // the slot holding the cell's tile
    uint k00;   // the first tap's texel in its slot; the others at +1, +kShoreSlotSide, +kShoreSlotSide + 1
    vec4 w;
};

// `rel` is the position relative to the grid's outer corner, m; the grid has `n` texels of
// `texel` m a side, its pages from `page_base` in shore_pages.
ShoreTap shore_grid_tap(vec2 rel, int n, float texel, uint page_base) {
    vec2 uv = clamp(rel / texel - 0.5, vec2(0.0), vec2(float(n - 1)));
    ivec2 ij = min(ivec2(uv), ivec2(n - 2));
    vec2 f = uv - vec2(ij);
    int tiles = (n + int(kShoreTileTexels) - 1) / int(kShoreTileTexels);
    ivec2 tile = ij / int(kShoreTileTexels);
    ivec2 local = ij - tile * int(kShoreTileTexels);
    ShoreTap t;
    t.slot = shore_pages[page_base + uint(tile.y * tiles + tile.x)];
    t.k00 = uint(local.y) * kShoreSlotSide + uint(local.x);
    t.w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    return t;
}
// The shared grid's tap; `rel` from its outer corner, m.
ShoreTap shore_tap(vec2 rel) {
    return shore_grid_tap(rel, int(SHORE_RESOLUTION), SHORE_TEXEL, SHORE_PAGE_BASE);
}
// Run `layer`'s record and its tap; `rel` from the shared grid's outer corner, m.
GpuShoreLayer shore_layer(uint layer) {
    return shore_layers[SHORE_LAYER_BASE + layer];
}
ShoreTap shore_layer_tap(GpuShoreLayer l, vec2 rel) {
    return shore_grid_tap(rel - l.grid.xy, int(l.grid.w), l.grid.z, l.waves.z);
}
// Wave `wave` of run `l` (its index within the run).
vec4 tap_waves(ShoreTap t, GpuShoreLayer l, uint wave) {
    uint k = l.waves.w + (t.slot * l.waves.y + wave) * kShoreSlotTexels + t.k00;
    return t.w.x * shore_waves[k] + t.w.y * shore_waves[k + 1u] + t.w.z * shore_waves[k + kShoreSlotSide] +
           t.w.w * shore_waves[k + kShoreSlotSide + 1u];
}
vec4 tap_shared(ShoreTap t) {
    uint k = SHORE_SHARED_BASE + t.slot * kShoreSlotTexels + t.k00;
    return t.w.x * shore_shared[k] + t.w.y * shore_shared[k + 1u] + t.w.z * shore_shared[k + kShoreSlotSide] +
           t.w.w * shore_shared[k + kShoreSlotSide + 1u];
}

#endif
