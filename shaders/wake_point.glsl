// The water a disturbance makes: the GLSL twin of
// runtime/core/private/tidewater/detail/wake_point.hpp (the formula) and of add_wakes /
// wakes_foam in runtime/core/src/water/wake_water.hpp (the walk along the chains).
// Constants come from host_device.h. The includer declares wake_points[] (GpuWakePoint,
// positions relative to the render origin O) and defines WAKE_COUNT (points) and
// WAKE_TURBULENT (how many of the first points belong to chains that carry turbulence).
#ifndef TIDEWATER_WAKE_POINT_GLSL
#define TIDEWATER_WAKE_POINT_GLSL

struct WakeWave {
    vec2 kvec;    // local wavevector, away from the disturbance, rad/m
    float a;      // amplitude per unit impulse, m per m^4/s
    float omega;  // rad/s
    float theta;  // phase, rad
};

// The unit pulse's wave at offset d (m) from a disturbance of source size `size` (m)
// made `age` seconds ago (tidewater::detail::wake_wave).
WakeWave wake_wave(vec2 d, float age, float size) {
    float spread = size * (1.0 / 6.2831853);
    float r2 = dot(d, d) + spread * spread;
    float inv_r = inversesqrt(r2 > 0.0 ? r2 : 1.0);
    float tau = max(age, 0.0);
    float k = 0.25 * kWakeGravity * tau * tau * inv_r * inv_r;
    WakeWave w;
    w.theta = -0.25 * kWakeGravity * tau * tau * inv_r;
    w.omega = 0.5 * kWakeGravity * tau * inv_r;
    float filter_ = exp(-k * k * spread * spread);
    float near = 1.0 - exp(-0.25 * w.theta * w.theta);
    w.a = (1.0 / (1.4142136 * 3.1415927 * sqrt(kWakeGravity))) * k * sqrt(k) * filter_ * near * inv_r;
    w.kvec = k * d * inv_r;
    return w;
}

// Adds the wave `w` carrying `impulse` (m^4/s) with steepness q, Q k A held to
// kWakeFoldLimit (tidewater::detail::wake_term).
void add_wake_wave(inout SurfaceSums s, WakeWave w, float impulse, float q) {
    float a = impulse * w.a;
    float ka = length(w.kvec) * a;
    float q_held = q * ka > kWakeFoldLimit ? kWakeFoldLimit / (ka > 0.0 ? ka : 1.0) : q;
    add_wave(s, w.kvec, a, q_held, w.omega, w.theta);
}

float wake_sinc(float x) {
    float small = x * x;
    return small > 1e-8 ? sin(x) / x : 1.0 - small / 6.0;
}

// A chain's segment between two disturbances (tidewater::detail::add_wake_segment).
void add_wake_segment(inout SurfaceSums s, WakeWave wa, WakeWave wb, float pa, float pb, float qa, float qb, float duration) {
    WakeWave mean;
    mean.kvec = 0.5 * (wa.kvec + wb.kvec);
    mean.omega = 0.5 * (wa.omega + wb.omega);
    mean.theta = 0.5 * (wa.theta + wb.theta);
    mean.a = 0.5 * (pa * wa.a + pb * wb.a);
    add_wake_wave(s, mean, duration * wake_sinc(0.5 * (wb.theta - wa.theta)), 0.5 * (qa + qb));
}

// Turbulence foam at distance d from a disturbance (tidewater::detail::wake_foam).
float wake_foam(float d, float age, float size, float turbulence) {
    float tau = max(age, 0.0);
    float x = d / (0.5 * size + kWakeFoamSpread * sqrt(tau));
    return turbulence * exp(-tau / kWakeFoamLifetime - x * x);
}

// Every chain segment and lone point at rest position xz (relative to O).
SurfaceSums wakes_at(vec2 xz) {
    SurfaceSums s = surface_zero();
    WakeWave last;
    for (uint i = 0u; i < WAKE_COUNT; ++i) {
        GpuWakePoint p = wake_points[i];
        WakeWave here = wake_wave(xz - p.position_age.xy, p.position_age.z, p.shape.x);
        bool after = i > 0u && wake_points[i - 1u].shape.w > 0.5;
        bool before = p.shape.w > 0.5;
        if (after) {
            GpuWakePoint o = wake_points[i - 1u];
            add_wake_segment(s, last, here, o.position_age.w, p.position_age.w, o.shape.y, p.shape.y, o.position_age.z - p.position_age.z);
        } else if (!before) {
            add_wake_wave(s, here, p.position_age.w, p.shape.y);
        }
        last = here;
    }
    return s;
}

// The foam the wakes' turbulence leaves at xz: the most of any segment's or lone point's.
float wakes_foam_at(vec2 xz) {
    float foam = 0.0;
    for (uint i = 0u; i < WAKE_TURBULENT; ++i) {
        GpuWakePoint p = wake_points[i];
        bool before = p.shape.w > 0.5 && i + 1u < WAKE_COUNT;
        vec2 rel = xz - p.position_age.xy;
        float f = 0.0;
        if (before) {
            GpuWakePoint b = wake_points[i + 1u];
            vec2 seg = b.position_age.xy - p.position_age.xy;
            float len2 = dot(seg, seg);
            float t = len2 > 0.0 ? clamp(dot(rel, seg) / len2, 0.0, 1.0) : 0.0;
            f = wake_foam(length(rel - t * seg), mix(p.position_age.z, b.position_age.z, t), mix(p.shape.x, b.shape.x, t),
                          mix(p.shape.z, b.shape.z, t));
        } else if (!(i > 0u && wake_points[i - 1u].shape.w > 0.5)) {
            f = wake_foam(length(rel), p.position_age.z, p.shape.x, p.shape.z);
        }
        foam = max(foam, f);
    }
    return foam;
}

#endif
