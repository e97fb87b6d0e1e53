// Floating-body helper: heave, pitch and roll of a hull riding the surface.
//
// The hull is a set of sample points in the body frame (x forward, z to
// starboard, metres). At time t the points are placed at the body's position
// and heading, the surface height is queried under each, and a plane
// y = heave + a*x + b*z is fitted by least squares. With the usual four points
// (bow, stern, port, starboard) this is the classic two-axis tilt.
// Threading: reentrant; FloatingBody is a plain value.
#pragma once

#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

struct HullAttitude {
    double heave = 0.0;  ///< World y of the fitted plane under the body origin, m.
    double pitch = 0.0;  ///< Bow-up rotation about the body's z axis, rad.
    double roll = 0.0;   ///< Starboard-down rotation about the body's x axis, rad.
    /// The mean current under the hull points (rivers and their plumes), m/s: what carries
    /// the body along. 0 from the WaterBody overload, which knows no currents.
    glm::dvec2 current{0.0};
};

struct FloatingBody {
    std::vector<glm::dvec2> hull_points;  ///< Body frame (forward, starboard), m; >= 3, not collinear.
    glm::dvec2 position{0.0};             ///< World (x, z) of the body origin, m.
    double heading_deg = 0.0;             ///< Forward axis, degrees from +x toward +z.

    /// Bow, stern, port and starboard points for a hull of this length and beam.
    static FloatingBody four_point(double length, double beam);
};

Result<HullAttitude> hull_attitude(const WaterBody& body, const FloatingBody& hull, double time);

/// The same over a whole scene (query_world): the hull rides whichever body it is in (a
/// river's falling surface, a lake) and reports the current it feels. A scene with lakes
/// or rivers must be baked.
Result<HullAttitude> hull_attitude(const Scene& scene, const FloatingBody& hull, double time);

}  // namespace tidewater
