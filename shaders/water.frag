#version 450
// Water shading (seed 004): depth colour and refraction from the copy of the
// opaque scene, Schlick Fresnel, sky and sun, screen-space reflection of the
// terrain, subsurface scattering at crests, foam where the Jacobian folds. What a
// pixel cannot resolve is filtered: the waves' slopes into the facets it sees
// (visible_facets.glsl), their compression into its foam (foam_filter.glsl), the
// foam's lace by its footprint (foam_cover.glsl).
#extension GL_GOOGLE_include_directive : require
#include "host_device.h"
#include "frame.glsl"
#include "water_lod.glsl"
#include "water_point.glsl"
#include "water_draw.glsl"
#include "body_masks.glsl"
#include "water_quality.glsl"
#include "flow_detail.glsl"
#define WAKE_COUNT uint(frame.wakes.x)
#define WAKE_TURBULENT uint(frame.wakes.y)
#include "wake_point.glsl"
#include "foam_filter.glsl"
#include "foam_cover.glsl"
#include "visible_facets.glsl"
#include "scene_reflection.glsl"
#include "water_medium.glsl"
#include "clip_volumes.glsl"
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
layout(location = 10) WATER_IN vec4 hidden_in;
layout(location = 11) WATER_IN vec4 hidden_lagged_in;
layout(location = 12) WATER_IN vec4 hidden_lagged_slope_in;
layout(location = 0) out vec4 out_color;

// Detail shorter than a few footprints (wave_lod_at) cannot be drawn: it goes into the
// slope variance instead (LEAN-style), which widens the sun's glitter and leaves the
// averaged reflection, as the supersampled picture shows, instead of aliasing.
// Normal detail: every wave as much as the pixel resolves it, less what the geometry
// already draws (waves faded out of the mesh add slope; waves the mesh draws but the
// pixel cannot resolve, as at grazing angles, are taken back out), then ripples (the
// ocean's or a lake's) or a river's flow-mapped detail carried by its current. What the
// pixel cannot resolve adds to `variance` (slope variance, per axis):
// `hidden_slope_variance`, summed at the patch's corners (hidden_waves_at), is the waves'
// share, and all of a wave the tier does not draw (QualitySettings::waves_drawn).
// The same share changes the Jacobian (to first order, by minus the trace of their m):
// by `jacobian`; the lagged Jacobians (the foam particles remember) by `lagged`.
// `fine`: the ripples' or flow detail's drawn slope and its slope variance per axis, which
// the scene's reflection filters instead of following (scene_reflection.glsl).
struct FineDetail {
    vec2 slope;
    float variance;
};
vec3 detail_normal(GpuBodyDraw d, WaveLod lod, float footprint, inout float variance, inout float jacobian, inout vec4 lagged,
                   float hidden_slope_variance, out FineDetail fine) {
    SurfaceSums faded = surface_zero();
    vec4 faded_lag_trace = vec4(0.0);
    bool river = uint(d.body.x) == kBodyRiver;
    uint first = uint(d.body.z), count = river ? 0u : uint(d.body.w);
    for (uint i = first; i < first + count; ++i) {
        GpuWave w = waves[i];
        if (wave_left_to_variance(w)) continue;
        vec2 kvec = w.dir_k_amp.xy * w.dir_k_amp.z;
        float drawn = wave_lod_weight(kvec, lod);
        float kept = pixel_keeps(kvec, lod);
        float change = kept - drawn;
        if (abs(change) < 1e-3) continue;
        float theta = dot(kvec, rest_xz) + w.steep_omega.z;
        add_wave(faded, kvec, change * w.dir_k_amp.w, w.steep_omega.x, w.steep_omega.y, theta);
        faded_lag_trace += wave_lagged_trace(kvec, change * w.dir_k_amp.w, w.steep_omega.x, w.lag_turn.xy, theta);
    }
    variance += hidden_slope_variance;  // the waves' share
    jacobian -= faded.m.x + faded.m.z;
    lagged -= faded_lag_trace;
    fine = FineDetail(vec2(0.0), 0.0);
    if (!river && d.ripple.x > 0.0) {
        // Ripple octaves: as slope where resolved, as variance where not.
        float shown = resolved(1.0 / d.ripple.y, footprint);
        for (int o = 1; o <= int(d.ripple.z); ++o) {
            float drawn = resolved(1.0 / (float(o) * d.ripple.y), footprint);
            float octave_slope = d.ripple.x * d.ripple.y;  // (amplitude / o) * (o / wavelength)
            variance += (1.0 - drawn) * 0.5 * octave_slope * octave_slope;
            fine.variance += shown * shown * 0.5 * octave_slope * octave_slope;
        }
        fine.slope = shown * ripple_slope(rest_xz, d.ripple, d.ripple_offset);
    }
    if (river && d.flow.params.z > 0.0) {
        fine.slope = flow_detail_slope(rest_xz - d.grid.xy, current, d.flow);
        float detail_slope = d.flow.params.x * d.flow.params.z;  // tiling x strength
        fine.variance = 0.5 * detail_slope * detail_slope;
    }
    vec2 slope = faded.slope + fine.slope;
    vec3 n = normalize(geo_normal);
    return normalize(n + vec3(-slope.x, 0.0, -slope.y));
}

// The surface seen from under it, `distance` m from the eye in direction -v: the world
// above through Snell's window (the sky, or land above the water that the opaque pass
// drew behind this pixel), the water below by total internal reflection outside it, the
// breaking foam from below, then the water along the path back to the eye.
vec3 seen_from_below(vec3 n, vec3 v, float distance) {
    SurfaceFromBelow s = surface_from_below(n, v);
    vec3 inscatter = water_inscatter(frame.underwater.y);
    vec3 above = vec3(0.0);
    if (s.reflectance < 1.0) {
        above = sky_seen(s.transmitted);  // the sky table: the transmitted ray rises
        if (frame.options.x > 0.5) {
            vec2 uv = view_uv();
            float behind_depth = textureLod(scene_depth, uv, 0.0).r;
            if (behind_depth > 0.0 && world_from_depth(uv, behind_depth).y > world_pos.y)
                above = from_scene_copy(textureLod(scene_color, uv, 0.0).rgb);
        }
    }
    vec3 color = mix(above, inscatter, s.reflectance);
    // Breaking foam is white from below too, lit by what reaches the surface.
    float crest_band = smoothstep(-0.3, 0.5, eta / (max(draws[draw_push.draw_index].extra.w, 1e-3) * 0.25));
    color = mix(color, vec3(0.85) * frame.sun.w, 0.6 * shore_info.y * (0.25 + 0.75 * crest_band));
    return through_water(camera_water(), color, distance, inscatter);
}

void main() {
    // Water behind the opaque scene (the sea under the land) leaves before it is shaded:
    // the ownership test below keeps the depth test after the shader, where hardware may not
    // reject it early.
    if (frame.water_density.z > 0.5 && gl_FragCoord.z < texelFetch(scene_depth, ivec2(view_pixel()), 0).r) discard;
    if (!owns_water(draw_push.draw_index, rest_xz)) discard;
    if (inside_clip_volumes(world_pos)) discard;  // a dry hull, a host's clip volume
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
    HiddenWaves hidden = hidden_waves_unpacked(hidden_in, hidden_lagged_in, hidden_lagged_slope_in);
    FineDetail fine;
    vec3 n = detail_normal(d, lod, footprint, variance, jacobian_detail, lagged_detail, hidden.slope_variance, fine);
    if (pixel_under_water() && view == kViewShaded) {  // the debug views show the same from both sides
        out_color = target_color(with_water_line(seen_from_below(n, v, distance)));
        return;
    }
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
    // The water column under this point.
    float column_depth = max(rest_level - terrain_height_at(world_pos.xz), 0.0);

    // Foam, here so that the lags' twelve numbers are done with before the reflections:
    // whitecaps where the crests compress past the body's whitecap Jacobian (set by the
    // wind, Monahan's coverage), where waves break, and in bands along the coast that run
    // up the beach with the swash. Breaking foam rides the crests (and lingers thinly in
    // the troughs).
    float crest_band = smoothstep(-0.3, 0.5, eta / (max_eta * 0.25));
    // Fresh crest foam and what the particles' earlier crests left, fading
    // (tidewater::detail::surface_foam): a sum, so each part filters on its own.
    vec2 lag_spread[kFoamLags];
    for (int l = 0; l < int(kFoamLagsShown); ++l)
        lag_spread[l] = seen_crest_spread(lagged_jacobian[l] + lagged_detail[l], hidden.lagged_covariance[l], hidden.lagged_slope_covariance[l],
                                          hidden, seen, facing);
    float crest_foam_here = seen_crest_foam(seen_crest_spread(jacobian + jacobian_detail, hidden.compression_covariance, 0.0, hidden, seen, facing),
                                            d.extra.x);
    for (int l = 0; l < int(kFoamLagsShown); ++l) crest_foam_here += seen_crest_foam(lag_spread[l], d.extra.x) * foam_memory_weight(l + 1);
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
    float cover = foam > 0.0 ? foam_cover(foam, rest_xz + frame.origin_mod.xy, footprint) : 0.0;
    VisibleFacets facets = visible_facets(n, v, variance, facet_slopes);
    n = facets.normal;
    vec2 uv = view_uv();
    bool has_scene = frame.options.x > 0.5;

    // Water column along the view ray, and what lies behind it.
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
    WaterOptics water = WaterOptics(d.optics_extinction.xyz, d.optics_color.xyz);
    vec3 refracted = through_water(water, behind, thickness, water.color);

    // Reflection: the sky over the visible facets, and the opaque scene where their
    // reflections meet it (scene_reflection.glsl), under the same Fresnel.
    vec3 color = refracted * (1.0 - facets.fresnel) + facets.sky;
    if (has_scene && kSceneReflection) {  // the same for every fragment: derivatives stay defined
        // The scene's reflection follows the waves' facets; the ripples' (or a river's
        // detail's) drawn slope would scatter a far hill's reflection pixel by pixel, so it
        // joins the spread.
        vec3 r = reflect(-v, normalize(n + vec3(fine.slope.x, 0.0, fine.slope.y)));
        r.y = abs(r.y);
        float reflected_tangent = r.y / max(length(r.xz), 1e-4);
        float reflected_change = length(vec2(dFdx(reflected_tangent), dFdy(reflected_tangent)));  // per pixel
        // Beside a discarded neighbour (another body's water) the difference is undefined.
        if (!(reflected_change < 1.0)) reflected_change = 1.0;
        // Reflection doubles a facet's tilt, so the spread of the facets' slopes along the
        // view (the visible ones' and the fine detail's) spreads the reflected elevations by
        // twice it; across the pixel they change as they do to the next pixel (the
        // mirror's own angle, the waves' curvature): a box that wide, of deviation the
        // width over sqrt(12).
        float slope_spread2 = facet_slopes.y * facet_slopes.y + fine.variance;
        float spread = sqrt(4.0 * slope_spread2 + reflected_change * reflected_change / 12.0);
        SceneReflection scene = scene_reflection(world_pos, r, max(distance * 0.02, 0.5), max(spread, 1e-4));
        color = mix(color, refracted * (1.0 - facets.fresnel) + facets.fresnel * scene.color, scene.share);
    }
    vec3 h = normalize(frame.sun.xyz + v);
    // Blinn-Phong sun glint widened by the unresolved slope variance; its energy is kept,
    // so a rough far field shows a broad, dimmer glitter path instead of sparkle.
    float shininess = 1.0 / (1.0 / 400.0 + variance);
    color += frame.sun.w * (shininess / 400.0) * pow(max(dot(n, h), 0.0), shininess) * vec3(2.4, 2.25, 2.0);

    // Subsurface light through thin crests facing away from the sun.
    float crest = clamp(eta / max_eta, 0.0, 1.0);
    float sss = pow(max(dot(v, -normalize(frame.sun.xyz + n * 0.5)), 0.0), 4.0) * crest;
    color += sss * vec3(0.06, 0.45, 0.38) * frame.sun.w;

    color = mix(color, vec3(0.92, 0.95, 0.96), cover);
    color = apply_fog(color, distance, -v);

    if (view != kViewShaded) {  // the debug views, in one branch the shaded picture skips
        float t = 0.0;              // what a heat view shows, 0..1
        if (view == kViewHeight) t = 0.5 + 0.5 * eta / max_eta;
        else if (view == kViewJacobian) t = 1.0 - jacobian;
        else if (view == kViewDepth) t = column_depth / 40.0;
        else if (view == kViewLod) t = log2(lod.spacing_along * 4.0) / 8.0;  // the vertex spacing along the view (water_lod.glsl)
        else if (view == kViewShore) t = shore_info.x / 300.0;
        else if (view == kViewBreaking) t = shore_info.y;
        else if (view == kViewWake) t = 0.5 + 0.5 * clamp(wake_eta, -1.0, 1.0);
        else if (view == kViewFlow) t = length(current) / 3.0;
        color = heat_color(t);
        if (view == kViewNormals) color = n * 0.5 + 0.5;
        if (view == kViewWireframe) color = vec3(0.02, 0.12, 0.3);
        if (view == kViewFoam) color = vec3(clamp(foam, 0.0, 1.0));
        if (view == kViewFlow && uint(d.body.x) != kBodyRiver) color = vec3(0.05, 0.08, 0.2);
    }
    color = with_water_line(color);
    out_color = target_color(color);
}
