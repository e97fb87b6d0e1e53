// Flow-mapped detail: the GLSL twin of tidewater::flow_detail
// (runtime/core/src/flow_detail.cpp). Two layers of gradient noise advected by the
// current with sawtooth progress, triangle weights that sum to one, a UV jump per
// cycle and a per-texel time offset; blended as (wA A + wB B) / sqrt(wA^2 + wB^2) so
// the contrast does not pulse. Needs gradient_noise (frame.glsl or the includer).
#ifndef TIDEWATER_FLOW_DETAIL_GLSL
#define TIDEWATER_FLOW_DETAIL_GLSL

// The blended detail slope at `rel` (m, from the zero whose reduced world position is
// d.origin.xy) in a current `flow` (m/s).
vec2 flow_detail_slope(vec2 rel, vec2 flow, GpuFlowDetail d) {
    vec2 p = rel + d.origin.xy;
    float tiling = d.params.x, speed = d.params.y, strength = d.params.z, offset = d.params.w;
    float period = d.clock.x;
    uint seed = uint(d.jump.z);
    float stagger = clamp(0.5 + 0.5 * gradient_noise(p * (tiling * kFlowOffsetScale), seed + kFlowStaggerSeed).x, 0.0, 1.0);
    vec2 slope = vec2(0.0);
    float weights2 = 0.0;
    for (int layer = 0; layer < 2; ++layer) {
        float c = d.clock.y + stagger + 0.5 * float(layer);
        float restarts = floor(c);
        float progress = c - restarts;
        float w = 1.0 - abs(1.0 - 2.0 * progress);
        vec2 travelled = flow * (speed * period * (progress + offset));
        vec2 uv = (p - travelled) * tiling + d.jump.xy + restarts * d.clock.zw + vec2(0.5 * float(layer));
        slope += w * gradient_noise(uv, seed + uint(layer)).yz * (tiling * strength);
        weights2 += w * w;
    }
    return slope * inversesqrt(weights2);
}

#endif
