#version 450
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_medium.glsl"
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;
void main() {
    vec4 far_point = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 dir = normalize(far_point.xyz / far_point.w - frame.camera.xyz);
    // From under a surface nothing reaches the sky but through it (the water pass): what is
    // left is water as far as the eye sees.
    out_color = target_color(with_water_line(pixel_under_water() ? water_inscatter(frame.underwater.y) : sky_color(dir)));
}
