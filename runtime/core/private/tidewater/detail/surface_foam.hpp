// The foam a query reports (private): one definition for the SIMD kernels, the double
// reference and the host side of the GPU query. The water shader's twin filters the same
// curves over what a pixel cannot resolve (shaders/foam_filter.glsl).
// Threading: pure functions.
#pragma once

#include <array>
#include <cstddef>

#include "tidewater/detail/water_point.hpp"

namespace tidewater::detail {

/// exp(-tau_l / kFoamDecayTime) with tau_l = lag * kFoamLagStep (lag 1..kFoamLags): how
/// much of its crest foam a particle keeps tau_l later (GLSL twin: foam_memory_weight).
double foam_memory_weight(std::size_t lag);

/// The crest foam a particle still carries from its earlier compression: the sum over the
/// lags of crest_foam(J_l, J*) * foam_memory_weight(l) (lagged_jacobians), what each
/// earlier compression left, fading as dF/dt = -F / kFoamDecayTime. Whitecaps leave a
/// fading trail instead of vanishing as the crest moves on. A sum, not a maximum, so that
/// a pixel's average of it is the sum of the lags' averages (the water shader filters
/// each lag as it filters the fresh foam).
double remembered_foam(const std::array<double, kFoamLags>& lagged_jacobians, double whitecap_jacobian);

/// max(breaking, min(1, crest_foam(jacobian, J*) + remembered_foam(lagged, J*))).
double surface_foam(double breaking, double jacobian, const std::array<double, kFoamLags>& lagged_jacobians,
                    double whitecap_jacobian);

}  // namespace tidewater::detail
