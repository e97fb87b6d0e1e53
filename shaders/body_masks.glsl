// Which draw owns a fragment's water: a river owns its texels (channel, mouth and
// plume); a lake its mask; the ocean the rest. Needs water_draw.glsl and river_water.glsl.
#ifndef TIDEWATER_BODY_MASKS_GLSL
#define TIDEWATER_BODY_MASKS_GLSL

// The kind of the river texel under `xz` (relative to O) for draw d; kRiverTexelNone outside its grid.
float river_texel_kind(GpuBodyDraw d, vec2 xz) {
    vec2 uv = (xz - d.grid.xy) / d.grid.z;
    if (any(lessThan(uv, vec2(0.0))) || uv.x >= d.river.x || uv.y >= d.river.y) return kRiverTexelNone;
    uvec2 ij = uvec2(uv);
    return body_masks[uint(d.grid.w) + ij.y * uint(d.river.x) + ij.x];
}

// True where the water at `xz` belongs to draw `self`.
bool owns_water(uint self, vec2 xz) {
    GpuBodyDraw d = draws[self];
    uint kind = uint(d.body.x);
    if (kind == kBodyRiver) return river_texel_kind(d, xz) != kRiverTexelNone;
    uint first = uint(d.rivers.x), count = uint(d.rivers.y);
    for (uint r = first; r < first + count; ++r)
        if (river_texel_kind(draws[r], xz) != kRiverTexelNone) return false;
    if (kind == kBodyLake) {
        vec2 uv = (xz - d.grid.xy) / d.grid.z;
        if (any(lessThan(uv, vec2(0.0))) || uv.x >= d.river.x || uv.y >= d.river.y) return false;
        uvec2 ij = uvec2(uv);
        return body_masks[uint(d.grid.w) + ij.y * uint(d.river.x) + ij.x] > 0.5;
    }
    return true;
}

#endif
