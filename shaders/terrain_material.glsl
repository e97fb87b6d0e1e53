// The terrain's own material and its light in the air: materials by height, slope and
// wetness (sand, wet sand where the swash runs, grass, rock on steep ground), detail
// normals and albedo variation that fade out where a footprint cannot resolve them. One
// place for the terrain pass and for the water's reflection of ground the camera does not
// see (scene_reflection.glsl). Needs frame.glsl.
#ifndef TIDEWATER_TERRAIN_MATERIAL_GLSL
#define TIDEWATER_TERRAIN_MATERIAL_GLSL

// Three octaves of gradient noise (40 m, 9 m, 2 m), each faded to its mean where
// unresolved: x the value (about -1..1), yz its slope per metre (for detail normals).
vec3 ground_detail(vec2 xz, float footprint) {
    vec3 sum = vec3(0.0);
    float size = 40.0, weight = 0.55;
    for (int o = 0; o < 3; ++o) {
        vec3 n = gradient_noise(xz / size, 71u + uint(o));
        sum += resolved(size, footprint) * weight * vec3(n.x, n.yz / size);
        size *= 0.22;
        weight *= 0.45;
    }
    return sum;
}

struct TerrainMaterial {
    vec3 albedo;
    vec3 n;      // the lit normal: the ground's, tilted by the detail
    float film;  // the swash's wet film over it (0..1)
    float rise;  // its height over the ocean's level, m
};

// The material at ground point `p` (relative to O) whose normal is `geo_n`, seen over a
// footprint of `footprint` m.
TerrainMaterial terrain_material(vec3 p, vec3 geo_n, float footprint) {
    float h = p.y;
    float level = frame.params.x;
    vec2 xz = p.xz + frame.origin_mod.xy;
    vec3 detail = ground_detail(xz, footprint);
    float slope = 1.0 - geo_n.y;

    // Materials. Boundaries wander with the broad noise so no contour line shows.
    vec3 sand = vec3(0.80, 0.72, 0.52) * (1.0 + 0.12 * detail.x);
    vec3 wet_sand = vec3(0.56, 0.49, 0.36);
    vec3 grass = mix(vec3(0.26, 0.44, 0.16), vec3(0.42, 0.47, 0.22), 0.5 + 0.5 * detail.x);  // lush to dry
    vec3 rock = vec3(0.44, 0.42, 0.40) * (1.0 + 0.25 * detail.x);
    float rise = h - level;
    vec3 base = mix(sand, grass, smoothstep(2.0, 6.0, rise + 2.5 * detail.x));
    // Rock where the ground is steep: cliffs, with horizontal strata.
    float rockiness = smoothstep(0.2, 0.34, slope + 0.08 * detail.x);
    float strata = 0.85 + 0.15 * sin(h * 2.1 + 3.0 * detail.x) * resolved(3.0, footprint);
    base = mix(base, rock * strata, rockiness);

    // Wet sand: soaked up to the swash's run-up R, drying over the next R/2, and a wet
    // film under the swash, whose top moves with the waves' period (the phase wanders
    // along the coast).
    float runup = frame.options.z;
    float swash_phase = frame.options.w * frame.camera.w - 6.2831 * gradient_noise(xz / 60.0, 79u).x;
    float swash_top = runup * (0.55 + 0.45 * sin(swash_phase));
    float soaked = runup > 0.0 ? smoothstep(1.5 * runup, runup, rise) : 0.0;
    float film = runup > 0.0 ? smoothstep(swash_top + 0.1 * runup, swash_top - 0.1 * runup, rise) : 0.0;
    float wetness = max(0.7 * soaked, film) * (1.0 - rockiness) * smoothstep(-1.5, -0.5, rise);
    base = mix(base, wet_sand, wetness);

    // Detail normals: the noise's slope tilts the mesh normal (faded where unresolved).
    vec3 n = normalize(geo_n - vec3(detail.y, 0.0, detail.z) * mix(1.0, 2.5, rockiness));
    return TerrainMaterial(base, n, film, rise);
}

// Its light: the sky's ambient and the sun's Lambert, each scaled per channel by what
// reaches it (1 in the air; under the water, what the water leaves and the caustics).
vec3 terrain_light(TerrainMaterial m, vec3 sky_lit, vec3 sun_lit) { return m.albedo * ground_light(m.n, sky_lit, sun_lit); }

#endif
