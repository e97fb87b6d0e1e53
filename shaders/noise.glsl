// Integer-hashed gradient noise shared by the ripples, foam grain and flow detail.
#ifndef TIDEWATER_NOISE_GLSL
#define TIDEWATER_NOISE_GLSL

// Integer-hashed gradient noise: the GLSL twin of tidewater::gradient_noise. The lattice
// repeats every 256 cells (or every `period_mask` + 1, a power of two: the foam's noise
// table tiles): the low bits of a two's complement index are its non-negative remainder
// (GLSL leaves % of a negative operand undefined, and it costs a division).
uint tw_hash_tiled(int ix, int iz, uint seed, uint period_mask) {
    uint x = uint(ix) & period_mask;
    uint z = uint(iz) & period_mask;
    uint h = (x * 0x8da6b343u) ^ (z * 0xd8163841u) ^ (seed * 0xcb1ab31fu);
    h ^= h >> 16; h *= 0x85ebca6bu; h ^= h >> 13; h *= 0xc2b2ae35u; h ^= h >> 16;
    return h;
}
uint tw_hash(int ix, int iz, uint seed) { return tw_hash_tiled(ix, iz, seed, 255u); }
vec2 tw_gradient(uint h) {
    const float d = 0.70710678;
    const vec2 g[8] = vec2[8](vec2(1, 0), vec2(-1, 0), vec2(0, 1), vec2(0, -1), vec2(d, d), vec2(-d, d), vec2(d, -d), vec2(-d, -d));
    return g[h & 7u];
}
// Returns (value, d/dx, d/dz) in lattice units.
vec3 gradient_noise_tiled(vec2 p, uint seed, uint period_mask) {
    vec2 i = floor(p);
    vec2 f = p - i;
    ivec2 c = ivec2(i);
    vec2 g00 = tw_gradient(tw_hash_tiled(c.x, c.y, seed, period_mask)), g10 = tw_gradient(tw_hash_tiled(c.x + 1, c.y, seed, period_mask));
    vec2 g01 = tw_gradient(tw_hash_tiled(c.x, c.y + 1, seed, period_mask)), g11 = tw_gradient(tw_hash_tiled(c.x + 1, c.y + 1, seed, period_mask));
    float n00 = dot(g00, f), n10 = dot(g10, f - vec2(1, 0)), n01 = dot(g01, f - vec2(0, 1)), n11 = dot(g11, f - vec2(1, 1));
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec2 du = 30.0 * f * f * (f - 1.0) * (f - 1.0);
    float nx0 = mix(n00, n10, u.x), nx1 = mix(n01, n11, u.x);
    vec2 gx0 = mix(g00, g10, u.x) + vec2(du.x * (n10 - n00), 0.0);
    vec2 gx1 = mix(g01, g11, u.x) + vec2(du.x * (n11 - n01), 0.0);
    const float scale = 1.4142135;
    return scale * vec3(mix(nx0, nx1, u.y), mix(gx0, gx1, u.y) + vec2(0.0, du.y * (nx1 - nx0)));
}
vec3 gradient_noise(vec2 p, uint seed) { return gradient_noise_tiled(p, seed, 255u); }

// How much of a detail of size `lambda` (m) a pixel of footprint `footprint` (m)
// resolves: all from 4 footprints up, none under 2. Detail a pixel cannot resolve fades
// to its mean (or, for the water's slopes, into their variance: water.frag).
float resolved(float lambda, float footprint) { return smoothstep(2.0 * footprint, 4.0 * footprint, lambda); }

#endif
