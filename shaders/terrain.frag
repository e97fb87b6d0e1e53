#version 450
// Terrain shading: materials by height, slope and wetness (sand, wet sand where the
// swash runs, grass, rock on steep ground), detail normals and albedo variation that
// fade out where a pixel cannot resolve them, caustics on submerged ground from the
// ocean's waves (caustics.glsl), light that fades with depth under the water, and the
// same fog as the water (through the water from under its surface). Lighting is a plain Lambert sun plus sky
// ambient: a host with its own lighting replaces this shader (docs/embedding.md).
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_quality.glsl"
#include "water_medium.glsl"
#include "caustics.glsl"
#include "clip_volumes.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 0) out vec4 out_color;

// Three octaves of gradient noise (40 m, 9 m, 2 m), each faded to its mean where
// unresolved: x the value (about -1..1), yz its slope per metre (for detail normals).
vec3 ground_detail(vec2 xz, float footprint) {
    vec3 sum = vec3(0.0);
    float size = 40.0, weight = 0.55;
    for (int o = 0; o < 3; ++o) {
        vec3 n = gradient_noise(xz / size, 71u + uint(o));
        sum += resolved(size, footprint) * weight * vec3(n.x, n.yz / size);
        size *= 0.22;
        weight *= 0.45;
    }
    return sum;
}

void main() {
    float h = world_pos.y;
    float level = frame.params.x;
    uint view = uint(frame.params.w);
    vec3 to_camera = frame.camera.xyz - world_pos;
    float distance = length(to_camera);
    vec3 v = to_camera / distance;
    // The ground's normal from the height texture over about a pixel's footprint: every
    // texel's detail near by, whatever the mesh's level, and no aliasing far away.
    vec3 geo_n = terrain_normal_at(world_pos.xz, distance / frame.params.z);
    // The pixel's footprint on the ground (distance / projection scale across the view,
    // see GpuFrame.params), stretched at grazing angles.
    float footprint = distance / frame.params.z / max(abs(dot(v, geo_n)), 0.1);
    // Under the water the sun's light through the waves is focused and spread: caustics
    // (first, while little else is live).
    // Ground inside a clip volume is dry.
    float depth = inside_clip_volumes(world_pos) ? 0.0 : level - h;
    float focus = depth > 0.0 ? caustic_gain(world_pos, depth, footprint) : 1.0;
    vec2 xz = world_pos.xz + frame.origin_mod.xy;
    vec3 detail = ground_detail(xz, footprint);
    float slope = 1.0 - geo_n.y;

    // Materials. Boundaries wander with the broad noise so no contour line shows.
    vec3 sand = vec3(0.80, 0.72, 0.52) * (1.0 + 0.12 * detail.x);
    vec3 wet_sand = vec3(0.56, 0.49, 0.36);
    vec3 grass = mix(vec3(0.26, 0.44, 0.16), vec3(0.42, 0.47, 0.22), 0.5 + 0.5 * detail.x);  // lush to dry
    vec3 rock = vec3(0.44, 0.42, 0.40) * (1.0 + 0.25 * detail.x);
    float rise = h - level;
    vec3 base = mix(sand, grass, smoothstep(2.0, 6.0, rise + 2.5 * detail.x));
    // Rock where the ground is steep: cliffs, with horizontal strata.
    float rockiness = smoothstep(0.2, 0.34, slope + 0.08 * detail.x);
    float strata = 0.85 + 0.15 * sin(h * 2.1 + 3.0 * detail.x) * resolved(3.0, footprint);
    base = mix(base, rock * strata, rockiness);

    // Wet sand: soaked up to the swash's run-up R, drying over the next R/2, and a wet
    // film under the swash, whose top moves with the waves' period (the phase wanders
    // along the coast).
    float runup = frame.options.z;
    float swash_phase = frame.options.w * frame.camera.w - 6.2831 * gradient_noise(xz / 60.0, 79u).x;
    float swash_top = runup * (0.55 + 0.45 * sin(swash_phase));
    float soaked = runup > 0.0 ? smoothstep(1.5 * runup, runup, rise) : 0.0;
    float film = runup > 0.0 ? smoothstep(swash_top + 0.1 * runup, swash_top - 0.1 * runup, rise) : 0.0;
    float wetness = max(0.7 * soaked, film) * (1.0 - rockiness) * smoothstep(-1.5, -0.5, rise);
    base = mix(base, wet_sand, wetness);

    // Detail normals: the noise's slope tilts the mesh normal (faded where unresolved).
    vec3 n = normalize(geo_n - vec3(detail.y, 0.0, detail.z) * mix(1.0, 2.5, rockiness));
    float diffuse = max(dot(n, frame.sun.xyz), 0.0);
    float sky_light = 0.5 + 0.5 * n.y;
    // Under the water the sun's and the sky's light fade with depth (water_medium.glsl).
    vec3 sun_lit = depth > 0.0 ? sunlight_under_water(depth) : vec3(1.0);
    vec3 sky_lit = depth > 0.0 ? skylight_under_water(depth) : vec3(1.0);
    vec3 color = base * ((0.22 + 0.18 * sky_light) * sky_lit + 0.75 * diffuse * sun_lit * focus);
    // A wet film on the ground the swash leaves bare reflects the sky and the sun (not
    // on ground under the water, which the water's own surface covers).
    film *= smoothstep(-1.5, -0.5, rise);
    if (film > 0.0) {
        vec3 r = reflect(-v, n);
        r.y = abs(r.y);
        float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
        color = mix(color, sky_seen(r), film * fresnel * 0.8);
    }
    if (view == kViewHeight) color = heat_color((h - level + 40.0) / 80.0);
    if (view == kViewDepth) color = depth > 0.0 ? heat_color(depth / 40.0) : vec3(0.2);
    if (view == kViewNormals) color = geo_n * 0.5 + 0.5;
    if (view == kViewWireframe) color = vec3(0.1, 0.25, 0.08);
    if (view == kViewShaded)
        color = pixel_under_water() ? seen_under_water(color, h, distance, -v) : apply_fog(color, distance, -v);
    out_color = target_color(with_water_line(color));
}
