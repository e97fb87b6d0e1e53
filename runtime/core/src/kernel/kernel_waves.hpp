// Entry points of the SIMD Eulerian query kernel (private), one per instruction set.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>

#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/surface_foam.hpp"
#include "tidewater/detail/wake_water.hpp"
#include "tidewater/query.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater::detail {

/// What a batch of queries evaluates: a body's waves at one instant and, near a
/// shore, the shore model that reshapes them (null: open water).
struct KernelInput {
    const PreparedWaves<float>* waves = nullptr;
    const ShoreWaves* shore = nullptr;
    const PreparedWakes<float>* wakes = nullptr;  ///< null or empty: none
};

struct RiverBake;

/// What a batch of river points evaluates (see water/river_solve.hpp).
template <typename Scalar>
struct RiverInput {
    const RiverBake* river = nullptr;
    /// prepare_river_waves of the river's preset; its level is the river's mouth level,
    /// which its surface fields are relative to.
    const PreparedWaves<Scalar>* river_waves = nullptr;
    /// The plume's still water: its waves (level included) and shore model. Null waves:
    /// the points are in the river's own water.
    const PreparedWaves<Scalar>* still_waves = nullptr;
    const ShoreWaves* still_shore = nullptr;
};

/// River kernel entry: solves `n` points of one river or one plume, full results.
using RiverSolveFn = void (*)(const RiverInput<float>& in, const glm::dvec2* points, std::size_t n, SurfacePoint* out);

/// Kernel entry: solves `n` points; exactly one of `full` and `heights` is non-null.
using SolveFn = void (*)(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full,
                         double* heights);

namespace kernel_sse2 {
void solve(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights);
void solve_river(const RiverInput<float>& in, const glm::dvec2* points, std::size_t n, SurfacePoint* out);
const char* name();
}  // namespace kernel_sse2

namespace kernel_avx2 {
void solve(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights);
void solve_river(const RiverInput<float>& in, const glm::dvec2* points, std::size_t n, SurfacePoint* out);
const char* name();
}  // namespace kernel_avx2

}  // namespace tidewater::detail
