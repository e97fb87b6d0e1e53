// The stream function of a river's depth-averaged current (private).
//
// With h u = perp(grad psi) = (-d psi/dz, d psi/dx), water is conserved by construction:
// the discharge between two points is the difference of psi there. psi solves
// div((1/h) grad psi) = 0 over the wet texels (the current has no vorticity), with
// psi fixed on each bank, no flux through the cut at the river's ends, and on each
// island the one constant value that leaves no net circulation around it.
// Discretised with finite volumes on the texel grid and solved with Eigen's sparse
// Cholesky factorisation.
#pragma once

#include <cstdint>
#include <vector>

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

enum class FlowCell : std::uint8_t {
    wet,       ///< water the current runs through
    bank,      ///< land with psi fixed at bank_value
    island,    ///< land inside the channel: island_of says which
    open_end,  ///< neither: no flux crosses a face to it (the cut at a river's ends)
};

struct StreamProblem {
    FieldGrid grid;
    std::vector<FlowCell> cell;
    std::vector<float> depth;        ///< m, > 0 on wet texels
    std::vector<double> bank_value;  ///< psi on bank texels, m^3/s
    std::vector<int> island_of;      ///< island index on island texels
    int islands = 0;
    /// m per texel: the depth a face conducts through is never taken below the larger of
    /// its two texels' (next to a bank the water column is a fraction of a texel, and 1/h
    /// must stay bounded); a share of the river's own depth there, no length of its own.
    std::vector<float> shallowest_face;
};

struct StreamSolution {
    std::vector<double> psi;   ///< every texel: wet solved, bank fixed, island its constant, else NaN
    std::size_t unknowns = 0;  ///< wet texels solved for, plus one per island
};

/// Solves for psi. Wet texels no bank or island reaches (a pool cut off at an end) keep
/// NaN and carry no current. Fails when the factorisation does.
Result<StreamSolution> solve_stream_function(const StreamProblem& problem);

}  // namespace tidewater::detail
