#include "tidewater/gerstner.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "gerstner_sums.hpp"
#include "tidewater/constants.hpp"

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

namespace detail {

LagrangianSample assemble_sample(const GerstnerSums& s) {
    LagrangianSample out;
    out.displacement = {s.dx, s.eta, s.dz};
    out.velocity = {s.vx, s.vy, s.vz};
    out.jxx = 1.0 - s.mxx;
    out.jxz = -s.mxz;
    out.jzz = 1.0 - s.mzz;
    out.jacobian = out.jxx * out.jzz - out.jxz * out.jxz;
    out.slope = {s.sx, s.sz};
    // Tangents of the displaced surface along x0 and z0; normal = Tz x Tx (y up).
    const glm::dvec3 tx{out.jxx, s.sx, out.jxz};
    const glm::dvec3 tz{out.jxz, s.sz, out.jzz};
    out.normal = glm::normalize(glm::cross(tz, tx));
    return out;
}

}  // namespace detail

LagrangianSample evaluate_lagrangian(const WaveSet& set, glm::dvec2 rest, double time) {
    detail::GerstnerSums g;
    double &dx = g.dx, &dz = g.dz, &eta = g.eta, &mxx = g.mxx, &mxz = g.mxz, &mzz = g.mzz;
    double &sx = g.sx, &sz = g.sz, &vx = g.vx, &vy = g.vy, &vz = g.vz;
    for (const Wave& w : set.waves()) {
        const double travelled = std::fmod(w.omega * time, kTwoPi);
        const double theta = w.k * (w.dir_x * rest.x + w.dir_z * rest.y) - travelled + w.phase;
        const double s = std::sin(theta), c = std::cos(theta);
        const double qa = w.steepness * w.amplitude;
        dx += qa * w.dir_x * c;
        dz += qa * w.dir_z * c;
        eta += w.amplitude * s;
        const double qak_s = qa * w.k * s;
        mxx += qak_s * w.dir_x * w.dir_x;
        mxz += qak_s * w.dir_x * w.dir_z;
        mzz += qak_s * w.dir_z * w.dir_z;
        const double ak_c = w.amplitude * w.k * c;
        sx += ak_c * w.dir_x;
        sz += ak_c * w.dir_z;
        // d theta / dt = -omega.
        vx += qa * w.omega * w.dir_x * s;
        vz += qa * w.omega * w.dir_z * s;
        vy -= w.amplitude * w.omega * c;
    }
    return detail::assemble_sample(g);
}

}  // namespace tidewater
