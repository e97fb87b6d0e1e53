// Whitecaps: how much of the open sea a wind turns white, and where the waves' own
// folding crosses that share.
//
// Monahan and O'Muircheartaigh (1980): the whitecap coverage of the open sea is
//   W(U) = 3.84e-6 * U^3.41        (U: wind speed at 10 m, m/s; W: area fraction)
// about 1.8% at 12 m/s. A body's crest foam turns on where its horizontal map compresses
// (Jacobian J < 1), and a particle keeps that foam for a while after its crest has passed
// (SurfacePoint::foam). The whitecap Jacobian J* is set so that foam >= 1/2, the fresh and
// the remembered together, covers the share W of the displaced (drawn) surface: Monahan's
// W counts the fading foam patches as well as the breaking crests.
// Threading: pure functions.
#pragma once

#include "tidewater/waves.hpp"

namespace tidewater {

/// Monahan's whitecap coverage for wind speed `wind_speed` (m/s at 10 m), as an area
/// fraction in [0, 1] (clamped at 1 for winds far beyond the fit's range).
double monahan_whitecap_fraction(double wind_speed);

/// The whitecap Jacobian J* at which foam >= 1/2 (fresh or remembered) covers `fraction`
/// (in (0, 1)) of the open sea's displaced surface for this wave set, by area. Estimated
/// from a fixed, seeded sample of 65 536 surface particles over eight instants (J* by
/// bisection on their foam), so the same set always gets the same J*;
/// a sampling error of about 0.005 in J* for the bundled presets. An empty set (flat
/// water, J = 1 everywhere) gives 1.
double whitecap_jacobian(const WaveSet& set, double fraction);

/// J* for bodies whose wind is not known (waves authored one by one): foam where the
/// map compresses by 45% (the curve's midpoint).
inline constexpr double kDefaultWhitecapJacobian = 0.55;

}  // namespace tidewater
