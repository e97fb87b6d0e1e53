// Gerstner evaluation shared by the water and query shaders. The CPU twin is
// runtime/core/src/kernel/eulerian_kernel_impl.hpp: the same sums, the same
// Newton solve, the same stopping rule.
#ifndef TIDEWATER_GERSTNER_GLSL
#define TIDEWATER_GERSTNER_GLSL

// Sums of one evaluation at rest offset e from the point (phases base + k D.e).
struct GerstnerSums {
    vec2 disp;       // sum Q A D cos
    vec3 m;          // sum Q A k sin * (Dx Dx, Dx Dz, Dz Dz)
    float eta;       // sum A sin
    vec2 slope;      // sum A k D cos
    vec3 velocity;   // (sum Q A w Dx sin, -sum A w cos, sum Q A w Dz sin)
};

GerstnerSums gerstner_zero() {
    GerstnerSums s;
    s.disp = vec2(0.0);
    s.m = vec3(0.0);
    s.eta = 0.0;
    s.slope = vec2(0.0);
    s.velocity = vec3(0.0);
    return s;
}

void gerstner_accumulate(inout GerstnerSums s, GpuWave w, float theta) {
    float sn = sin(theta);
    float cs = cos(theta);
    vec2 d = w.dir_k_amp.xy;
    float k = w.dir_k_amp.z;
    float a = w.dir_k_amp.w;
    float qa = w.steep_omega.x * a;
    float omega = w.steep_omega.y;
    s.disp += qa * d * cs;
    s.m += qa * k * sn * vec3(d.x * d.x, d.x * d.y, d.y * d.y);
    s.eta += a * sn;
    s.slope += a * k * d * cs;
    s.velocity += vec3(qa * omega * d.x * sn, -a * omega * cs, qa * omega * d.y * sn);
}

// Normal of the displaced surface: Tz x Tx with Tx = (jxx, sx, jxz), Tz = (jxz, sz, jzz).
vec3 gerstner_normal(GerstnerSums s) {
    float jxx = 1.0 - s.m.x, jxz = -s.m.y, jzz = 1.0 - s.m.z;
    vec3 tx = vec3(jxx, s.slope.x, jxz);
    vec3 tz = vec3(jxz, s.slope.y, jzz);
    return normalize(cross(tz, tx));
}

float gerstner_jacobian(GerstnerSums s) {
    float jxx = 1.0 - s.m.x, jxz = -s.m.y, jzz = 1.0 - s.m.z;
    return jxx * jzz - jxz * jxz;
}

#endif
