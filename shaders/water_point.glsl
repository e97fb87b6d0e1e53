// The water at one rest position: the GLSL twin of
// runtime/core/include/tidewater/detail/water_point.hpp (the sums) and
// runtime/core/src/water/newton.hpp (the Eulerian solve). Constants come from
// host_device.h. A body, shore, current or wake changes what a wave's wavevector,
// amplitude, steepness and phase are at a point (water_body.glsl); it never writes
// these sums again.
#ifndef TIDEWATER_WATER_POINT_GLSL
#define TIDEWATER_WATER_POINT_GLSL

struct SurfaceSums {
    vec2 disp;      // sum Q A D cos
    vec3 m;         // sum Q A k sin * (Dx Dx, Dx Dz, Dz Dz)
    float eta;      // sum A sin
    vec2 slope;     // sum A K cos
    vec3 velocity;  // (sum Q A w Dx sin, -sum A w cos, sum Q A w Dz sin)
};

SurfaceSums surface_zero() {
    SurfaceSums s;
    s.disp = vec2(0.0);
    s.m = vec3(0.0);
    s.eta = 0.0;
    s.slope = vec2(0.0);
    s.velocity = vec3(0.0);
    return s;
}

// One wave with local wavevector K = k D (rad/m), amplitude a (m), steepness q and
// angular frequency omega, at phase theta. Zero amplitude adds exactly nothing.
// `m_gain` scales the wave's compression (the sums m) alone: 1 but for the render's
// vertices (wave_lod_shares).
void add_wave_compressing(inout SurfaceSums s, vec2 kvec, float a, float q, float omega, float theta, float m_gain) {
    float k = length(kvec);
    vec2 d = kvec / (k > 0.0 ? k : 1.0);
    float sn = sin(theta);
    float cs = cos(theta);
    float qa = q * a;
    s.disp += qa * d * cs;
    s.m += m_gain * qa * k * sn * vec3(d.x * d.x, d.x * d.y, d.y * d.y);
    s.eta += a * sn;
    s.slope += a * kvec * cs;
    s.velocity += vec3(qa * omega * d.x * sn, -a * omega * cs, qa * omega * d.y * sn);
}
void add_wave(inout SurfaceSums s, vec2 kvec, float a, float q, float omega, float theta) {
    add_wave_compressing(s, kvec, a, q, omega, theta, 1.0);
}

// The compression a particle's crest had earlier (tidewater::detail::LaggedCompression):
// the sums m at the kFoamLags lags tau_l = l * kFoamLagStep s ago (l = 1..4, one per
// component), at the same rest position. Each wave's phase then was theta + omega tau:
// (sin, cos) theta turns by omega kFoamLagStep per lag; `turn` holds that angle's sine and
// cosine (GpuWave.lag_turn, formed once per wave on the host).
struct LaggedCompression {
    vec4 mxx, mxz, mzz;
};

LaggedCompression lagged_zero() { return LaggedCompression(vec4(0.0), vec4(0.0), vec4(0.0)); }

// sin(theta - l omega kFoamLagStep) for l = 1..4: the wave's phase at each lag.
vec4 lagged_sines(float theta, vec2 turn) {
    float sn = sin(theta), cs = cos(theta);
    float step_sin = turn.x, step_cos = turn.y;
    vec4 lagged_sin;
    for (int l = 0; l < 4; ++l) {
        float s = sn * step_cos + cs * step_sin;
        cs = cs * step_cos - sn * step_sin;
        sn = s;
        lagged_sin[l] = s;
    }
    return lagged_sin;
}

void add_wave_lags(inout LaggedCompression c, vec2 kvec, float a, float q, vec2 turn, float theta) {
    float k = length(kvec);
    vec2 d = kvec / (k > 0.0 ? k : 1.0);
    vec3 coeff = q * a * k * vec3(d.x * d.x, d.x * d.y, d.y * d.y);
    vec4 lagged_sin = lagged_sines(theta, turn);
    c.mxx += coeff.x * lagged_sin;
    c.mxz += coeff.y * lagged_sin;
    c.mzz += coeff.z * lagged_sin;
}

void add_scaled(inout LaggedCompression c, LaggedCompression b, float w) {
    c.mxx += w * b.mxx;
    c.mxz += w * b.mxz;
    c.mzz += w * b.mzz;
}

// A wave's share of the trace mxx + mzz at each lag (to first order the Jacobian falls by
// it): Q A k times its lagged sines. What a pixel adds for the waves its mesh fades out.
vec4 wave_lagged_trace(vec2 kvec, float a, float q, vec2 turn, float theta) { return q * a * length(kvec) * lagged_sines(theta, turn); }

// The Jacobian determinant at each lag.
vec4 lagged_jacobians(LaggedCompression c) { return (1.0 - c.mxx) * (1.0 - c.mzz) - c.mxz * c.mxz; }

// How much of its crest foam a particle keeps lag l (1..4) later
// (tidewater::detail::foam_memory_weight): exp(-l kFoamLagStep / kFoamDecayTime).
float foam_memory_weight(int lag) { return exp(-float(lag) * kFoamLagStep / kFoamDecayTime); }

// Jacobian of the horizontal map [[jxx, jxz], [jxz, jzz]]: xyz = (jxx, jxz, jzz).
vec3 surface_jacobian_matrix(SurfaceSums s) {
    return vec3(1.0 - s.m.x, -s.m.y, 1.0 - s.m.z);
}
float surface_jacobian(SurfaceSums s) {
    vec3 j = surface_jacobian_matrix(s);
    return j.x * j.z - j.y * j.y;
}
// Normal of the displaced surface: Tz x Tx with Tx = (jxx, sx, jxz), Tz = (jxz, sz, jzz).
vec3 surface_normal(SurfaceSums s) {
    vec3 j = surface_jacobian_matrix(s);
    return normalize(cross(vec3(j.y, s.slope.y, j.z), vec3(j.x, s.slope.x, j.y)));
}

// Foam from crests compressing across the body's whitecap Jacobian (tidewater::crest_foam).
float crest_foam(float jacobian, float whitecap_jacobian) {
    float half_width = 0.5 * kFoamRampFraction * max(1.0 - whitecap_jacobian, 0.0);
    if (half_width <= 0.0) return jacobian < whitecap_jacobian ? 1.0 : 0.0;
    return smoothstep(whitecap_jacobian + half_width, whitecap_jacobian - half_width, jacobian);
}

// Render LOD, seed 000's "fewer waves far away": a wave keeps full amplitude while its
// wavelength spans 4+ vertices, none below 2; continuous in space (no seams, no popping).
// `vertex_phase`: the phase the wave turns through from one vertex to the next (rad).
float wave_lod_fade(float vertex_phase) {
    return smoothstep(2.0, 4.0, 6.2831853 / max(vertex_phase, 1e-6));
}

// Render LOD at a point of water: the vertex spacing across the view (m; 0 for no LOD, as
// queries) and along it (m), and the footprint of a pixel there on the rest plane: one
// pixel across the view (m), and along it (m), stretched by the angle at which the view
// meets the water (wave_lod_at); `toward` is the horizontal direction to the camera.
// The vertices are a fixed number of pixels apart on screen, so along the view they
// are as much further apart on the water as the pixel's footprint is longer.
struct WaveLod {
    float spacing;
    float spacing_along;
    vec2 toward;
    float along;
    float across;
};

WaveLod no_wave_lod() { return WaveLod(0.0, 0.0, vec2(1.0, 0.0), 0.0, 0.0); }

// The share of a wave that survives a pixel's average over its footprint: the box
// filter's sinc(x / 2) in its Gaussian fit exp(-x^2 / 24) (no negative lobes), x the
// phase the wave turns through from one pixel to the next along and across the view.
// Anisotropic: at grazing angles waves running toward the camera fade first.
float pixel_keeps(vec2 kvec, WaveLod lod) {
    float along = dot(kvec, lod.toward) * lod.along;
    float across = dot(kvec, vec2(-lod.toward.y, lod.toward.x)) * lod.across;
    return exp(-(along * along + across * across) / 24.0);
}

// The share of a wave the mesh draws: what the vertices resolve (wave_lod_fade) and the
// pixel resolves (pixel_keeps); the rest goes into the shading's slope variance, so that
// geometry hands over to the filtered normal distribution without aliasing.
// x: that share (wave_lod_weight). y: the gain on the wave's compression at the vertices.
// Between vertices the mesh interpolates linearly, which keeps sinc^2(phi / 2) of a wave
// turning phi from one vertex to the next (a triangle filter's response), and the foam
// reads the interpolated Jacobian past a threshold: without a gain it thinned as the
// vertices spread out. The vertices carry each wave's compression over sinc(phi / 2),
// halfway between no gain and the filter's inverse (which overshoots at the vertices): the
// whitecap cover looking down on ocean_rolling then stays within 9% from 1.5 to 6 pixels
// per vertex (0.0122, 0.0112, 0.0114 of the pixels; without the gain 0.0117, 0.0092,
// 0.0082; docs/PERFORMANCE.md).
vec2 wave_lod_shares(vec2 kvec, WaveLod lod) {
    if (lod.spacing <= 0.0) return vec2(1.0);
    float vertex_phase = length(vec2(dot(kvec, lod.toward) * lod.spacing_along,
                                     dot(kvec, vec2(-lod.toward.y, lod.toward.x)) * lod.spacing));
    float half_phase = min(0.5 * vertex_phase, 1.5707963);  // past pi the wave is faded out
    float sinc = half_phase > 1e-3 ? sin(half_phase) / half_phase : 1.0;
    return vec2(wave_lod_fade(vertex_phase) * pixel_keeps(kvec, lod), 1.0 / sinc);
}
float wave_lod_weight(vec2 kvec, WaveLod lod) { return wave_lod_shares(kvec, lod).x; }

float newton_tolerance(float max_offset) {
    return max(kNewtonToleranceFloor, kNewtonToleranceScale * max_offset);
}
float newton_radius(float max_offset) {
    return max_offset * kNewtonRadiusSlack + kNewtonRadiusFloor;
}

#ifdef TW_WATER_NEWTON
// The includer defines the water at rest offset e from its query point, and whether its
// sums' Jacobian is the map's (the open sea: no secant correction; sums_jacobian_exact).
SurfaceSums water_at_offset(vec2 e);
bool water_sums_jacobian_exact();

struct NewtonResult {
    SurfaceSums sums;  // at the last evaluation
    vec2 step_e;       // the Newton step from it (results carry it to first order)
    vec2 e;            // the rest offset of that evaluation
    float iterations;
    float converged;
};

// Solves e + d(p + e) = 0 for the rest offset e = x0 - p: the same steps, secant
// correction (SecantCorrection), stopping rule, back-off and radius as solve_rest_offset
// in newton.hpp.
NewtonResult solve_rest_offset(float tolerance, float radius) {
    NewtonResult r;
    r.e = vec2(0.0);
    r.iterations = 0.0;
    r.converged = 0.0;
    vec2 last_e = vec2(0.0);
    float last_f2 = 3.0e38;
    // The secant's correction C (columns: d/dex, d/dez) and the last evaluation's e, F and
    // sums' Jacobian (xx, xz, zz).
    mat2 c = mat2(0.0);
    vec2 prev_e = vec2(0.0), prev_f = vec2(0.0);
    vec3 prev_j = vec3(0.0);
    float min_step2 = 0.01 * tolerance * tolerance;
    bool secant = !water_sums_jacobian_exact();
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        r.sums = water_at_offset(r.e);
        r.iterations += 1.0;
        vec3 j = surface_jacobian_matrix(r.sums);
        vec2 f = r.e + r.sums.disp;
        if (secant && it > 0) {
            vec2 de = r.e - prev_e;
            float de2 = dot(de, de);
            if (de2 > min_step2) {
                vec3 m = 0.5 * (j + prev_j);
                vec2 miss = (f - prev_f) - (mat2(m.x, m.y, m.y, m.z) + c) * de;
                c += outerProduct(miss / de2, de);
            }
        }
        prev_e = r.e;
        prev_f = f;
        prev_j = j;
        mat2 jc = mat2(j.x, j.y, j.y, j.z) + c;
        float det = jc[0][0] * jc[1][1] - jc[1][0] * jc[0][1];
        // -(jc^-1) f, with jc[col][row].
        r.step_e = vec2(jc[1][0] * f.y - jc[1][1] * f.x, jc[0][1] * f.x - jc[0][0] * f.y) / det;
        float f2 = dot(f, f);
        if (f2 <= tolerance * tolerance) {
            r.converged = 1.0;
            break;
        }
        if (it + 1 == kMaxNewtonIterations) break;  // reported unconverged
        bool grew = f2 > last_f2;
        vec2 next_e = grew ? 0.5 * (r.e + last_e) : r.e + r.step_e;
        if (!grew) {
            last_e = r.e;
            last_f2 = f2;
        }
        float r2 = dot(next_e, next_e);
        if (r2 > radius * radius) next_e *= sqrt(radius * radius / r2);
        r.e = next_e;
    }
    return r;
}
#endif

#endif
