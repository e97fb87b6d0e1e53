#version 450
// The sky table (sky.glsl): the sky without the sun's disc over the upper hemisphere, for
// the water's reflections and the fog. Drawn by a full-screen triangle (sky.vert) into
// the kSkyTableSide-square table whenever a frame's sky may have changed.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "sky.glsl"
layout(push_constant) uniform SkyPush { GpuSky sky; } push;
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(sky_dome(push.sky, sky_table_direction(0.5 + 0.5 * ndc)), 1.0); }
