// Entry points of the SIMD Eulerian query kernel (private), one per instruction set.
#pragma once

#include <cstddef>

#include <glm/vec2.hpp>

#include "tidewater/query.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater::detail {

/// What a batch of queries evaluates: a body's waves at one instant and, near a
/// shore, the shore model that reshapes them (null: open water).
struct KernelInput {
    const PreparedWaves<float>* waves = nullptr;
    const ShoreWaves* shore = nullptr;
};

/// Kernel entry: solves `n` points; exactly one of `full` and `heights` is non-null.
using SolveFn = void (*)(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
                         double* heights);

/// The foam a query reports: max(breaking, crest_foam(jacobian)).
double surface_foam(double breaking, double jacobian);

namespace kernel_sse2 {
void solve(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights);
const char* name();
}  // namespace kernel_sse2

namespace kernel_avx2 {
void solve(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights);
const char* name();
}  // namespace kernel_avx2

}  // namespace tidewater::detail
