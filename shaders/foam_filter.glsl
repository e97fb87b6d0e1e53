// The crest foam of a pixel whose waves it cannot all resolve (water.frag): the
// expectation of tidewater::crest_foam under the Jacobian's unresolved spread, over the
// particles and facets the viewer sees at grazing angles. Shader-only: the CPU queries
// see no pixels.
#ifndef TIDEWATER_FOAM_FILTER_GLSL
#define TIDEWATER_FOAM_FILTER_GLSL
#include "water_lod.glsl"
#include "water_quality.glsl"

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
    vec2 pdf_cdf = normal_pdf_cdf(u);
    float phi = pdf_cdf.x, cdf = pdf_cdf.y;
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
    // Each end's integrals weighed first: two numbers held instead of six.
    vec3 weights = vec3(alpha * (1.0 - alpha), beta * (1.0 - 2.0 * alpha), -beta * beta);
    float sum = 6.0 * beta * (dot(weights, phi_integrals(ub)) - dot(weights, phi_integrals(ua)));
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

// The waves of draw `d` that a pixel with render LOD `lod` cannot resolve: the share
// 1 - kept^2 of each wave's variance that its footprint averages away (pixel_keeps), and
// all of it for the waves the tier does not draw (QualitySettings::waves_drawn).
// They change with the footprint, which changes slowly across a water patch, and not
// with the waves' phases: water.tesc sums them at the patch's corners and the pixels
// interpolate them (hidden_waves_packed / hidden_waves_unpacked), instead of every
// pixel summing every wave. A river's waves ride its current and hide nothing here.
HiddenWaves hidden_waves_at(GpuBodyDraw d, WaveLod lod) {
    HiddenWaves hidden = hidden_zero();
    if (uint(d.body.x) == kBodyRiver) return hidden;
    uint first = uint(d.body.z), count = uint(d.body.w);
    for (uint i = first; i < first + count; ++i) {
        GpuWave w = waves[i];
        vec2 kvec = w.dir_k_amp.xy * w.dir_k_amp.z;
        float kept = wave_left_to_variance(w) ? 0.0 : pixel_keeps(kvec, lod);
        float slope_amplitude = w.dir_k_amp.z * w.dir_k_amp.w;
        float compression = w.steep_omega.x * slope_amplitude;  // Q k A
        add_hidden_wave(hidden, 1.0 - kept * kept, w.dir_k_amp.w, slope_amplitude, compression, -dot(kvec, lod.toward), w.lag_turn.xy);
    }
    return hidden;
}
// Three vec4s, as the tessellation stages pass them on: (compression variance, height
// variance, slope variance, compression covariance), the lagged covariances, the lagged
// slope covariances.
mat3x4 hidden_waves_packed(HiddenWaves h) {
    return mat3x4(vec4(h.compression_variance, h.height_variance, h.slope_variance, h.compression_covariance), h.lagged_covariance,
                  h.lagged_slope_covariance);
}
HiddenWaves hidden_waves_unpacked(vec4 a, vec4 lagged, vec4 lagged_slope) {
    return HiddenWaves(max(a.x, 0.0), max(a.y, 0.0), max(a.z, 0.0), a.w, lagged, lagged_slope);
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
    vec2 pdf_cdf = normal_pdf_cdf(u);
    float lambda = pdf_cdf.x / u - (1.0 - pdf_cdf.y);
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
// seen_crest_spread gives the Jacobian's mean and spread over what is seen, for
// crest_foam_filtered: the foam's lags each take theirs before any is filtered, so that
// the filter's terms for one lag do not share the registers with the others' inputs.
vec2 seen_crest_spread(float j, float covariance, float slope_covariance, HiddenWaves h, vec2 seen, vec2 facing) {
    float spread2 = h.compression_variance;
    if (h.height_variance > 0.0) {
        float per_height = covariance / sqrt(h.height_variance);
        j -= per_height * seen.x;
        spread2 -= per_height * per_height * (1.0 - seen.y);
    }
    j -= slope_covariance * facing.x;
    spread2 -= slope_covariance * slope_covariance * facing.y;
    return vec2(j, sqrt(max(spread2, 0.0)));
}
float seen_crest_foam(vec2 spread, float whitecap_jacobian) { return crest_foam_filtered(spread.x, whitecap_jacobian, spread.y); }
#endif
