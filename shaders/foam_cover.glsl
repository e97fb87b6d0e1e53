// How a pixel's foam amount whitens it (water.frag): a lace that rides the water and
// is filtered by the pixel's footprint.
#ifndef TIDEWATER_FOAM_COVER_GLSL
#define TIDEWATER_FOAM_COVER_GLSL
#include "noise.glsl"

// Foam lace: 0 on the borders of its cells (where bubbles gather between the holes
// that open in decaying foam), rising to 1 at their centres (F2 - F1 of a cellular noise).
float foam_lace(vec2 p) {
    vec2 cell = floor(p), f = p - cell;
    float f1 = 8.0, f2 = 8.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            uint h = tw_hash(int(cell.x) + i, int(cell.y) + j, 53u);
            vec2 site = vec2(i, j) + vec2(float(h & 0xffffu), float(h >> 16)) / 65535.0;
            float dist = length(site - f);
            if (dist < f1) { f2 = f1; f1 = dist; } else if (dist < f2) f2 = dist;
        }
    return clamp((f2 - f1) * 1.6, 0.0, 1.0);
}

// The foam's four noises at lattice point q (they tile every kFoamNoiseCells cells).
vec4 foam_noise_at(vec2 q) { return textureLod(foam_noise, q / float(kFoamNoiseCells), 0.0); }

// How much of the pixel foam of amount `foam` (0..1) whitens. Fresh foam (near 1) is
// solid; thinner foam opens into lace (foam_lace, broken up by a finer gradient noise)
// that rides the water (rest coordinates move with the particles). Where the pixel
// cannot resolve the lace its edge widens to the whole range and the cover becomes a
// smooth function of `foam` alone (smoothstep(foam)): no sparkle far away, though thin
// distant foam shows less than its area share.
float foam_cover(float foam, vec2 xz, float footprint) {
    float broad = resolved(8.0, footprint), coarse = resolved(2.7, footprint), fine = resolved(0.7, footprint);
    // Warped so that the cells vary in size and shape; patches 8 m across stay solid or open.
    // Lace cells of 2.7 m. Every scale here repeats a whole number of times in 2048 m (the
    // lace every 256 cells, the table every kFoamNoiseCells): the origin enters xz reduced
    // modulo 2048 m (frame.origin_mod) and the foam stays continuous when it wraps.
    vec2 p = xz * 0.375;
    // The gradient noises from the foam's noise table (foam_noise.frag), at their lattice scales.
    vec2 warp = foam_noise_at(p * 0.5).xy;
    float n = 0.5 + broad * 0.3 * foam_noise_at(xz * 0.125).z +
              coarse * (0.6 * (foam_lace(p + 0.7 * warp) - 0.5) + 0.2 * fine * foam_noise_at(xz * 1.40625).w);
    float edge = mix(0.5, 0.1, coarse);
    // Thin lace lets some of the water through.
    return smoothstep(0.0, 1.0, (foam - n) / (2.0 * edge) + 0.5) * mix(0.75, 1.0, foam);
}
#endif
