#version 450
// Terrain shading: sand, grass and rock by height and slope, wet sand at the
// waterline, animated Voronoi caustics on submerged ground.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec4 out_color;

// Distance to the nearest of jittered cell points (Voronoi), animated in time.
float voronoi(vec2 p, float t) {
    vec2 cell = floor(p);
    float best = 8.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            vec2 c = cell + vec2(i, j);
            uint h = tw_hash(int(c.x), int(c.y), 99u);
            vec2 jitter = vec2(float(h & 0xffffu), float(h >> 16)) / 65535.0;
            vec2 pt = c + 0.5 + 0.4 * sin(t * 0.8 + 6.2831 * jitter);
            best = min(best, length(p - pt));
        }
    return best;
}

void main() {
    vec3 n = normalize(normal);
    float h = world_pos.y;
    float level = frame.params.x;
    float slope = 1.0 - n.y;
    uint view = uint(frame.params.w);

    vec3 sand = vec3(0.80, 0.72, 0.52);
    vec3 wet = vec3(0.48, 0.42, 0.31);
    vec3 grass = vec3(0.28, 0.46, 0.18);
    vec3 rock = vec3(0.45, 0.43, 0.41);
    vec3 base = mix(sand, grass, smoothstep(level + 2.0, level + 6.0, h));
    base = mix(base, rock, smoothstep(0.25, 0.45, slope));
    base = mix(base, wet, smoothstep(level + 1.2, level + 0.2, h) * (1.0 - smoothstep(0.35, 0.5, slope)));

    float diffuse = max(dot(n, frame.sun.xyz), 0.0);
    vec3 color = base * (0.35 + 0.75 * diffuse);
    float depth = level - h;
    if (depth > 0.0) {
        // Caustics fade with depth; refraction and absorption are applied by the water pass.
        float t = frame.camera.w;
        vec2 q = (world_pos.xz + frame.origin_mod.xy) * 0.375;  // period 256 / 0.375 divides 2048 m
        float c = voronoi(q, t) * voronoi(q + 7.3, t * 1.3);
        // Troughs bare the sand just below the mean level: no caustics in the top half metre.
        float caustic = pow(clamp(1.0 - c * 2.2, 0.0, 1.0), 3.0) * 1.6 * exp(-depth * 0.18) * diffuse * smoothstep(0.5, 2.0, depth);
        color += caustic * vec3(0.9, 1.0, 0.95);
    }
    if (view == kViewHeight) color = heat_color((h - level + 40.0) / 80.0);
    if (view == kViewDepth) color = depth > 0.0 ? heat_color(depth / 40.0) : vec3(0.2);
    if (view == kViewNormals) color = n * 0.5 + 0.5;
    if (view == kViewWireframe) color = vec3(0.1, 0.25, 0.08);
    vec3 ray = world_pos - frame.camera.xyz;
    if (view == kViewShaded) color = apply_fog(color, length(ray), normalize(ray));
    out_color = target_color(color);
}
