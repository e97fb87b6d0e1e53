// Wave data laid out for the SIMD Eulerian query kernel (private).
#pragma once

#include <cstddef>
#include <vector>

#include "tidewater/query.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::detail {

/// One wave set at one instant, as structure-of-arrays. Phases that need the
/// full range (k*x for large x) stay in double; everything applied to the
/// small Newton offset is float.
struct KernelWaves {
    std::size_t count = 0;
    std::vector<double> kx, kz, offset;  // k*D and (phase - omega*t) reduced to [-pi, pi)
    std::vector<float> kxf, kzf;          // k*D for the offset from the query point
    std::vector<float> a, ak_x, ak_z;     // A, A*k*D: elevation and its slope
    std::vector<float> qa_x, qa_z;        // Q*A*D: horizontal displacement
    std::vector<float> qak_xx, qak_xz, qak_zz;  // Q*A*k*D*D^T: displacement gradient
    std::vector<float> qaw_x, qaw_z, aw;  // Q*A*omega*D and A*omega: particle velocity
    float max_offset = 0.0f;              // sum(Q*A): the rest position lies within this of the point
    float tolerance = 0.0f;               // residual |x0 + d(x0) - p| accepted as converged, m
    double level = 0.0;                   // rest water level added to heights
};

KernelWaves prepare_kernel_waves(const WaveSet& set, double local_time, double level);

/// Kernel entry: solves `n` points; exactly one of `full` and `heights` is non-null.
using SolveFn = void (*)(const KernelWaves& waves, const glm::dvec2* points, std::size_t n,
                         SurfacePoint* full, double* heights);

inline constexpr int kMaxNewtonIterations = 24;

namespace kernel_sse2 {
void solve(const KernelWaves& waves, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
           double* heights);
const char* name();
}  // namespace kernel_sse2

namespace kernel_avx2 {
void solve(const KernelWaves& waves, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
           double* heights);
const char* name();
}  // namespace kernel_avx2

}  // namespace tidewater::detail
