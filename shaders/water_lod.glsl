// Level of detail shared by the water tessellation stages: one continuous
// function of distance, so neighbouring patches agree on shared edges (no
// cracks) and waves fade smoothly (no seams, no popping).
#ifndef TIDEWATER_WATER_LOD_GLSL
#define TIDEWATER_WATER_LOD_GLSL
#include "water_point.glsl"

// The shading's footprint across the view at a distance (m): a pixel, or a sample where
// the water shades every sample of a multisampled target.
float footprint_across(float distance) {
    return max(distance, 1.0) / (frame.params.z * frame.water_density.x);
}

// The standard normal density phi(u) and distribution function Phi(u), the latter within
// 2e-7 (Abramowitz and Stegun 7.1.26), tails included: one exponential serves both.
vec2 normal_pdf_cdf(float u) {
    float e = exp(-0.5 * u * u);
    float t = 1.0 / (1.0 + 0.3275911 * 0.7071068 * abs(u));
    float tail = 0.5 * t * (0.2548296 + t * (-0.2844967 + t * (1.4214137 + t * (-1.4531520 + t * 1.0614054)))) * e;
    return vec2(0.3989423 * e, u < 0.0 ? tail : 1.0 - tail);
}
float normal_cdf(float u) { return normal_pdf_cdf(u).y; }

// The slopes toward the viewer of the facets a ray meets at elevation tangent t, for
// Gaussian slopes of deviation sigma per axis weighted by the area they show the viewer,
// (t + s)+: their mean sigma Phi(u) / Z and deviation sigma sqrt((u Phi(u) + 2 phi(u)) / Z
// - (Phi(u) / Z)^2), Z = u Phi(u) + phi(u), u = t / sigma. At grazing the mean is 1.25
// sigma and the deviation 0.65 sigma; from above, sigma^2 / t and sigma.
vec2 visible_slopes(float t, float sigma) {
    if (sigma <= 0.0) return vec2(0.0);
    float u = t / sigma;
    vec2 pdf_cdf = normal_pdf_cdf(u);
    float phi = pdf_cdf.x, cdf = pdf_cdf.y;
    float z = max(u * cdf + phi, 1e-6);
    float mean = cdf / z;
    return sigma * vec2(mean, sqrt(max((u * cdf + 2.0 * phi) / z - mean * mean, 0.0)));
}

// The render LOD of water at rest position `xz` and rest height `level` (WaveLod), for a
// body whose waves have mean square slope `mean_square_slope` (both axes). A pixel is
// one pixel wide across the view; along it, its footprint is stretched by the angle at
// which it meets the facets it sees: the view's elevation tangent (from the camera's
// height over the rest plane, not the waves', so that it does not change from crest to
// trough) plus the mean slope those facets turn toward the viewer.
WaveLod wave_lod_at(vec2 xz, float level, float mean_square_slope) {
    vec3 to_camera = frame.camera.xyz - vec3(xz.x, level, xz.y);
    float distance = max(length(to_camera), 1.0);
    float horizontal = max(length(to_camera.xz), 1e-4);
    float elevation = max(to_camera.y, 0.0) / horizontal;
    WaveLod lod;
    lod.toward = to_camera.xz / horizontal;
    lod.across = footprint_across(distance);
    float meets = elevation + visible_slopes(elevation, sqrt(0.5 * mean_square_slope)).x;
    float stretch = min(sqrt(1.0 + 1.0 / max(meets * meets, 1e-4)), 100.0);
    lod.along = lod.across * stretch;
    lod.spacing = frame.water_density.y * lod.across;
    lod.spacing_along = lod.spacing * min(stretch, frame.water_density.w);
    return lod;
}

// How many vertices an edge from a to b needs at the vertex spacing wanted at `at`.
float vertices_along(vec2 e, vec2 at, float level, float mean_square_slope) {
    WaveLod lod = wave_lod_at(at, level, mean_square_slope);
    return length(vec2(dot(e, lod.toward) / lod.spacing_along, dot(e, vec2(-lod.toward.y, lod.toward.x)) / lod.spacing));
}

// How many vertices the water's tessellation puts along a rest-plane edge from a to b:
// its length on screen over the vertex spacing at its middle, or where the vertices spread
// along the view (QualitySettings::water_max_foreshortening over 1), where that spacing
// grows with the square of the distance, at the finest of its ends and middle, so that the
// mesh is nowhere coarser than the spacing each vertex fades its waves by. Both sides of
// an edge agree (no cracks).
float tessellation_level(vec2 a, vec2 b, float level, float mean_square_slope) {
    vec2 e = b - a;
    float n = vertices_along(e, 0.5 * (a + b), level, mean_square_slope);
    if (frame.water_density.w > 1.0)
        n = max(n, max(vertices_along(e, a, level, mean_square_slope), vertices_along(e, b, level, mean_square_slope)));
    return clamp(n, 1.0, 64.0);
}
#endif
