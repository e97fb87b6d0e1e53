#include "water/prepared_waves.hpp"

#include <cmath>

#include "host_device.h"
#include "tidewater/constants.hpp"
#include "tidewater/detail/newton.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/gerstner.hpp"

namespace tidewater::detail {

namespace {
/// Round-to-nearest without libm: adding 1.5 * 2^52 pushes the fraction out.
inline double round_to_integer(double v) {
    constexpr double kShift = 6755399441055744.0;
    return (v + kShift) - kShift;
}
}  // namespace

template <typename Scalar>
PreparedWaves<Scalar> prepare_waves(const WaveSet& set, double local_time, double level) {
    PreparedWaves<Scalar> p;
    const auto waves = set.waves();
    const std::size_t n = waves.size();
    p.count = n;
    p.level = level;
    p.offset.resize(n);
    phase_offsets_at(set, local_time, p.offset);
    double max_offset = 0.0;
    for (const Wave& w : waves) {
        const double kx = w.k * w.dir_x, kz = w.k * w.dir_z;
        p.kx.push_back(kx);
        p.kz.push_back(kz);
        p.kx_s.push_back(static_cast<Scalar>(kx));
        p.kz_s.push_back(static_cast<Scalar>(kz));
        p.amplitude.push_back(static_cast<Scalar>(w.amplitude));
        p.steepness.push_back(static_cast<Scalar>(w.steepness));
        p.omega.push_back(static_cast<Scalar>(w.omega));
        for (std::size_t l = 1; l <= kFoamLags; ++l) {
            const double lag_phase = w.omega * static_cast<double>(l) * static_cast<double>(gpu::kFoamLagStep);
            p.lag_sin.push_back(static_cast<Scalar>(std::sin(lag_phase)));
            p.lag_cos.push_back(static_cast<Scalar>(std::cos(lag_phase)));
        }
        // The coefficients are formed in double and rounded once.
        const WaveTerm<double> t = wave_term<double>(kx, kz, w.amplitude, w.steepness, w.omega);
        p.open_sea.push_back({static_cast<Scalar>(t.a), static_cast<Scalar>(t.ak_x), static_cast<Scalar>(t.ak_z),
                              static_cast<Scalar>(t.qa_x), static_cast<Scalar>(t.qa_z), static_cast<Scalar>(t.qak_xx),
                              static_cast<Scalar>(t.qak_xz), static_cast<Scalar>(t.qak_zz),
                              static_cast<Scalar>(t.qaw_x), static_cast<Scalar>(t.qaw_z), static_cast<Scalar>(t.aw)});
        max_offset += w.steepness * w.amplitude;
    }
    p.max_offset = max_offset;
    p.tolerance = newton_tolerance(max_offset);
    p.radius = newton_radius(max_offset);
    return p;
}

template PreparedWaves<float> prepare_waves<float>(const WaveSet&, double, double);
template PreparedWaves<double> prepare_waves<double>(const WaveSet&, double, double);

template <typename Scalar>
PreparedWaves<Scalar> prepare_body_waves(const WaterBody& body, double time) {
    PreparedWaves<Scalar> p = prepare_waves<Scalar>(body.waves(), body.local_time(time), body.level());
    p.whitecap_jacobian = body.whitecap_jacobian();
    return p;
}

template PreparedWaves<float> prepare_body_waves<float>(const WaterBody&, double);
template PreparedWaves<double> prepare_body_waves<double>(const WaterBody&, double);

template <typename Scalar>
PreparedWaves<Scalar> prepare_river_waves(const WaveSet& set, double local_time, double level, double mean_speed) {
    PreparedWaves<Scalar> p = prepare_waves<Scalar>(set, local_time, level);
    for (std::size_t i = 0; i < p.count; ++i) p.offset[i] = wrap_angle(p.offset[i] - p.kx[i] * mean_speed * local_time);
    p.bank_ramp_depth = river_bank_ramp_depth(set);
    return p;
}

template PreparedWaves<float> prepare_river_waves<float>(const WaveSet&, double, double, double);
template PreparedWaves<double> prepare_river_waves<double>(const WaveSet&, double, double, double);

double river_bank_ramp_depth(const WaveSet& waves) {
    return 2.0 * waves.max_elevation() / static_cast<double>(gpu::kRiverBankBreakerIndex);
}

std::vector<RiverWaveAt> river_waves_at(const WaveSet& waves, double local_time, double mean_speed) {
    const PreparedWaves<double> p = prepare_river_waves<double>(waves, local_time, 0.0, mean_speed);
    std::vector<RiverWaveAt> out(p.count);
    for (std::size_t i = 0; i < p.count; ++i)
        out[i] = {p.kx[i], p.kz[i], p.amplitude[i], p.steepness[i], p.omega[i], p.offset[i]};
    return out;
}

namespace {
template <typename Scalar>
void reduced_phases(const PreparedWaves<Scalar>& w, double px, double pz, Scalar* base, std::size_t stride) {
    constexpr double kInvTwoPi = 1.0 / kTwoPi;
    for (std::size_t i = 0; i < w.count; ++i) {
        double t = w.kx[i] * px + w.kz[i] * pz + w.offset[i];
        t -= kTwoPi * round_to_integer(t * kInvTwoPi);
        base[i * stride] = static_cast<Scalar>(t);
    }
}
}  // namespace

void base_phases(const PreparedWaves<float>& w, double px, double pz, float* base, std::size_t stride) {
    reduced_phases(w, px, pz, base, stride);
}
void base_phases(const PreparedWaves<double>& w, double px, double pz, double* base, std::size_t stride) {
    reduced_phases(w, px, pz, base, stride);
}

}  // namespace tidewater::detail
