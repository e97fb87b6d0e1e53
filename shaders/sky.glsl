// The daylight sky (GpuSky): the Preetham sky's colour toward a direction, the sun's
// disc, and the table of the sky the water's reflections and the fog read instead of
// evaluating it (sky_table.frag fills it; frame.glsl reads it). No bindings: the table's
// pass takes the sky in push constants, the frame's pipelines from GpuFrame.
#ifndef TIDEWATER_SKY_GLSL
#define TIDEWATER_SKY_GLSL

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

// Sky colour toward direction d (y up), display-referred, without the sun's disc: the
// Preetham sky's luminance (relative to the zenith's) and chromaticity in linear sRGB,
// white-balanced, exposed with a soft shoulder that keeps the hue, saturated as a camera
// renders daylight (frame_constants.cpp), sRGB-encoded; plus the sun's glow. Below the
// horizon it darkens toward the ground's haze.
vec3 sky_dome(GpuSky sky, vec3 d) {
    vec3 up_dir = normalize(vec3(d.x, max(d.y, 0.0), d.z));
    vec3 sun = normalize(vec3(sky.sun.x, max(sky.sun.y, 0.0), sky.sun.z));
    float gamma = acos(clamp(dot(up_dir, sun), -1.0, 1.0));
    float Y = sky.zenith.x * perez(sky.Y, sky.e.x, up_dir.y, gamma);
    float x = sky.zenith.y * perez(sky.x, sky.e.y, up_dir.y, gamma);
    float y = max(sky.zenith.z * perez(sky.y, sky.e.z, up_dir.y, gamma), 1e-4);
    vec3 XYZ = vec3(x * Y / y, Y, (1.0 - x - y) * Y / y);
    vec3 rgb = max(mat3(3.2406, -0.9689, 0.0557, -1.5372, 1.8758, -0.2040, -0.4986, 0.0415, 1.0570) * XYZ, vec3(0.0));
    rgb *= sky.balance.xyz;
    float luminance = max(dot(rgb, vec3(0.2126, 0.7152, 0.0722)), 1e-6);
    float shown = 1.0 - exp(-sky.e.w * luminance);
    rgb *= shown / luminance;
    vec3 color = linear_to_srgb(max(mix(vec3(shown), rgb, sky.zenith.w), vec3(0.0)));
    if (d.y < 0.0) color = mix(color, vec3(0.35, 0.42, 0.5), clamp(-d.y * 5.0, 0.0, 1.0));
    float s = max(dot(d, sky.sun.xyz), 0.0);
    return color + sky.sun.w * pow(s, 12.0) * vec3(0.25, 0.2, 0.12);
}

// The sun's disc toward d: narrower than the table's texels, so never in the table.
vec3 sun_disc(GpuSky sky, vec3 d) {
    float s = max(dot(d, sky.sun.xyz), 0.0);
    return sky.sun.w * pow(s, 900.0) * vec3(8.0, 7.0, 5.5);
}

// The sky table's coordinates of an upper-hemisphere direction (d.y >= 0, unit): its
// stereographic projection from the nadir, the unit disc inscribed in the table. A texel
// spans 0.45 degrees of elevation at the horizon, 0.9 at the zenith; no trigonometry.
vec2 sky_table_uv(vec3 d) { return 0.5 + 0.5 * d.xz / (1.0 + max(d.y, 0.0)); }
// The direction a table texel holds (the inverse; the corners outside the disc hold the horizon).
vec3 sky_table_direction(vec2 uv) {
    vec2 p = 2.0 * uv - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) {
        p /= sqrt(r2);
        r2 = 1.0;
    }
    return vec3(2.0 * p.x, 1.0 - r2, 2.0 * p.y) / (1.0 + r2);
}

#endif
