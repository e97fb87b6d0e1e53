// Clip volumes: where the water is removed (tidewater/clip_volume.hpp, whose
// clip_distance this is the twin of). Needs frame.glsl (GpuFrame.clip_volumes).
#ifndef TIDEWATER_CLIP_VOLUMES_GLSL
#define TIDEWATER_CLIP_VOLUMES_GLSL

layout(std430, set = kFrameSet, binding = eFrameClipTextures) readonly buffer ClipTextures { float clip_texture_samples[]; };

// A distance texture's distance at `local`: trilinear between the samples of the box's
// nearest point, plus the distance to it (DistanceTexture::distance). `head` holds the box's
// half extents and the first sample, `sides` the samples along x, y and z.
float texture_distance(vec4 head, vec3 sides, vec3 local) {
    vec3 h = head.xyz;
    vec3 nearest = clamp(local, -h, h);
    float outside = length(local - nearest);
    vec3 u = (nearest + h) / (2.0 * h) * (sides - 1.0);
    vec3 cell = min(floor(u), sides - 2.0);
    vec3 f = u - cell;
    uint row = uint(sides.x), slice = row * uint(sides.y);
    uint base = uint(head.w) + uint(cell.x) + row * uint(cell.y) + slice * uint(cell.z);
    float x00 = mix(clip_texture_samples[base], clip_texture_samples[base + 1u], f.x);
    float x10 = mix(clip_texture_samples[base + row], clip_texture_samples[base + row + 1u], f.x);
    float x01 = mix(clip_texture_samples[base + slice], clip_texture_samples[base + slice + 1u], f.x);
    float x11 = mix(clip_texture_samples[base + slice + row], clip_texture_samples[base + slice + row + 1u], f.x);
    return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z) + outside;
}

// The signed distance from `p` (relative to O) to the volume's surface, m: < 0 inside.
float clip_distance(GpuClipVolume c, vec3 p) {
    vec3 d = p - c.center.xyz;
    vec3 local = vec3(dot(d, c.axis_x.xyz), dot(d, c.axis_y.xyz), dot(d, c.axis_z.xyz));
    uint shape = uint(c.center.w);
    if (shape == kClipBox) {
        vec3 q = abs(local) - vec3(c.axis_x.w, c.axis_y.w, c.axis_z.w);
        return length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0);
    }
    if (shape == kClipSphere) return length(local) - c.axis_x.w;
    if (shape == kClipConvex) {
        float outside = -1e30;
        uint first = uint(c.axis_x.w), count = uint(c.axis_y.w);
        for (uint i = first; i < first + count; ++i) {
            vec4 plane = frame.clip_planes[i];
            outside = max(outside, dot(plane.xyz, local) - plane.w);
        }
        return outside;
    }
    if (shape == kClipTexture) {
        uint first = uint(c.axis_x.w);
        return texture_distance(frame.clip_planes[first], frame.clip_planes[first + 1u].xyz, local);
    }
    return length(local - vec3(0.0, clamp(local.y, -c.axis_y.w, c.axis_y.w), 0.0)) - c.axis_x.w;
}

// Whether `p` (relative to O) lies inside any of the frame's clip volumes.
bool inside_clip_volumes(vec3 p) {
    for (uint i = 0u; i < uint(frame.clips.x); ++i)
        if (clip_distance(frame.clip_volumes[i], p) < 0.0) return true;
    return false;
}

// Whether the side of a surface at `p` that faces along `n` (the side the eye sees) is in a
// clip volume: a hull's skin lies on its volume's boundary, its inside dry, its outside wet.
const float kClipSkin = 0.05;  // m
bool seen_side_in_clip_volumes(vec3 p, vec3 n) { return inside_clip_volumes(p + kClipSkin * n); }

#endif
