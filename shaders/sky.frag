#version 450
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;
void main() {
    vec4 far_point = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 dir = normalize(far_point.xyz / far_point.w - frame.camera.xyz);
    out_color = target_color(sky_color(dir));
}
