// The analytic daylight sky of Preetham, Shirley and Smits (1999, "A practical analytic
// model for daylight"): luminance Y and chromaticity (x, y) toward a direction, from
// the sun's direction and the air's turbidity T.
//
//   value(theta, gamma) = zenith * F(theta, gamma) / F(0, theta_s)
//   F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma)
//
// theta: the direction's angle from the zenith, gamma: its angle to the sun, theta_s:
// the sun's zenith angle. The host computes the coefficients and zenith values once per
// frame (GpuFrame.sky_*); shaders/frame.glsl evaluates F and turns Yxy into colour.
// Threading: pure functions.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace tidewater::render::detail {

/// The sky's display look (shaders/frame.glsl sky_color): luminance L (relative to the
/// zenith's) maps to 1 - exp(-kSkyExposure L), a photographer's exposure with a soft
/// shoulder that keeps the hue, and the colour is then saturated by kSkySaturation about
/// its grey, as a camera's daylight rendering does.
inline constexpr double kSkyExposure = 0.35;
inline constexpr double kSkySaturation = 1.4;

struct PreethamSky {
    glm::dvec4 abcd[3];  ///< A, B, C, D for Y, x, y
    glm::dvec3 e;        ///< E for Y, x, y
    glm::dvec3 zenith;   ///< Y (kcd/m^2), x and y at the zenith
    /// zenith value / F(0, theta_s) for Y (kcd/m^2), x and y
    glm::dvec3 zenith_over_f0;
};

/// The model for a sun toward `sun` (unit, y up; a sun below the horizon is held on it)
/// and turbidity `turbidity` in [1.7, 10] (2: very clear, 3: clear, 6: hazy).
PreethamSky preetham_sky(glm::dvec3 sun, double turbidity);

/// Y (kcd/m^2), x, y toward unit direction `dir` at or above the horizon.
glm::dvec3 preetham_Yxy(const PreethamSky& sky, glm::dvec3 sun, glm::dvec3 dir);

/// White-balance gains (multiplying linear sRGB) under which the horizon, averaged round
/// the compass, shows a pale clear-sky blue (0.94, 1, 1.1) instead of the model's faint
/// magenta there.
glm::dvec3 sky_white_balance(const PreethamSky& sky, glm::dvec3 sun);

/// Linear sRGB of a Yxy colour (CIE XYZ through the sRGB matrix), luminance kept in Y's units.
glm::dvec3 linear_srgb_from_Yxy(glm::dvec3 Yxy);

}  // namespace tidewater::render::detail
