// Light through water: Beer–Lambert extinction per colour channel along a path and the
// light the water scatters into it, the sun's light fading with depth, and the surface
// seen from below (Snell's window, total internal reflection outside it). One place for
// the water pass (refraction from above, the surface from below), the terrain, the floats
// and the sky seen from under the surface. Needs frame.glsl.
//
// A body's optics (tidewater::WaterOptics): its extinction per channel (1/m) and the colour
// deep water sends up. Each water draw has its body's (GpuBodyDraw.optics_*); the frame has
// the body over the camera's (GpuFrame.water_*: the ocean's when the camera is above every
// surface), which lights the seabed and fills every path from an eye under the surface.
#ifndef TIDEWATER_WATER_MEDIUM_GLSL
#define TIDEWATER_WATER_MEDIUM_GLSL

// The pixel in its view (the view's rectangle of the host's targets, GpuFrame.view_corner
// and viewport): in pixels from the view's corner, and 0..1 across it, where the view's
// copies of the opaque scene hold what lies behind it.
vec2 view_pixel() { return gl_FragCoord.xy - frame.view_corner.xy; }
vec2 view_uv() { return view_pixel() * frame.viewport.zw; }

struct WaterOptics {
    vec3 extinction;  // 1/m
    vec3 color;       // what deep water sends up toward the sky
};
WaterOptics camera_water() { return WaterOptics(frame.water_extinction.xyz, frame.water_color.xyz); }

// Along a level path under the surface the water scatters more light toward the eye than
// deep water sends up (the sun's light comes from above, scattered forward).
const float kWaterSideLight = 3.0;

// The share of light left after `path` metres of water, per channel.
vec3 water_transmittance(WaterOptics water, float path) { return exp(-water.extinction * path); }

// `color` seen through `path` metres of water that scatters `inscatter` into the path.
vec3 through_water(WaterOptics water, vec3 color, float path, vec3 inscatter) {
    vec3 t = water_transmittance(water, path);
    return color * t + inscatter * (1.0 - t);
}

// How far under the surface the pixel's point on the near plane lies (m, > 0 under), from
// the near plane's corners (frame.near_plane_depths, bilinear across a plane a fraction of
// a metre wide), and how much that changes to the next pixel.
vec2 near_plane_depth() {
    vec2 s = view_uv();
    vec4 d = frame.near_plane_depths;
    float top = mix(d.x, d.y, s.x), bottom = mix(d.w, d.z, s.x);
    float across = (mix(d.y, d.z, s.y) - mix(d.x, d.w, s.y)) * frame.viewport.z;
    float down = (bottom - top) * frame.viewport.w;
    return vec2(mix(top, bottom, s.y), length(vec2(across, down)));
}

// Whether this pixel sees the world from under a body's surface.
bool pixel_under_water() { return frame.underwater.x > 0.5 && near_plane_depth().x > 0.0; }

// The water line on the lens: where the surface crosses the near plane, a thin meniscus
// (a pixel or two, dark) between the view above and the view below.
const vec3 kMeniscusColor = vec3(0.04, 0.07, 0.08);
vec3 with_water_line(vec3 color) {
    if (frame.underwater.x < 0.5) return color;
    vec2 d = near_plane_depth();
    float pixels = abs(d.x) / max(d.y, 1e-9);
    return mix(color, kMeniscusColor, 0.8 * (1.0 - smoothstep(0.5, 1.5, pixels)));
}

// The sun's and the sky's light `depth` metres under the surface, relative to above it:
// the sun's along its slanted path, the sky's straight down.
vec3 sunlight_under_water(WaterOptics water, float depth) { return water_transmittance(water, max(depth, 0.0) / max(frame.sun.y, 0.1)); }
vec3 skylight_under_water(WaterOptics water, float depth) { return water_transmittance(water, max(depth, 0.0)); }
vec3 sunlight_under_water(float depth) { return sunlight_under_water(camera_water(), depth); }
vec3 skylight_under_water(float depth) { return skylight_under_water(camera_water(), depth); }

// What the water scatters toward an eye `depth` metres under the surface: its colour far
// along a level path there.
vec3 water_inscatter(float depth) {
    float sun = frame.sun.w * (0.25 + 0.75 * max(frame.sun.y, 0.0));
    return frame.water_color.xyz * kWaterSideLight * sun * skylight_under_water(depth);
}

// The surface seen from below at a point whose upward normal is `n`, from an eye in the
// direction `v` from it (below the surface): inside Snell's window the world above is seen
// along the transmitted direction, weighted by one minus the Fresnel reflectance from the
// water side; outside it (48.6 degrees from the normal) total internal reflection shows
// the water below.
struct SurfaceFromBelow {
    vec3 transmitted;  // the direction into the air (zero under total internal reflection)
    float reflectance;  // Fresnel reflectance from the water side, unpolarised
};
SurfaceFromBelow surface_from_below(vec3 n, vec3 v) {
    vec3 i = -v;  // from the eye, upward
    float cos_i = clamp(dot(n, i), 1e-4, 1.0);
    float sin_t2 = kWaterRefractiveIndex * kWaterRefractiveIndex * (1.0 - cos_i * cos_i);
    if (sin_t2 >= 1.0) return SurfaceFromBelow(vec3(0.0), 1.0);
    float cos_t = sqrt(1.0 - sin_t2);
    float rs = (kWaterRefractiveIndex * cos_i - cos_t) / (kWaterRefractiveIndex * cos_i + cos_t);
    float rp = (kWaterRefractiveIndex * cos_t - cos_i) / (kWaterRefractiveIndex * cos_t + cos_i);
    return SurfaceFromBelow(refract(i, -n, kWaterRefractiveIndex), 0.5 * (rs * rs + rp * rp));
}

// A point of the opaque scene `height` m high, `distance` m from an eye under a body's
// surface (a pixel_under_water) along unit direction `dir`. Below the surface it is seen
// through the water all the way. Above it, it is seen through the surface, which the water
// pass draws in front wherever its waves are; where they leave a gap (the waterline, the
// horizon) through a level surface: inside Snell's window with the water up to it, and
// outside the window not at all (total internal reflection shows the water below).
vec3 seen_under_water(vec3 color, float height, float distance, vec3 dir) {
    vec3 inscatter = water_inscatter(frame.underwater.y);
    if (height < frame.underwater.z) return through_water(camera_water(), color, distance, inscatter);
    float path = min(frame.underwater.y / max(dir.y, 1e-4), distance);
    if (surface_from_below(vec3(0.0, 1.0, 0.0), -dir).reflectance >= 1.0) color = inscatter;
    return through_water(camera_water(), color, path, inscatter);
}

#endif
