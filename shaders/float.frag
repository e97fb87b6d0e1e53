#version 450
// Floating bodies (boats, barrels): one paint per body, a plain Lambert sun plus sky
// ambient (as the terrain), dimmed with depth and focused by the waves (caustics) under
// the ocean's surface, and the same fog as the water (through the water from under its
// surface). Drawn with terrain.vert before the water, so the water refracts and fogs
// their submerged parts.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_quality.glsl"
#include "water_medium.glsl"
#include "caustics.glsl"
#include "body_masks.glsl"
#include "water_over.glsl"
#include "clip_volumes.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 1) in vec3 normal;
layout(push_constant) uniform Push { layout(offset = kPushMeshOrigin) vec4 mesh_origin; layout(offset = kPushFloatPaint) vec4 paint; };  // paint: linear RGB
layout(location = 0) out vec4 out_color;

void main() {
    vec3 n = normalize(normal);
    vec3 to_camera = frame.camera.xyz - world_pos;
    float distance = length(to_camera);
    vec3 v = to_camera / distance;
    if (dot(n, v) < 0.0) n = -n;  // the inside of a hull seen through a gap
    // Under the ocean's or a lake's surface as the terrain (water_over.glsl, caustics.glsl).
    WaterOver water = water_over(world_pos);
    float depth = water.depth;
    vec3 sun_lit = vec3(1.0), sky_lit = vec3(1.0);
    if (depth > 0.0 && !seen_side_in_clip_volumes(world_pos, n)) {  // not the inside of a dry hold
        sun_lit = sunlight_under_water(water.optics, depth) *
                  caustic_gain(world_pos, depth, distance / frame.params.z, water.draw, water.optics);
        sky_lit = skylight_under_water(water.optics, depth);
    }
    vec3 color = paint.rgb * ground_light(n, sky_lit, sun_lit);
    // A little sheen: painted hulls and barrels are glossy.
    vec3 h = normalize(v + frame.sun.xyz);
    color += 0.08 * pow(max(dot(n, h), 0.0), 40.0) * max(dot(n, frame.sun.xyz), 0.0);
    uint view = uint(frame.params.w);
    if (view == kViewNormals) color = n * 0.5 + 0.5;
    if (view == kViewShaded)
        color = pixel_under_water() ? seen_under_water(color, world_pos.y, distance, -v) : apply_fog(color, distance, -v);
    out_color = target_color(with_water_line(color));
}
