// The opaque scene a pixel of water reflects (water.frag), from the copy of the scene
// drawn before the water. The terrain is a height field, so it is met in world space:
// its silhouette along the reflected ray's azimuth says what share of the pixel's
// visible facets reflect it (their reflections spread in elevation), which filters the
// reflection's edge as the facets filter the sky instead of cutting it per pixel.
// Anything else opaque (floaters, a host's meshes) is met in screen space by the mean
// facet's ray alone.
#ifndef TIDEWATER_SCENE_REFLECTION_GLSL
#define TIDEWATER_SCENE_REFLECTION_GLSL
#include "frame.glsl"
#include "water_lod.glsl"
#include "water_quality.glsl"
#include "terrain_material.glsl"

struct SceneReflection {
    vec3 color;   // the scene's colour where the reflections meet it
    float share;  // the share of the pixel's reflection it takes (0..1); the sky has the rest
};

// The terrain at ground point `p` as the water reflects it from `range` m away, its
// reflections spread by `elevation_spread` (scene_reflection's). Where the camera sees p
// itself, the scene copy's colour there. Where it does not (it sees nearer ground in front
// of p, or the sky at a silhouette, or p lies off the screen), the terrain's own material
// and light at p (terrain_material.glsl, the terrain pass's), its detail softened over the
// footprint the reflections spread across, with the fog of its distance from the camera:
// a reflected hill is its own colour, not a texture from elsewhere in the frame.
SceneReflection terrain_seen_at(vec3 p, float range, float elevation_spread) {
    vec3 from_camera = p - frame.camera.xyz;
    float camera_distance = length(from_camera);
    vec4 clip = frame.view_proj * vec4(p, 1.0);
    if (clip.w > 0.0) {
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        float z = textureLod(scene_depth, clamp(uv, vec2(0.0), vec2(1.0)), 0.0).r;
        bool on_screen = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
        // The drawn mesh and the height field differ by a little: p is seen if the point
        // the screen shows there lies within a few percent of its distance.
        if (on_screen && z > 0.0 && length(world_from_depth(uv, z) - p) < 0.02 * camera_distance + 0.5)
            return SceneReflection(from_scene_copy(textureLod(scene_color, uv, 0.0).rgb), 1.0);
    }
    float footprint = max(range * elevation_spread, (range + camera_distance) / frame.params.z);
    TerrainMaterial ground = terrain_material(p, terrain_normal_at(p.xz, footprint), footprint);
    vec3 color = terrain_light(ground, vec3(1.0), vec3(1.0));
    return SceneReflection(apply_fog(color, camera_distance, from_camera / camera_distance), 1.0);
}

// The terrain's elevation tangent from `origin` at distance t along the ray r (its
// horizontal run `horizontal` per unit t).
float terrain_tangent(vec3 origin, vec3 r, float horizontal, float t) {
    vec3 p = origin + r * t;
    return (terrain_height_at(p.xz) - origin.y) / (t * horizontal);
}

// What the ray r (unit, upward) from water point `origin` reflects of the scene.
// `elevation_spread`: the deviation of the pixel's reflected rays' elevation tangents
// about r's (water.frag: the facets' slope deviation doubled in reflection, and the
// elevation's change to the next pixel). The march: kReflectionSteps steps (24 at
// `ultra`, 12 at `high`) growing by kReflectionStepGrowth (1.25 at 24 steps) from
// `first_step` m; the terrain's silhouette is then refined between the samples round its
// highest, so that it does not step with them.
SceneReflection scene_reflection(vec3 origin, vec3 r, float first_step, float elevation_spread) {
    float horizontal = max(length(r.xz), 1e-4);
    float ray_tangent = r.y / horizontal;
    float best_tangent = -1e9, best_t = 0.0, best_step = first_step;  // the highest sample
    float hit_before = -1.0, hit_t = -1.0;  // the step in which the mean ray goes under the terrain
    float t = 0.0, step_len = first_step;
    float highest = frame.terrain_heights.x;
    bool seek_ground = highest > origin.y, seek_screen = true;
    for (int i = 0; i < kReflectionSteps && (seek_ground || seek_screen); ++i) {
        float t_before = t;
        t += step_len;
        step_len *= kReflectionStepGrowth;
        vec3 p = origin + r * t;
        if (seek_ground) {
            float ground = terrain_height_at(p.xz);
            float tangent = (ground - origin.y) / (t * horizontal);
            if (tangent > best_tangent) {
                best_tangent = tangent;
                best_t = t;
                best_step = step_len / kReflectionStepGrowth;
            }
            if (hit_t < 0.0 && p.y < ground) {  // the mean ray goes under the terrain
                hit_before = t_before;
                hit_t = t;
                seek_screen = false;
            }
            // No ground further on can rise above the best seen: the highest ground
            // there subtends less.
            if ((highest - origin.y) / (t * horizontal) <= best_tangent) seek_ground = false;
        }
        if (!seek_screen) continue;
        // Something else opaque in front of the ray in screen space: met where the scene
        // there is not the terrain and lies within a few percent of the ray's range.
        vec4 clip = frame.view_proj * vec4(p, 1.0);
        vec3 ndc = clip.xyz / clip.w;
        vec2 uv = ndc.xy * 0.5 + 0.5;
        if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
            seek_screen = false;  // behind the camera or off the screen: nothing more to see there
            continue;
        }
        float scene_z = textureLod(scene_depth, uv, 0.0).r;
        if (scene_z > ndc.z && scene_z > 0.0) {  // reversed Z: larger is nearer
            // Bisect back along the step to where the ray meets it (long steps otherwise
            // pass far behind).
            float lo = t_before, hi = t;
            for (int b = 0; b < 5; ++b) {
                float mid = 0.5 * (lo + hi);
                vec4 mc = frame.view_proj * vec4(origin + r * mid, 1.0);
                vec3 mn = mc.xyz / mc.w;
                if (textureLod(scene_depth, mn.xy * 0.5 + 0.5, 0.0).r > mn.z) hi = mid; else lo = mid;
            }
            vec3 q = origin + r * hi;
            vec4 qc = frame.view_proj * vec4(q, 1.0);
            vec2 quv = clamp(qc.xy / qc.w * 0.5 + 0.5, vec2(0.0), vec2(1.0));
            vec3 seen = world_from_depth(quv, textureLod(scene_depth, quv, 0.0).r);
            if (abs(seen.y - terrain_height_at(seen.xz)) > 0.5 && length(seen - q) < 0.03 * length(q - frame.camera.xyz) + 1.0)
                return SceneReflection(from_scene_copy(textureLod(scene_color, quv, 0.0).rgb), 1.0);
        }
    }
    // Reflected rays never point down (a facet's reflection into the water is its mirror
    // image, water.frag): terrain that stays under the water's height is never met.
    if (best_tangent <= 0.0) return SceneReflection(vec3(0.0), 0.0);
    // The silhouette between the neighbouring samples: a golden-section search for the
    // highest tangent (the terrain is smooth between its texels).
    float a = max(best_t - best_step, 1e-3), b = best_t + kReflectionStepGrowth * best_step;
    for (int k = 0; k < 6; ++k) {
        float m1 = b - 0.618034 * (b - a), m2 = a + 0.618034 * (b - a);
        float t1 = terrain_tangent(origin, r, horizontal, m1), t2 = terrain_tangent(origin, r, horizontal, m2);
        if (t1 > t2) {
            b = m2;
            if (t1 > best_tangent) { best_tangent = t1; best_t = m1; }
        } else {
            a = m1;
            if (t2 > best_tangent) { best_tangent = t2; best_t = m2; }
        }
    }
    float share = normal_cdf((best_tangent - ray_tangent) / elevation_spread);
    // Its colour where the mean ray meets the terrain (bisected), or at the silhouette,
    // which the facets that reflect lower still meet.
    vec3 meets = origin + r * best_t;
    if (hit_t >= 0.0) {
        float lo = hit_before, hi = hit_t;
        for (int k = 0; k < 5; ++k) {
            float mid = 0.5 * (lo + hi);
            vec3 m = origin + r * mid;
            if (m.y < terrain_height_at(m.xz)) hi = mid; else lo = mid;
        }
        meets = origin + r * hi;
    }
    SceneReflection seen =
        terrain_seen_at(vec3(meets.x, terrain_height_at(meets.xz), meets.z), length(meets - origin), elevation_spread);
    seen.share *= share;
    return seen;
}
#endif
