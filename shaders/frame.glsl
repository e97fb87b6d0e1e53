// Set kFrameSet of the render pipelines (bindings in host_device.h): frame constants,
// waves, the terrain height texture, the copy of the opaque scene, the sky table and the foam's noise.
#ifndef TIDEWATER_FRAME_GLSL
#define TIDEWATER_FRAME_GLSL

#include "noise.glsl"
#include "sky.glsl"

layout(std140, set = kFrameSet, binding = eFrameConstants) uniform Frame { GpuFrame frame; };
layout(std430, set = kFrameSet, binding = eFrameWaves) readonly buffer Waves { GpuWave waves[]; };
layout(std430, set = kFrameSet, binding = eFrameBodyDraws) readonly buffer BodyDraws { GpuBodyDraw draws[]; };  // the frame's water draws
layout(set = kFrameSet, binding = eFrameTerrainHeight) uniform sampler2D terrain_height;  // R16 unorm
layout(set = kFrameSet, binding = eFrameSceneColor) uniform sampler2D scene_color;
layout(set = kFrameSet, binding = eFrameSceneDepth) uniform sampler2D scene_depth;
layout(std430, set = kFrameSet, binding = eFrameShoreWaves) readonly buffer ShoreWavesBuf { vec4 shore_waves[]; };
layout(std430, set = kFrameSet, binding = eFrameShoreShared) readonly buffer ShoreSharedBuf { vec4 shore_shared[]; };
layout(std430, set = kFrameSet, binding = eFrameShorePages) readonly buffer ShorePagesBuf { uint shore_pages[]; };
layout(std430, set = kFrameSet, binding = eFrameShoreLayers) readonly buffer ShoreLayersBuf { GpuShoreLayer shore_layers[]; };
layout(set = kFrameSet, binding = eFrameSkyTable) uniform sampler2D sky_table;  // sky.glsl
layout(set = kFrameSet, binding = eFrameFoamNoise) uniform sampler2D foam_noise;  // repeating (foam_noise.frag)

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

// Sky colour toward direction d (y up), display-referred, with the sun's disc (sky.glsl).
vec3 sky_color(vec3 d) { return sky_dome(frame.sky, d) + sun_disc(frame.sky, d); }
// The same toward an upper-hemisphere direction (d.y >= 0), from the sky table: what the
// water reflects over its facets and the fog fades to, at a texture read each.
vec3 sky_seen(vec3 d) { return textureLod(sky_table, sky_table_uv(d), 0.0).rgb + sun_disc(frame.sky, d); }

// Distance fog toward the horizon colour.
vec3 apply_fog(vec3 color, float distance, vec3 dir) {
    float f = 1.0 - exp(-distance * 0.00018);
    return mix(color, sky_seen(normalize(vec3(dir.x, max(dir.y, 0.02), dir.z))), clamp(f, 0.0, 1.0));
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

// The light on an opaque surface facing `n` (the terrain, floats, a host's geometry under
// water): sky ambient and a Lambert sun, each scaled by what reaches it (sky_lit,
// sun_lit: 1 in the air).
vec3 ground_light(vec3 n, vec3 sky_lit, vec3 sun_lit) {
    float diffuse = max(dot(n, frame.sun.xyz), 0.0);
    float sky_light = 0.5 + 0.5 * n.y;
    return (0.22 + 0.18 * sky_light) * sky_lit + 0.75 * diffuse * sun_lit;
}

// The point (relative to O) the view's depth `depth` shows at `uv` (0..1 across the view).
vec3 world_from_depth(vec2 uv, float depth) {
    vec4 p = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
    return p.xyz / p.w;
}

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
