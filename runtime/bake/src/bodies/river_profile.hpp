// A river along its centreline (private): resampled from its path, its bed following
// the terrain downhill, its surface never rising, and its depth from Manning's formula
// for the discharge, the width and the slope.
#pragma once

#include <cmath>

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// The across-channel shape of a carved bed: depth below the surface at |2n / w| = x
/// is h_c (1 - x^4), whose mean is 0.8 h_c.
inline double carved_depth_fraction(double x) {
    const double x2 = x * x;
    return x < 1.0 ? 1.0 - x2 * x2 : 0.0;
}
/// The same shape as a grid of nodes `step` apart (in x) holds it, linear between them:
/// what the baked fields and the carved terrain reproduce, so Manning's formula is
/// solved for the channel that is drawn and queried.
inline double carved_depth_fraction(double x, double step) {
    const double node = std::floor(x / step) * step;
    const double t = (x - node) / step;
    return (1.0 - t) * carved_depth_fraction(node) + t * carved_depth_fraction(node + step);
}
/// A carved bank rises from the waterline at this slope (vertical / horizontal).
inline constexpr double kCarvedBankSlope = 0.5;
/// The steepest a surface falls into the body it ends in (vertical / horizontal): a
/// mountain stream's 15%, so steep rivers keep their fall and a berm at the mouth is cut.
inline constexpr double kMouthRampSlope = 0.15;
/// Ground inside a carved channel that stands this many times the channel's centre depth
/// above the surface and clear of both banks is a knoll the river goes round (an
/// island), not terrain to cut.
inline constexpr double kIslandFreeboard = 4.0;
/// The fewest texels a knoll must cover to stay: smaller ones are shaved with the channel.
inline constexpr int kIslandMinimumTexels = 4;
/// The current is the depth-integrated current over a depth no shallower than this share
/// of its section's deepest (next to the waterline the water column vanishes).
inline constexpr double kShallowestCurrentDepth = 0.1;
/// The gentlest slope Manning's formula is given (pools and flat reaches).
inline constexpr double kMinimumSlope = 1e-4;

struct CentrelineSamples {
    std::vector<glm::dvec2> points;
    std::vector<double> along, width;
};

/// A per-sample quantity at distance `s` along the centreline, linear between samples and
/// held at the ends.
double at_along(const std::vector<double>& along, const std::vector<double>& values, double s);

/// Samples the path every `spacing` m (and at its ends), widths interpolated along it.
CentrelineSamples resample_centreline(const std::vector<glm::dvec2>& path, const std::vector<double>& width,
                                      double spacing);

/// Where the river's surface must end: NaN at the domain edge (free), else the level.
struct ProfileInputs {
    const Terrain* terrain = nullptr;
    bool carve = true;
    double texel = 1.0;  ///< m, of the grid that will hold the channel
    double manning = 0.035;
    double mouth_level = 0.0;       ///< NaN: no level to meet
    std::vector<double> discharge;  ///< Q at each sample, m^3/s
};

/// The river's surface, bed, slope and centre depth per sample (fills `river`'s
/// centreline vectors) and the carved centre depth h_c per sample (0 without carving).
std::vector<double> bake_profile(const CentrelineSamples& samples, const ProfileInputs& in, RiverBake& river);

/// Manning's discharge (1/n) A R^(2/3) S^(1/2) of a section sampled at `count` points
/// `spacing` m apart with bed heights `bed`, under the surface `eta`.
double manning_discharge(const double* bed, int count, double spacing, double eta, double slope, double manning,
                         double* area = nullptr, double* perimeter = nullptr);

}  // namespace tidewater::detail
