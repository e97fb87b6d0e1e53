// The sums of a Gerstner evaluation turned into a LagrangianSample (private):
// shared by the open-water and the shore evaluators.
#pragma once

#include "tidewater/gerstner.hpp"

namespace tidewater::detail {

struct GerstnerSums {
    double dx = 0, dz = 0, eta = 0;  // displacement
    double mxx = 0, mxz = 0, mzz = 0;  // sum Q A k D D^T sin(theta)
    double sx = 0, sz = 0;           // d eta / d x0
    double vx = 0, vy = 0, vz = 0;   // particle velocity
};

LagrangianSample assemble_sample(const GerstnerSums& s);

}  // namespace tidewater::detail
