// Set kFrameSet of the render pipelines (bindings in host_device.h): frame constants,
// waves, the terrain height texture and the copy of the opaque scene.
#ifndef TIDEWATER_FRAME_GLSL
#define TIDEWATER_FRAME_GLSL

#include "noise.glsl"

layout(std140, set = kFrameSet, binding = eFrameConstants) uniform Frame { GpuFrame frame; };
layout(std430, set = kFrameSet, binding = eFrameWaves) readonly buffer Waves { GpuWave waves[]; };
layout(set = kFrameSet, binding = eFrameTerrainHeight) uniform sampler2D terrain_height;  // R16 unorm
layout(set = kFrameSet, binding = eFrameSceneColor) uniform sampler2D scene_color;
layout(set = kFrameSet, binding = eFrameSceneDepth) uniform sampler2D scene_depth;
layout(std430, set = kFrameSet, binding = eFrameShoreWaves) readonly buffer ShoreWavesBuf { vec4 shore_waves[]; };
layout(std430, set = kFrameSet, binding = eFrameShoreShared) readonly buffer ShoreSharedBuf { vec4 shore_shared[]; };
layout(std430, set = kFrameSet, binding = eFrameShorePages) readonly buffer ShorePagesBuf { uint shore_pages[]; };
layout(std430, set = kFrameSet, binding = eFrameShoreLayers) readonly buffer ShoreLayersBuf { GpuShoreLayer shore_layers[]; };

// The ground's height (m) at xz relative to O: the height texture between its texel
// centres, and beyond them the edge value eased to the seabed (the GLSL twin of
// tidewater::heightmap_edge_fade in Terrain::height_at).
float terrain_height_at(vec2 xz) {
    vec2 uv = (xz - frame.terrain_rect.xy) / frame.terrain_rect.zw;
    float h = frame.terrain_heights.y + frame.terrain_heights.z * textureLod(terrain_height, uv, 0.0).r;
    float fade = frame.terrain_lod.x;
    if (fade > 0.0) {
        vec2 half_texel = 0.5 * frame.terrain_lod.yz;
        vec2 outside = max(max(frame.terrain_rect.xy + half_texel - xz, xz - (frame.terrain_rect.xy + frame.terrain_rect.zw - half_texel)), 0.0);
        h = mix(h, frame.terrain_heights.w, smoothstep(0.0, fade, length(outside)));
    }
    return h;
}

// The ground's normal from central differences `step` metres apart (at least a texel):
// the heightmap's own detail, whatever the mesh's level of detail.
vec3 terrain_normal_at(vec2 xz, float step) {
    vec2 e = max(vec2(step), frame.terrain_lod.yz);
    float dx = terrain_height_at(xz + vec2(e.x, 0.0)) - terrain_height_at(xz - vec2(e.x, 0.0));
    float dz = terrain_height_at(xz + vec2(0.0, e.y)) - terrain_height_at(xz - vec2(0.0, e.y));
    return normalize(vec3(-dx / (2.0 * e.x), 1.0, -dz / (2.0 * e.y)));
}

vec3 srgb_to_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}
vec3 linear_to_srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// The Perez function of the Preetham sky for one of Y, x, y (sky_model.hpp).
float perez(vec4 abcd, float e, float cos_theta, float gamma) {
    float cos_gamma = cos(gamma);
    return (1.0 + abcd.x * exp(abcd.y / max(cos_theta, 0.01))) * (1.0 + abcd.z * exp(abcd.w * gamma) + e * cos_gamma * cos_gamma);
}

// Sky colour toward direction d (y up), display-referred: the Preetham sky's luminance
// (relative to the zenith's) and chromaticity in linear sRGB, white-balanced, exposed
// with a soft shoulder that keeps the hue, saturated as a camera renders daylight
// (frame_constants.cpp), sRGB-encoded; plus the sun's disc and glow. Below the horizon
// it darkens toward the ground's haze.
vec3 sky_color(vec3 d) {
    vec3 up_dir = normalize(vec3(d.x, max(d.y, 0.0), d.z));
    vec3 sun = normalize(vec3(frame.sun.x, max(frame.sun.y, 0.0), frame.sun.z));
    float gamma = acos(clamp(dot(up_dir, sun), -1.0, 1.0));
    float Y = frame.sky_zenith.x * perez(frame.sky_Y, frame.sky_e.x, up_dir.y, gamma);
    float x = frame.sky_zenith.y * perez(frame.sky_x, frame.sky_e.y, up_dir.y, gamma);
    float y = max(frame.sky_zenith.z * perez(frame.sky_y, frame.sky_e.z, up_dir.y, gamma), 1e-4);
    vec3 XYZ = vec3(x * Y / y, Y, (1.0 - x - y) * Y / y);
    vec3 rgb = max(mat3(3.2406, -0.9689, 0.0557, -1.5372, 1.8758, -0.2040, -0.4986, 0.0415, 1.0570) * XYZ, vec3(0.0));
    rgb *= frame.sky_balance.xyz;
    float luminance = max(dot(rgb, vec3(0.2126, 0.7152, 0.0722)), 1e-6);
    float shown = 1.0 - exp(-frame.sky_e.w * luminance);
    rgb *= shown / luminance;
    vec3 sky = linear_to_srgb(max(mix(vec3(shown), rgb, frame.sky_zenith.w), vec3(0.0)));
    if (d.y < 0.0) sky = mix(sky, vec3(0.35, 0.42, 0.5), clamp(-d.y * 5.0, 0.0, 1.0));
    float s = max(dot(d, frame.sun.xyz), 0.0);
    sky += frame.sun.w * (pow(s, 900.0) * vec3(8.0, 7.0, 5.5) + pow(s, 12.0) * vec3(0.25, 0.2, 0.12));
    return sky;
}

// Distance fog toward the horizon colour.
vec3 apply_fog(vec3 color, float distance, vec3 dir) {
    float f = 1.0 - exp(-distance * 0.00018);
    return mix(color, sky_color(normalize(vec3(dir.x, max(dir.y, 0.02), dir.z))), clamp(f, 0.0, 1.0));
}

vec3 heat_color(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(1.5 * t, 1.5 * t * (1.0 - t) * 2.0, 1.5 * (1.0 - t)), 0.0, 1.0);
}

// The shading works in display-referred sRGB values. A target that wants linear colour
// (an sRGB-encoding or float format, frame.options.y) gets them decoded, so that it shows
// the same picture, and what is sampled back from its copy is encoded again.
vec4 target_color(vec3 c) { return vec4(frame.options.y > 0.5 ? srgb_to_linear(c) : c, 1.0); }
vec3 from_scene_copy(vec3 sampled) { return frame.options.y > 0.5 ? linear_to_srgb(sampled) : sampled; }

// Ripple slope (d/dx, d/dz) at xz relative to O of a body's ripples (GpuBodyDraw's
// ripple and ripple_offset); the origin enters reduced modulo the noise period.
vec2 ripple_slope(vec2 xz, vec4 ripple, vec4 offset) {
    vec2 slope = vec2(0.0);
    float amp = ripple.x;
    if (amp <= 0.0) return slope;
    uint seed = uint(ripple.w);
    int octaves = int(ripple.z);
    for (int i = 1; i <= octaves; ++i) {
        float scale = float(i) * ripple.y;
        vec3 n = gradient_noise((xz + offset.zw) * scale + offset.xy, seed + uint(i));
        slope += (amp / float(i)) * scale * n.yz;
    }
    return slope;
}

#endif
