// The sky a pixel of water reflects over the facets it sees (water.frag).
#ifndef TIDEWATER_VISIBLE_FACETS_GLSL
#define TIDEWATER_VISIBLE_FACETS_GLSL
#include "frame.glsl"
#include "water_quality.glsl"

// The facets a pixel sees when its waves are not all resolved: slopes of variance
// sigma^2 per axis about the resolved normal n, each weighted by the area it shows the
// viewer. At grazing angles the facets facing the viewer dominate (Bruneton, Neyret
// and Holzschuch 2010): the geometry shows this where it draws the waves, and the
// filtered far field must too. Quadrature: two slopes along the view's azimuth with the
// visible slopes' mean and deviation (`slopes`, from visible_slopes), each +-sigma across it;
// or, where the tier takes one facet (kReflectionFacets), the one at their mean slope.
struct VisibleFacets {
    vec3 normal;    // their mean normal
    float fresnel;  // their mean Fresnel reflectance
    vec3 sky;       // their mean Fresnel-weighted reflection of the sky
};

float schlick_fresnel(vec3 n, vec3 v) { return 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0); }

// One facet of normal m: its Fresnel reflectance and its reflection of the sky (reflected
// down into the next wave, the ray sees its mirror image).
VisibleFacets one_facet(vec3 m, vec3 v) {
    float fresnel = schlick_fresnel(m, v);
    vec3 r = reflect(-v, m);
    r.y = abs(r.y);
    return VisibleFacets(m, fresnel, fresnel * sky_seen(r));
}

VisibleFacets visible_facets(vec3 n, vec3 v, float variance, vec2 slopes) {
    VisibleFacets f;
    float cos_view = clamp(dot(n, v), 1e-4, 1.0);
    vec3 flat_view = v - n * cos_view;  // v in the resolved facet's plane
    float in_plane = length(flat_view);
    if (variance <= 0.0 || in_plane < 1e-4) return one_facet(n, v);
    vec3 along = flat_view / in_plane, across = normalize(cross(n, along));
    if (kReflectionFacets == 1u) return one_facet(normalize(n + along * slopes.x), v);
    float sigma = sqrt(variance);
    f.normal = vec3(0.0);
    f.fresnel = 0.0;
    f.sky = vec3(0.0);
    // one_facet's terms written out: through the struct the loop took 88 VGPRs on navi21, not 80.
    for (int i = -1; i <= 1; i += 2)
        for (int j = -1; j <= 1; j += 2) {
            vec3 m = normalize(n + along * (slopes.x + float(i) * slopes.y) + across * (sigma * float(j)));
            float fresnel = schlick_fresnel(m, v);
            vec3 r = reflect(-v, m);
            r.y = abs(r.y);  // reflected down into the next wave: its mirror image
            f.normal += 0.25 * m;
            f.fresnel += 0.25 * fresnel;
            f.sky += 0.25 * fresnel * sky_seen(r);
        }
    f.normal = normalize(f.normal);
    return f;
}
#endif
