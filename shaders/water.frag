#version 450
// Water shading (seed 004): depth colour and refraction from the copy of the
// opaque scene, Schlick Fresnel, sky and sun, screen-space reflection of the
// terrain, subsurface scattering at crests, foam where the Jacobian folds.
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_lod.glsl"
#include "water_point.glsl"
#include "water_draw.glsl"
#include "body_masks.glsl"
#include "flow_detail.glsl"
#define WAKE_COUNT uint(frame.wakes.x)
#define WAKE_TURBULENT uint(frame.wakes.y)
#include "wake_point.glsl"
// Compiled twice: as is, and with TW_WATER_PER_SAMPLE for multisampled targets that shade
// the water at every sample (its inputs interpolated there; RendererInitInfo::shade_water_per_sample).
#ifdef TW_WATER_PER_SAMPLE
#define WATER_IN sample in
#else
#define WATER_IN in
#endif
layout(location = 0) WATER_IN vec3 world_pos;
layout(location = 1) WATER_IN vec3 geo_normal;
layout(location = 2) WATER_IN vec2 rest_xz;
layout(location = 3) WATER_IN float jacobian;
layout(location = 4) WATER_IN float eta;
layout(location = 5) WATER_IN float wake_eta;
layout(location = 6) WATER_IN vec2 shore_info;
layout(location = 7) WATER_IN float rest_level;
layout(location = 8) WATER_IN vec2 current;
layout(location = 9) WATER_IN vec4 lagged_jacobian;
layout(location = 0) out vec4 out_color;

const vec3 kAbsorption = vec3(0.42, 0.085, 0.06);  // 1/m: red fades first
const vec3 kDeepColor = vec3(0.01, 0.09, 0.13);
const vec3 kShallowTint = vec3(0.55, 0.85, 0.8);

vec3 world_from_depth(vec2 uv, float depth) {
    vec4 p = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
    return p.xyz / p.w;
}

// Detail shorter than a few footprints (wave_lod_at) cannot be drawn: it goes into the
// slope variance instead (LEAN-style), which widens the sun's glitter and leaves the
// averaged reflection, as the supersampled picture shows, instead of aliasing.
// How much of a detail of wavelength `lambda` a pixel resolves: all from 4 footprints up,
// none under 2.
float resolved(float lambda, float footprint) { return smoothstep(2.0 * footprint, 4.0 * footprint, lambda); }

// The crest foam a pixel covers on average when waves it cannot resolve spread its
// Jacobian as a Gaussian of deviation `sigma` about `j`: the expectation of crest_foam
// (tidewater::crest_foam, a smoothstep from J* + w down to J* - w) over that spread, in
// closed form. Whitecaps are rare (a few percent of the sea), so most of a distant
// pixel's foam comes from the Gaussian's tail past the ramp: a ramp merely widened by
// sigma would cut that tail off and thin the far field's foam as pixels grow.
// The expectation is the integral over x in [J* - w, J* + w] of the curve's fall
// q(x) (it integrates to 1) times P(J < x), with
// q dx = 6 t (1 - t) dt, t = alpha + beta u, u = (x - j) / sigma, and the integrals of
// u^n Phi(u) known: G0 = u Phi + phi, G1 = ((u^2 - 1) Phi + u phi) / 2,
// G2 = (u^3 Phi + (u^2 + 2) phi) / 3.
vec3 phi_integrals(float u) {
    float phi = 0.3989423 * exp(-0.5 * u * u), cdf = normal_cdf(u);
    return vec3(u * cdf + phi, 0.5 * ((u * u - 1.0) * cdf + u * phi), (u * u * u * cdf + (u * u + 2.0) * phi) / 3.0);
}
float crest_foam_filtered(float j, float whitecap_jacobian, float sigma) {
    float half_width = 0.5 * kFoamRampFraction * max(1.0 - whitecap_jacobian, 0.0);
    float width = 2.0 * half_width;
    float beta = sigma / max(width, 1e-6);
    // A spread small against the ramp changes it by under 1% (and the sums would cancel).
    if (beta < 0.05) return crest_foam(j, whitecap_jacobian);
    float alpha = (j - (whitecap_jacobian - half_width)) / width;
    if (alpha - 1.0 > 6.0 * beta) return 0.0;  // the whole spread lies above the ramp (most of the sea)
    // Past 6 deviations Phi is 0 (nothing to add) or 1 (the ramp's own rise, in closed form).
    float ua = clamp(-alpha / beta, -6.0, 6.0), ub = clamp((1.0 - alpha) / beta, -6.0, 6.0);
    vec3 span = phi_integrals(ub) - phi_integrals(ua);
    float sum = 6.0 * beta * (alpha * (1.0 - alpha) * span.x + beta * (1.0 - 2.0 * alpha) * span.y - beta * beta * span.z);
    float t = clamp(alpha + 6.0 * beta, 0.0, 1.0);
    return clamp(sum + (ub >= 6.0 ? 1.0 - t * t * (3.0 - 2.0 * t) : 0.0), 0.0, 1.0);
}

// The waves a pixel cannot resolve, as the foam needs them: the variance of their
// compression (the trace of their m: J falls by it, to first order), their height
// variance (m^2), slope variance per axis (waves only: ripples are too low to hide
// anything), the covariance of their height with their compression now and at each
// lag of the foam's memory, and that of their slope away from the viewer with their
// compression at each lag (now it is none: the crest is where the slope turns).
struct HiddenWaves {
    float compression_variance;
    float height_variance;
    float slope_variance;
    float compression_covariance;
    vec4 lagged_covariance;
    vec4 lagged_slope_covariance;
};
HiddenWaves hidden_zero() { return HiddenWaves(0.0, 0.0, 0.0, 0.0, vec4(0.0), vec4(0.0)); }
// A wave of amplitude a (m) that the pixel loses `lost` of its variance of: eta = a sin
// theta, its slope away from the viewer a k_away cos theta (k_away: its wavevector along
// the view, rad/m), its compression Q k a sin theta and, l lags ago, Q k a sin(theta +
// l omega kFoamLagStep) (turn: sine and cosine of omega kFoamLagStep).
void add_hidden_wave(inout HiddenWaves h, float lost, float a, float slope_amplitude, float compression, float k_away, vec2 turn) {
    h.compression_variance += lost * 0.5 * compression * compression;
    h.height_variance += lost * 0.5 * a * a;
    h.slope_variance += lost * 0.5 * slope_amplitude * slope_amplitude;
    float covariance = lost * 0.5 * compression * a;
    h.compression_covariance += covariance;
    float sn = 0.0, cs = 1.0;
    for (int l = 0; l < 4; ++l) {
        float s = sn * turn.y + cs * turn.x;
        cs = cs * turn.y - sn * turn.x;
        sn = s;
        h.lagged_covariance[l] += covariance * cs;
        h.lagged_slope_covariance[l] += covariance * k_away * sn;
    }
}

// At grazing angles the crests hide the troughs behind them. Smith's height-correlated
// masking sees a point of height z (in deviations) with probability Phi(z)^Lambda,
// Lambda = phi(u) / u - (1 - Phi(u)) for Gaussian slopes of deviation sigma toward a view
// of elevation tangent t = u sigma: the heights seen are distributed as the largest of
// 1 + Lambda normal samples. Their mean and variance (in deviations) from rational fits
// in L = ln(1 + Lambda) (within 3e-4 and 0.025 of the exact integrals up to 300 samples).
vec2 visible_heights(float t, float sigma) {
    if (sigma <= 0.0) return vec2(0.0, 1.0);
    float u = max(t / sigma, 1e-3);
    float lambda = 0.3989423 * exp(-0.5 * u * u) / u - (1.0 - normal_cdf(u));
    float L = log(clamp(1.0 + lambda, 1.0, 300.0));
    float mean = L * (0.9055 + 0.01263 * L) / (1.0 + 0.1790 * L - 0.002568 * L * L);
    float variance = 1.0 / (1.0 + 0.7105 * L + 0.05301 * L * L);
    return vec2(mean, variance);
}

// Crest foam over the particles the viewer sees: the Jacobian j, less the unresolved
// waves' share (crest_foam_filtered's spread), conditioned on the heights seen (`seen`,
// from visible_heights): its mean falls by cov / sigma_h times their mean height, its
// variance loses (cov / sigma_h)^2 times what the masking takes off theirs. And on the
// facets seen (`facing`: the visible facets' mean slope away from the viewer over the
// slope variance, and the share of the variance their spread leaves out, over it; the
// slope is independent of the height): the foam a crest left behind it lies on the face
// it has passed, which faces the viewer where the waves run away from it.
float seen_crest_foam(float j, float covariance, float slope_covariance, HiddenWaves h, vec2 seen, vec2 facing,
                      float whitecap_jacobian) {
    float spread2 = h.compression_variance;
    if (h.height_variance > 0.0) {
        float per_height = covariance / sqrt(h.height_variance);
        j -= per_height * seen.x;
        spread2 -= per_height * per_height * (1.0 - seen.y);
    }
    j -= slope_covariance * facing.x;
    spread2 -= slope_covariance * slope_covariance * facing.y;
    return crest_foam_filtered(j, whitecap_jacobian, sqrt(max(spread2, 0.0)));
}

// Foam lace: 0 on the borders of 2.5 m cells (where bubbles gather between the holes
// that open in decaying foam), rising to 1 at their centres (F2 - F1 of a cellular noise).
float foam_lace(vec2 p) {
    vec2 cell = floor(p), f = p - cell;
    float f1 = 8.0, f2 = 8.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            uint h = tw_hash(int(cell.x) + i, int(cell.y) + j, 53u);
            vec2 site = vec2(i, j) + vec2(float(h & 0xffffu), float(h >> 16)) / 65535.0;
            float dist = length(site - f);
            if (dist < f1) { f2 = f1; f1 = dist; } else if (dist < f2) f2 = dist;
        }
    return clamp((f2 - f1) * 1.6, 0.0, 1.0);
}

// The facets a pixel sees when its waves are not all resolved: slopes of variance
// sigma^2 per axis about the resolved normal n, each weighted by the area it shows the
// viewer. At grazing angles the facets facing the viewer dominate (Bruneton, Neyret
// and Holzschuch 2010): the geometry shows this where it draws the waves, and the
// filtered far field must too. Quadrature: two slopes along the view's azimuth with the
// visible slopes' mean and deviation (`slopes`, from visible_slopes), each +-sigma across it.
struct VisibleFacets {
    vec3 normal;    // their mean normal
    float fresnel;  // their mean Fresnel reflectance
    vec3 sky;       // their mean Fresnel-weighted reflection of the sky
};

float schlick_fresnel(vec3 n, vec3 v) { return 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0); }

VisibleFacets visible_facets(vec3 n, vec3 v, float variance, vec2 slopes) {
    VisibleFacets f;
    float cos_view = clamp(dot(n, v), 1e-4, 1.0);
    vec3 flat_view = v - n * cos_view;  // v in the resolved facet's plane
    float in_plane = length(flat_view);
    if (variance <= 0.0 || in_plane < 1e-4) {
        f.normal = n;
        f.fresnel = schlick_fresnel(n, v);
        vec3 r = reflect(-v, n);
        r.y = abs(r.y);
        f.sky = f.fresnel * sky_color(r);
        return f;
    }
    vec3 along = flat_view / in_plane, across = normalize(cross(n, along));
    float sigma = sqrt(variance);
    f.normal = vec3(0.0);
    f.fresnel = 0.0;
    f.sky = vec3(0.0);
    for (int i = -1; i <= 1; i += 2)
        for (int j = -1; j <= 1; j += 2) {
            vec3 m = normalize(n + along * (slopes.x + float(i) * slopes.y) + across * (sigma * float(j)));
            float fresnel = schlick_fresnel(m, v);
            vec3 r = reflect(-v, m);
            r.y = abs(r.y);  // reflected down into the next wave: its mirror image
            f.normal += 0.25 * m;
            f.fresnel += 0.25 * fresnel;
            f.sky += 0.25 * fresnel * sky_color(r);
        }
    f.normal = normalize(f.normal);
    return f;
}

// How much of the pixel foam of amount `foam` (0..1) whitens. Fresh foam (near 1) is
// solid; thinner foam opens into lace (foam_lace, broken up by a finer gradient noise)
// that rides the water (rest coordinates move with the particles). Where the pixel
// cannot resolve the lace its edge widens to the whole range and the cover becomes a
// smooth function of `foam` alone (smoothstep(foam)): no sparkle far away, though thin
// distant foam shows less than its area share.
float foam_cover(float foam, vec2 xz, float footprint) {
    float broad = resolved(8.0, footprint), coarse = resolved(2.5, footprint), fine = resolved(0.7, footprint);
    // Warped so that the cells vary in size and shape; patches 8 m across stay solid or open.
    vec2 p = xz * 0.4;
    vec2 warp = vec2(gradient_noise(p * 0.5, 41u).x, gradient_noise(p * 0.5, 43u).x);
    float n = 0.5 + broad * 0.3 * gradient_noise(xz * 0.12, 47u).x +
              coarse * (0.6 * (foam_lace(p + 0.7 * warp) - 0.5) + 0.2 * fine * gradient_noise(xz * 1.4, 37u).x);
    float edge = mix(0.5, 0.1, coarse);
    // Thin lace lets some of the water through.
    return smoothstep(0.0, 1.0, (foam - n) / (2.0 * edge) + 0.5) * mix(0.75, 1.0, foam);
}

// Normal detail: every wave as much as the pixel resolves it, less what the geometry
// already draws (waves faded out of the mesh add slope; waves the mesh draws but the
// pixel cannot resolve, as at grazing angles, are taken back out), then ripples (the
// ocean's or a lake's) or a river's flow-mapped detail carried by its current. What the
// pixel cannot resolve adds to `variance` (slope variance, per axis) and to `hidden`.
// The same share changes the Jacobian (to first order, by minus the trace of their m):
// by `jacobian`; the lagged Jacobians (the foam particles remember) by `lagged`.
vec3 detail_normal(GpuBodyDraw d, WaveLod lod, float footprint, inout float variance, inout float jacobian, inout vec4 lagged,
                   inout HiddenWaves hidden) {
    SurfaceSums faded = surface_zero();
    LaggedCompression faded_lags = lagged_zero();
    bool river = uint(d.body.x) == kBodyRiver;
    uint first = uint(d.body.z), count = river ? 0u : uint(d.body.w);
    for (uint i = first; i < first + count; ++i) {
        GpuWave w = waves[i];
        vec2 kvec = w.dir_k_amp.xy * w.dir_k_amp.z;
        float drawn = wave_lod_weight(kvec, lod);
        float kept = pixel_keeps(kvec, lod);
        float slope_amplitude = w.dir_k_amp.z * w.dir_k_amp.w;
        float compression = w.steep_omega.x * slope_amplitude;  // Q k A
        float lost = 1.0 - kept * kept;
        add_hidden_wave(hidden, lost, w.dir_k_amp.w, slope_amplitude, compression, -dot(kvec, lod.toward), w.lag_turn.xy);
        float change = kept - drawn;
        if (abs(change) < 1e-3) continue;
        float theta = dot(kvec, rest_xz) + w.steep_omega.z;
        add_wave(faded, kvec, change * w.dir_k_amp.w, w.steep_omega.x, w.steep_omega.y, theta);
        add_wave_lags(faded_lags, kvec, change * w.dir_k_amp.w, w.steep_omega.x, w.lag_turn.xy, theta);
    }
    variance += hidden.slope_variance;  // the waves' share
    vec2 slope = faded.slope;
    jacobian -= faded.m.x + faded.m.z;
    lagged -= faded_lags.mxx + faded_lags.mzz;
    if (!river && d.ripple.x > 0.0) {
        // Ripple octaves: as slope where resolved, as variance where not.
        for (int o = 1; o <= int(d.ripple.z); ++o) {
            float drawn = resolved(1.0 / (float(o) * d.ripple.y), footprint);
            float octave_slope = d.ripple.x * d.ripple.y;  // (amplitude / o) * (o / wavelength)
            variance += (1.0 - drawn) * 0.5 * octave_slope * octave_slope;
        }
        slope += resolved(1.0 / d.ripple.y, footprint) * ripple_slope(rest_xz, d.ripple, d.ripple_offset);
    }
    if (river && d.flow.params.z > 0.0) slope += flow_detail_slope(rest_xz - d.grid.xy, current, d.flow);
    vec3 n = normalize(geo_normal);
    return normalize(n + vec3(-slope.x, 0.0, -slope.y));
}

void main() {
    if (!owns_water(draw_push.draw_index, rest_xz)) discard;
    GpuBodyDraw d = draws[draw_push.draw_index];
    float max_eta = max(d.extra.w, 1e-3);
    uint view = uint(frame.params.w);
    vec3 to_camera = frame.camera.xyz - world_pos;
    float distance = length(to_camera);
    vec3 v = to_camera / distance;
    WaveLod lod = wave_lod_at(rest_xz, d.body.y, d.lod.x);
    float footprint = lod.along;  // the footprint's longer side
    float variance = 0.0;
    float jacobian_detail = 0.0;
    vec4 lagged_detail = vec4(0.0);
    HiddenWaves hidden = hidden_zero();
    vec3 n = detail_normal(d, lod, footprint, variance, jacobian_detail, lagged_detail, hidden);
    if (dot(n, v) < 0.0) n = normalize(n + v * (0.01 - dot(n, v)));
    // The unresolved crests the viewer sees (before n turns to the visible facets' mean).
    float cos_view = clamp(dot(n, v), 1e-4, 1.0);
    float view_tangent = cos_view / max(sqrt(1.0 - cos_view * cos_view), 1e-4);
    vec2 seen = visible_heights(view_tangent, sqrt(hidden.slope_variance));
    // The facets seen: their slopes away from the viewer (mean, deviation), for the
    // reflection and for the foam that lingers on the faces the crests have passed.
    vec2 facet_slopes = visible_slopes(view_tangent, sqrt(variance));
    vec2 facing = vec2(0.0);
    if (variance > 0.0) facing = vec2(facet_slopes.x, 1.0 - facet_slopes.y * facet_slopes.y / variance) / variance;
    VisibleFacets facets = visible_facets(n, v, variance, facet_slopes);
    n = facets.normal;
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    bool has_scene = frame.options.x > 0.5;

    // Water column along the view ray, and what lies behind it.
    float column_depth = max(rest_level - terrain_height_at(world_pos.xz), 0.0);
    float thickness = column_depth / max(v.y, 0.15);
    vec3 behind = vec3(0.62, 0.56, 0.42) * 0.8;
    if (has_scene) {
        vec2 offset = n.xz * 0.04 * clamp(thickness / 4.0, 0.0, 1.0) / max(distance * 0.02, 1.0);
        vec2 ruv = clamp(uv + offset, vec2(0.0), vec2(1.0));
        vec3 floor_pos = world_from_depth(ruv, textureLod(scene_depth, ruv, 0.0).r);
        if (length(floor_pos - frame.camera.xyz) < distance) {  // refracted sample is above water: no offset
            ruv = uv;
            floor_pos = world_from_depth(ruv, textureLod(scene_depth, ruv, 0.0).r);
        }
        thickness = max(length(floor_pos - world_pos), 0.0);
        behind = from_scene_copy(textureLod(scene_color, ruv, 0.0).rgb);
    }
    vec3 transmittance = exp(-kAbsorption * thickness);
    vec3 refracted = behind * transmittance * kShallowTint / max(kShallowTint.g, 1e-3) + kDeepColor * (1.0 - transmittance);

    // Reflection: the sky, and the terrain by a short screen-space march.
    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    vec3 reflected = vec3(0.0);  // the terrain's, where the screen-space march meets it
    bool reflects_scene = false;  // the screen-space march hit the terrain
    if (has_scene) {
        vec3 p = world_pos;
        float step_len = max(distance * 0.02, 0.5);
        for (int i = 0; i < 24; ++i) {
            p += r * step_len;
            step_len *= 1.25;
            vec4 clip = frame.view_proj * vec4(p, 1.0);
            if (clip.w <= 0.0) break;
            vec3 ndc = clip.xyz / clip.w;
            vec2 suv = ndc.xy * 0.5 + 0.5;
            if (any(lessThan(suv, vec2(0.0))) || any(greaterThan(suv, vec2(1.0)))) break;
            float scene_z = textureLod(scene_depth, suv, 0.0).r;
            // Reversed Z: larger is nearer. A hit when the scene is in front of the ray point.
            if (scene_z > ndc.z && scene_z > 0.0) {
                // Bisect back along the last step to where the ray meets the scene, and
                // accept only a meeting within a few percent of its range: long steps
                // otherwise pass far behind hills and take their colour.
                vec3 lo = p - r * (step_len / 1.25), hi = p;
                for (int b = 0; b < 5; ++b) {
                    vec3 mid = 0.5 * (lo + hi);
                    vec4 mc = frame.view_proj * vec4(mid, 1.0);
                    vec3 mn = mc.xyz / mc.w;
                    float mz = textureLod(scene_depth, mn.xy * 0.5 + 0.5, 0.0).r;
                    if (mz > mn.z) hi = mid; else lo = mid;
                }
                vec4 hc = frame.view_proj * vec4(hi, 1.0);
                suv = clamp(hc.xy / hc.w * 0.5 + 0.5, vec2(0.0), vec2(1.0));
                p = hi;
                scene_z = textureLod(scene_depth, suv, 0.0).r;
                vec3 hit = world_from_depth(suv, scene_z);
                if (length(hit - p) < 0.03 * length(p - frame.camera.xyz) + 1.0) {
                    float edge = smoothstep(0.0, 0.1, min(min(suv.x, 1.0 - suv.x), min(suv.y, 1.0 - suv.y)));
                    reflected = mix(sky_color(r), from_scene_copy(textureLod(scene_color, suv, 0.0).rgb), edge);
                    reflects_scene = edge > 0.0;
                }
                break;
            }
        }
    }

    // The sky's reflection over the visible facets; the terrain's (screen-space) from the
    // mean facet.
    vec3 color = refracted * (1.0 - facets.fresnel) + facets.sky;
    if (reflects_scene) color = mix(refracted, reflected, schlick_fresnel(n, v));
    vec3 h = normalize(frame.sun.xyz + v);
    // Blinn-Phong sun glint widened by the unresolved slope variance; its energy is kept,
    // so a rough far field shows a broad, dimmer glitter path instead of sparkle.
    float shininess = 1.0 / (1.0 / 400.0 + variance);
    color += frame.sun.w * (shininess / 400.0) * pow(max(dot(n, h), 0.0), shininess) * vec3(2.4, 2.25, 2.0);

    // Subsurface light through thin crests facing away from the sun.
    float crest = clamp(eta / max_eta, 0.0, 1.0);
    float sss = pow(max(dot(v, -normalize(frame.sun.xyz + n * 0.5)), 0.0), 4.0) * crest;
    color += sss * vec3(0.06, 0.45, 0.38) * frame.sun.w;

    // Foam: whitecaps where the crests compress past the body's whitecap Jacobian (set by
    // the wind, Monahan's coverage), where waves break, and in bands along the coast that
    // run up the beach with the swash. Breaking foam rides the crests (and lingers thinly
    // in the troughs).
    float crest_band = smoothstep(-0.3, 0.5, eta / (max_eta * 0.25));
    // Fresh crest foam and what the particles' earlier crests left, fading
    // (tidewater::detail::surface_foam): a sum, so each part filters on its own.
    float crest_foam_here = seen_crest_foam(jacobian + jacobian_detail, hidden.compression_covariance, 0.0, hidden, seen, facing, d.extra.x);
    for (int l = 0; l < 4; ++l)
        crest_foam_here += seen_crest_foam(lagged_jacobian[l] + lagged_detail[l], hidden.lagged_covariance[l], hidden.lagged_slope_covariance[l],
                                           hidden, seen, facing, d.extra.x) *
                           foam_memory_weight(l + 1);
    float foam = max(min(crest_foam_here, 1.0), shore_info.y * (0.25 + 0.75 * crest_band));
    // Boats churn white water behind them (the wakes' turbulence, tidewater::detail::wakes_foam).
    if (uint(d.body.x) != kBodyRiver && WAKE_TURBULENT > 0u && wakes_reach(rest_xz)) foam = max(foam, wakes_foam_at(rest_xz));
    // A fast current churns white water.
    foam = max(foam, 0.6 * smoothstep(1.6, 3.2, length(current)) * smoothstep(0.3, 1.0, column_depth));
    if (d.shore.w > 0.0) {
        float d = shore_info.x;
        float swash = 0.5 + 0.5 * sin(d * 0.9 - frame.camera.w * 1.4);
        foam = max(foam, smoothstep(10.0, 0.0, d) * (0.35 + 0.65 * swash) * step(-1.0, d));
    }
    if (foam > 0.0) {
        float cover = foam_cover(foam, rest_xz + frame.origin_mod.xy, footprint);
        color = mix(color, vec3(0.92, 0.95, 0.96), cover);
    }
    color = apply_fog(color, distance, -v);

    if (view == kViewHeight) color = heat_color(0.5 + 0.5 * eta / max_eta);
    if (view == kViewNormals) color = n * 0.5 + 0.5;
    if (view == kViewJacobian) color = heat_color(1.0 - jacobian);
    if (view == kViewDepth) color = heat_color(column_depth / 40.0);
    if (view == kViewLod) color = heat_color(log2(vertex_spacing(distance) * 4.0) / 8.0);  // the vertex spacing (water_lod.glsl)
    if (view == kViewWireframe) color = vec3(0.02, 0.12, 0.3);
    if (view == kViewShore) color = heat_color(clamp(shore_info.x / 300.0, 0.0, 1.0));
    if (view == kViewBreaking) color = heat_color(shore_info.y);
    if (view == kViewFoam) color = vec3(clamp(foam, 0.0, 1.0));
    if (view == kViewWake) color = heat_color(0.5 + 0.5 * clamp(wake_eta, -1.0, 1.0));
    if (view == kViewFlow) color = uint(d.body.x) == kBodyRiver ? heat_color(length(current) / 3.0) : vec3(0.05, 0.08, 0.2);
    out_color = target_color(color);
}
