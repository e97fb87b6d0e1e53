#version 450
// Render-test probe in place of water.frag: no water is drawn over the ground. It reads
// every input the tessellation evaluation shader writes, so the interfaces still match.
layout(location = 0) in vec3 world_pos;
layout(location = 1) in vec3 geo_normal;
layout(location = 2) in vec2 rest_xz;
layout(location = 3) in float jacobian;
layout(location = 4) in float eta;
layout(location = 5) in float wake_eta;
layout(location = 6) in vec2 shore_info;
layout(location = 7) in float rest_level;
layout(location = 8) in vec2 current;
layout(location = 9) in vec4 lagged_jacobian;
layout(location = 10) in vec4 hidden;
layout(location = 11) in vec4 hidden_lagged;
layout(location = 12) in vec4 hidden_lagged_slope;
layout(location = 0) out vec4 out_color;

void main() {
    float any = world_pos.x + geo_normal.x + rest_xz.x + jacobian + eta + wake_eta + shore_info.x + rest_level + current.x +
                lagged_jacobian.x + hidden.x + hidden_lagged.x + hidden_lagged_slope.x;
    if (!(any > 3.0e38)) discard;
    out_color = vec4(any);
}
