#version 450
// Terrain shading: the ground's material (terrain_material.glsl), caustics on submerged
// ground from the waves of the ocean or lake over it (caustics.glsl, water_over.glsl),
// light that fades with depth under that water, a wet film where the swash runs, and the same fog as the water (through the
// water from under its surface). Lighting is a plain Lambert sun plus sky ambient: a host
// with its own lighting replaces this shader (docs/embedding.md).
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_quality.glsl"
#include "water_medium.glsl"
#include "caustics.glsl"
#include "body_masks.glsl"
#include "water_over.glsl"
#include "clip_volumes.glsl"
#include "terrain_material.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 0) out vec4 out_color;

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
    // Under the water (not inside a clip volume, which is dry) the sun's light through the
    // waves is focused and spread: caustics (first, while little else is live).
    WaterOver water = water_over(world_pos);
    float depth = inside_clip_volumes(world_pos) ? 0.0 : water.depth;
    float focus = depth > 0.0 ? caustic_gain(world_pos, depth, footprint, water.draw, water.optics) : 1.0;
    TerrainMaterial m = terrain_material(world_pos, geo_n, footprint);
    vec3 n = m.n;
    // Under the water the sun's and the sky's light fade with depth (water_medium.glsl).
    vec3 sun_lit = depth > 0.0 ? sunlight_under_water(water.optics, depth) : vec3(1.0);
    vec3 sky_lit = depth > 0.0 ? skylight_under_water(water.optics, depth) : vec3(1.0);
    vec3 color = terrain_light(m, sky_lit, sun_lit * focus);
    // A wet film on the ground the swash leaves bare reflects the sky and the sun (not
    // on ground under the water, which the water's own surface covers).
    float film = m.film * smoothstep(-1.5, -0.5, m.rise);
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
