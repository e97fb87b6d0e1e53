#version 450
// The host's own geometry, drawn into the targets before the frame (FrameTargets::clear
// false), where it lies under a body's surface: the sun's and the sky's light it loses to
// the water over it and the caustics that water's waves focus on it, as on the terrain
// (ground_light's split of sun and sky, its normal from the depth copy's neighbours); and,
// from an eye under the surface, the water it is seen through and the water line. A
// full-screen pass over the copy of the host's colour and depth; pixels where the host drew
// nothing, or that no water touches, are left as they are.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_quality.glsl"
#include "water_medium.glsl"
#include "caustics.glsl"
#include "body_masks.glsl"
#include "water_over.glsl"
#include "clip_volumes.glsl"
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;

// The host's point at a texel of the view (relative to O), or the far plane's (depth 0).
vec3 host_point(ivec2 texel, out float depth) {
    depth = texelFetch(scene_depth, texel, 0).r;
    return world_from_depth((vec2(texel) + 0.5) * frame.viewport.zw, depth);
}

// The surface's normal from the neighbours on the side nearer in depth along each axis
// (so that an edge does not bend it), turned toward the eye.
vec3 host_normal(ivec2 texel, vec3 p, vec3 v) {
    ivec2 last = ivec2(frame.viewport.xy) - 1;
    float z;
    vec3 right = host_point(min(texel + ivec2(1, 0), last), z) - p;
    vec3 left = p - host_point(max(texel - ivec2(1, 0), ivec2(0)), z);
    vec3 down = host_point(min(texel + ivec2(0, 1), last), z) - p;
    vec3 up = p - host_point(max(texel - ivec2(0, 1), ivec2(0)), z);
    vec3 dx = dot(right, right) < dot(left, left) ? right : left;
    vec3 dy = dot(down, down) < dot(up, up) ? down : up;
    vec3 n = normalize(cross(dx, dy));
    return dot(n, v) < 0.0 ? -n : n;
}

void main() {
    ivec2 texel = ivec2(view_pixel());
    float z;
    vec3 p = host_point(texel, z);
    if (z <= 0.0) discard;  // the host drew nothing here
    WaterOver water = water_over(p);
    float depth = inside_clip_volumes(p) ? 0.0 : water.depth;
    bool seen_from_below = pixel_under_water();
    if (depth <= 0.0 && frame.underwater.x < 0.5) discard;  // in the air, seen from the air
    vec3 to_camera = frame.camera.xyz - p;
    float distance = length(to_camera);
    vec3 v = to_camera / distance;
    vec3 color = from_scene_copy(texelFetch(scene_color, texel, 0).rgb);
    if (depth > 0.0) {
        vec3 n = host_normal(texel, p, v);
        float footprint = distance / frame.params.z / max(abs(dot(v, n)), 0.1);
        float focus = caustic_gain(p, depth, footprint, water.draw, water.optics);
        vec3 under = ground_light(n, skylight_under_water(water.optics, depth),
                                  sunlight_under_water(water.optics, depth) * focus);
        color *= under / ground_light(n, vec3(1.0), vec3(1.0));
    }
    if (seen_from_below) color = seen_under_water(color, p.y, distance, -v);
    out_color = target_color(with_water_line(color));
}
