// The water a disturbance makes: the GLSL twin of
// runtime/core/private/tidewater/detail/wake_point.hpp (the formula) and of add_wakes /
// wakes_foam in runtime/core/src/water/wake_water.hpp (the walk along the chains).
// Constants come from host_device.h. The includer declares wake_points[] (GpuWakePoint,
// positions relative to the render origin O), wake_blocks[] (their block discs) and defines WAKE_COUNT (points) and
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
    float k = 0.25 * kGravityAcceleration * tau * tau * inv_r * inv_r;
    WakeWave w;
    w.theta = -0.25 * kGravityAcceleration * tau * tau * inv_r;
    w.omega = 0.5 * kGravityAcceleration * tau * inv_r;
    float filter_ = exp(-k * k * spread * spread);
    float near = 1.0 - exp(-0.25 * w.theta * w.theta);
    w.a = (1.0 / (1.4142136 * 3.1415927 * sqrt(kGravityAcceleration))) * k * sqrt(k) * filter_ * near * inv_r;
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

// How far from a disturbance made `age` s ago by an emitter at `speed` m/s (0: a
// splash) its waves can be felt, m (tidewater::detail::wake_reach).
float wake_reach(float age, float speed, float size) {
    float margin = kWakeReachSizes * size + kWakeReachMargin;
    if (speed > 0.0) return kWakeReachSpeedShare * speed * age + margin;
    float k_min = kWakeSplashLongest * 1.7320508 * 3.1415927 / size;
    return 0.5 * sqrt(kGravityAcceleration / k_min) * age + margin;
}

// How much of the segment from point a (the older) to b, or of lone point a = b, is
// summed at xz: all within kWakeReachFullShare of its reach, none beyond, a smoothstep
// in the squared distance between (tidewater::detail::wake_reach_disc, wake_reach_share).
float wake_reach_share(vec2 xz, GpuWakePoint a, GpuWakePoint b) {
    vec2 seg = b.position_age.xy - a.position_age.xy;
    float len = length(seg);
    float duration = a.position_age.z - b.position_age.z;
    float speed = duration > 0.0 ? len / duration : 0.0;
    float radius = wake_reach(max(a.position_age.z, b.position_age.z), speed, max(a.shape.x, b.shape.x)) + 0.5 * len;
    vec2 r = xz - 0.5 * (a.position_age.xy + b.position_age.xy);
    float r2 = radius * radius;
    float x = clamp((r2 - dot(r, r)) / (r2 * (1.0 - kWakeReachFullShare * kWakeReachFullShare)), 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

WakeWave wake_wave_of(vec2 xz, GpuWakePoint p) { return wake_wave(xz - p.position_age.xy, p.position_age.z, p.shape.x); }

// Every chain segment and lone point at rest position xz (relative to O); those that
// cannot be felt there are skipped (tidewater::detail::add_wakes).
SurfaceSums wakes_at(vec2 xz) {
    SurfaceSums s = surface_zero();
    WakeWave last;
    bool last_made = false;
    for (uint begin = 0u; begin < WAKE_COUNT; begin += kWakeBlockPoints) {
        vec4 disc = wake_blocks[begin / kWakeBlockPoints];
        vec2 off = xz - disc.xy;
        if (dot(off, off) > disc.z) {  // none of this block is felt here
            last_made = false;
            continue;
        }
        for (uint i = begin; i < min(WAKE_COUNT, begin + kWakeBlockPoints); ++i) {
            GpuWakePoint p = wake_points[i];
            bool after = i > 0u && wake_points[i - 1u].shape.w > 0.5;
            bool before = p.shape.w > 0.5;
            if (!after && before) {  // a chain's first point: no term of its own
                last_made = false;
                continue;
            }
            GpuWakePoint o = wake_points[after ? i - 1u : i];
            float share = wake_reach_share(xz, o, p);
            if (share <= 0.0) {
                last_made = false;
                continue;
            }
            WakeWave here = wake_wave_of(xz, p);
            if (after) {
                if (!last_made) last = wake_wave_of(xz, o);
                add_wake_segment(s, last, here, share * o.position_age.w, share * p.position_age.w, o.shape.y, p.shape.y,
                                 o.position_age.z - p.position_age.z);
            } else {
                add_wake_wave(s, here, share * p.position_age.w, p.shape.y);
            }
            last = here;
            last_made = true;
        }
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
