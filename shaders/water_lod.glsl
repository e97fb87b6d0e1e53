// Level of detail shared by the water tessellation stages: one continuous
// function of distance, so neighbouring patches agree on shared edges (no
// cracks) and waves fade smoothly (no seams, no popping).
#ifndef TIDEWATER_WATER_LOD_GLSL
#define TIDEWATER_WATER_LOD_GLSL

// Distance from the camera to a point of water at rest height `level`.
float camera_distance(vec2 xz, float level) {
    return length(vec3(xz.x, level, xz.y) - frame.camera.xyz);
}
// Target vertex spacing (m) at a distance: grows linearly with distance.
float vertex_spacing(float distance) {
    return max(distance, 1.0) / frame.params.z;
}
#endif
