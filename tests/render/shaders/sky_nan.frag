#version 450
// Render-test probe in place of sky.frag: white, the code the terrain probe never writes.
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;

void main() {
    out_color = vec4(1.0);
}
