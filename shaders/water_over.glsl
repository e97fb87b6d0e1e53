// The water over a point of the ground or of a float: the lake whose mask holds it and
// whose rest level is above it, else the ocean when the point is under the sea's level.
// Its depth under that rest level and its optics light the point (the sun's and the sky's
// light fading with depth, caustics from its own waves). A river's bed is lit as dry
// ground (its surface is not a level; the river's refraction fogs what lies under it).
// Needs frame.glsl, water_medium.glsl and body_masks.glsl.
#ifndef TIDEWATER_WATER_OVER_GLSL
#define TIDEWATER_WATER_OVER_GLSL

struct WaterOver {
    float depth;         // m under the body's rest level; <= 0: no water over the point
    uint draw;           // the body's draw (draws[]): the ocean's 0, or a lake's
    WaterOptics optics;  // the body's
};

WaterOver water_over(vec3 p) {
    // The draws: the ocean and its rings (when the scene has an ocean), the lakes from
    // rivers.z on, then the rivers from rivers.x on (every draw carries both).
    GpuBodyDraw first = draws[0];
    for (uint i = uint(first.rivers.z); i < uint(first.rivers.x); ++i) {
        GpuBodyDraw d = draws[i];
        if (d.body.y <= p.y || !owns_water(i, p.xz)) continue;
        return WaterOver(d.body.y - p.y, i, WaterOptics(d.optics_extinction.xyz, d.optics_color.xyz));
    }
    WaterOptics sea = WaterOptics(first.optics_extinction.xyz, first.optics_color.xyz);
    if (uint(first.body.x) != kBodyOcean) return WaterOver(0.0, 0u, sea);  // no ocean: dry
    return WaterOver(frame.params.x - p.y, 0u, sea);
}

#endif
