#include "tidewater/gerstner.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/reference.hpp"
#include "water/open_sea_water.hpp"
#include "water/shore_water.hpp"

namespace tidewater {

double wrap_angle(double radians) {
    return radians - kTwoPi * std::floor(radians / kTwoPi + 0.5);
}

void phase_offsets_at(const WaveSet& set, double time, std::span<double> out) {
    const auto waves = set.waves();
    for (std::size_t i = 0; i < waves.size() && i < out.size(); ++i) {
        // omega*t grows without bound; reduce it on its own first so the sum keeps its digits.
        const double travelled = wrap_angle(std::fmod(waves[i].omega * time, kTwoPi));
        out[i] = wrap_angle(waves[i].phase - travelled);
    }
}

namespace {

LagrangianSample to_sample(const detail::SurfaceSums<double>& s) {
    const detail::SurfaceFrame<double> f = detail::surface_frame(s);
    LagrangianSample out;
    out.displacement = {s.dx, s.eta, s.dz};
    out.velocity = {s.vx, s.vy, s.vz};
    out.jxx = f.jxx;
    out.jxz = f.jxz;
    out.jzz = f.jzz;
    out.jacobian = f.det;
    out.slope = {s.sx, s.sz};
    out.normal = glm::normalize(glm::dvec3(f.nx, f.ny, f.nz));
    return out;
}

}  // namespace

LagrangianSample evaluate_lagrangian(const WaveSet& set, glm::dvec2 rest, double time) {
    const auto waves = detail::prepare_waves<double>(set, time, 0.0);
    std::array<double, kMaxWaves> base{};
    detail::base_phases(waves, rest.x, rest.y, base.data(), 1);
    const detail::OpenSeaWater<double> water(waves, base.data());
    return to_sample(water.evaluate<true>(0.0, 0.0));
}

LagrangianSample evaluate_lagrangian_shore(const WaveSet& set, const ShoreWaves& shore, glm::dvec2 rest, double time,
                                           LocalShore* local) {
    const auto waves = detail::prepare_waves<double>(set, time, 0.0);
    std::array<double, kMaxWaves> base{};
    detail::base_phases(waves, rest.x, rest.y, base.data(), 1);
    detail::ShoreWater<double> water(waves, shore, &rest.x, &rest.y, base.data());
    if (local) {
        std::array<LocalWave, kMaxWaves> per_wave;
        *local = shore.sample(rest, std::span<LocalWave>(per_wave.data(), set.size()));
    }
    return to_sample(water.evaluate<true>(0.0, 0.0));
}

}  // namespace tidewater
