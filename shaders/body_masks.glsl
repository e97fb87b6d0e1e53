// Which draw owns a fragment's water: a river owns its texels (channel, mouth and
// plume); a lake its mask; the ocean the rest. Needs frame.glsl (the draws).
#ifndef TIDEWATER_BODY_MASKS_GLSL
#define TIDEWATER_BODY_MASKS_GLSL

layout(std430, set = kFrameSet, binding = eFrameBodyMasks) readonly buffer BodyMasks { float body_masks[]; };  // river texel kinds, lake masks

// Draw d's mask texel under `xz` (relative to O): a river's texel kind, a lake's extent
// flag; 0 (kRiverTexelNone) outside its grid.
float body_mask(GpuBodyDraw d, vec2 xz) {
    vec2 uv = (xz - d.grid.xy) / d.grid.z;
    if (any(lessThan(uv, vec2(0.0))) || uv.x >= d.river.x || uv.y >= d.river.y) return kRiverTexelNone;
    uvec2 ij = uvec2(uv);
    return body_masks[uint(d.grid.w) + ij.y * uint(d.river.x) + ij.x];
}

// True where the water at `xz` belongs to draw `self`.
bool owns_water(uint self, vec2 xz) {
    GpuBodyDraw d = draws[self];
    uint kind = uint(d.body.x);
    if (kind == kBodyRiver) return body_mask(d, xz) != kRiverTexelNone;
    uint first = uint(d.rivers.x), count = uint(d.rivers.y);
    for (uint r = first; r < first + count; ++r)
        if (body_mask(draws[r], xz) != kRiverTexelNone) return false;
    return kind != kBodyLake || body_mask(d, xz) > 0.5;
}

#endif
