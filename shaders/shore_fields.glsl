// Sampling the shore fields (tidewater::ShoreWaves) exactly as the CPU does:
// bilinear between texel centres, clamped at the edges, from the slot that holds the
// cell's tile (tidewater::ShoreTiles; kShoreTileTexels in host_device.h), on each
// layer's own grid. The including shader declares the buffers `shore_pages` ([tile]:
// its slot, grid after grid), `shore_waves` (a run's [base + (slot * run waves + wave) *
// kShoreSlotTexels + texel]: residual phase, amplitude factor, wavevector x, z),
// `shore_shared` ([base + slot * kShoreSlotTexels + texel]: depth, breaking, steepness
// scale, shore distance) and `shore_layers` (GpuShoreLayer: the model's shared fields'
// record, then each run's); it may define SHORE_LAYER_BASE, the model's first record
// when the buffers hold several models (default 0).
#ifndef TIDEWATER_SHORE_FIELDS_GLSL
#define TIDEWATER_SHORE_FIELDS_GLSL
#ifndef SHORE_LAYER_BASE
#define SHORE_LAYER_BASE 0u
#endif

struct ShoreTap {
    uint slot;  // the slot holding the cell's tile
    uint base;  // the first element of the grid's slot 0
    uint k00;   // the first tap's texel in its slot; the others at +1, +kShoreSlotSide, +kShoreSlotSide + 1
    vec4 w;
};

// `rel` is the position relative to the model's shared grid's outer corner, m; `grid` as
// GpuShoreLayer::grid, its pages from `page_base` in shore_pages, its slots from `base`.
ShoreTap shore_grid_tap(vec2 rel, vec4 grid, uint page_base, uint base) {
    int n = int(grid.w);
    vec2 uv = clamp((rel - grid.xy) / grid.z - 0.5, vec2(0.0), vec2(float(n - 1)));
    ivec2 ij = min(ivec2(uv), ivec2(n - 2));
    vec2 f = uv - vec2(ij);
    int tiles = (n + int(kShoreTileTexels) - 1) / int(kShoreTileTexels);
    ivec2 tile = ij / int(kShoreTileTexels);
    ivec2 local = ij - tile * int(kShoreTileTexels);
    ShoreTap t;
    t.slot = shore_pages[page_base + uint(tile.y * tiles + tile.x)];
    t.base = base;
    t.k00 = uint(local.y) * kShoreSlotSide + uint(local.x);
    t.w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    return t;
}
// Layer `l`'s tap; `rel` from the shared grid's outer corner, m. A tile streamed out is
// read from the layer's coarse grid, which is always resident.
ShoreTap shore_layer_tap(GpuShoreLayer l, vec2 rel) {
    ShoreTap t = shore_grid_tap(rel, l.grid, l.waves.z, l.waves.w);
    if (t.slot == kShoreNotResident) t = shore_grid_tap(rel, l.coarse_grid, l.coarse.x, l.coarse.y);
    return t;
}
// The shared fields' tap; `rel` from their grid's outer corner, m.
ShoreTap shore_tap(vec2 rel) {
    return shore_layer_tap(shore_layers[SHORE_LAYER_BASE], rel);
}
// Run `layer`'s record.
GpuShoreLayer shore_layer(uint layer) {
    return shore_layers[SHORE_LAYER_BASE + 1u + layer];
}
// Wave `wave` of run `l` (its index within the run).
vec4 tap_waves(ShoreTap t, GpuShoreLayer l, uint wave) {
    uint k = t.base + (t.slot * l.waves.y + wave) * kShoreSlotTexels + t.k00;
    return t.w.x * shore_waves[k] + t.w.y * shore_waves[k + 1u] + t.w.z * shore_waves[k + kShoreSlotSide] +
           t.w.w * shore_waves[k + kShoreSlotSide + 1u];
}
vec4 tap_shared(ShoreTap t) {
    uint k = t.base + t.slot * kShoreSlotTexels + t.k00;
    return t.w.x * shore_shared[k] + t.w.y * shore_shared[k + 1u] + t.w.z * shore_shared[k + kShoreSlotSide] +
           t.w.w * shore_shared[k + kShoreSlotSide + 1u];
}

#endif
