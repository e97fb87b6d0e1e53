#include <algorithm>

#include "kernel/kernel_waves.hpp"
#include "tidewater/gerstner.hpp"

namespace tidewater::detail {

KernelWaves prepare_kernel_waves(const WaveSet& set, double local_time, double level) {
    KernelWaves k;
    const auto waves = set.waves();
    const std::size_t n = waves.size();
    k.count = n;
    k.level = level;
    k.offset.resize(n);
    phase_offsets_at(set, local_time, k.offset);
    for (std::vector<double>* v : {&k.kx, &k.kz}) v->resize(n);
    for (std::vector<float>* v : {&k.kxf, &k.kzf, &k.a, &k.ak_x, &k.ak_z, &k.qa_x, &k.qa_z, &k.qak_xx,
                                  &k.qak_xz, &k.qak_zz, &k.qaw_x, &k.qaw_z, &k.aw})
        v->resize(n);
    double max_offset = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Wave& w = waves[i];
        const double qa = w.steepness * w.amplitude;
        const double kx = w.k * w.dir_x, kz = w.k * w.dir_z;
        k.kx[i] = kx;
        k.kz[i] = kz;
        k.kxf[i] = static_cast<float>(kx);
        k.kzf[i] = static_cast<float>(kz);
        k.a[i] = static_cast<float>(w.amplitude);
        k.ak_x[i] = static_cast<float>(w.amplitude * kx);
        k.ak_z[i] = static_cast<float>(w.amplitude * kz);
        k.qa_x[i] = static_cast<float>(qa * w.dir_x);
        k.qa_z[i] = static_cast<float>(qa * w.dir_z);
        k.qak_xx[i] = static_cast<float>(qa * kx * w.dir_x);
        k.qak_xz[i] = static_cast<float>(qa * kx * w.dir_z);
        k.qak_zz[i] = static_cast<float>(qa * kz * w.dir_z);
        k.qaw_x[i] = static_cast<float>(qa * w.omega * w.dir_x);
        k.qaw_z[i] = static_cast<float>(qa * w.omega * w.dir_z);
        k.aw[i] = static_cast<float>(w.amplitude * w.omega);
        max_offset += qa;
    }
    // A little slack so the clamp never cuts the true solution; the tolerance
    // sits above float rounding of a residual of this size.
    k.max_offset = static_cast<float>(max_offset * 1.001 + 1e-6);
    k.tolerance = static_cast<float>(std::max(1e-5, 4e-6 * max_offset));
    return k;
}

}  // namespace tidewater::detail
