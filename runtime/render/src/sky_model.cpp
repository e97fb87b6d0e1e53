#include "sky_model.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace tidewater::render::detail {

namespace {

double perez(const glm::dvec4& abcd, double e, double cos_theta, double gamma) {
    const double cos_gamma = std::cos(gamma);
    return (1.0 + abcd.x * std::exp(abcd.y / std::max(cos_theta, 0.01))) *
           (1.0 + abcd.z * std::exp(abcd.w * gamma) + e * cos_gamma * cos_gamma);
}

}  // namespace

PreethamSky preetham_sky(glm::dvec3 sun, double turbidity) {
    const double t = turbidity;
    const double theta_s = std::acos(std::clamp(sun.y, 0.0, 1.0));
    PreethamSky sky;
    // The distribution coefficients (Preetham et al. 1999, appendix A.2).
    sky.abcd[0] = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771};
    sky.abcd[1] = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989};
    sky.abcd[2] = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537};
    sky.e = {-0.0670 * t + 0.3703, -0.0033 * t + 0.0452, -0.0109 * t + 0.0529};
    // Zenith luminance and chromaticity (appendix A.2).
    const double chi = (4.0 / 9.0 - t / 120.0) * (M_PI - 2.0 * theta_s);
    const double zenith_Y = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
    const double s = theta_s, s2 = s * s, s3 = s2 * s, t2 = t * t;
    const double zenith_x = t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s) +
                            t * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s + 0.00394) +
                            (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s + 0.25886);
    const double zenith_y = t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s) +
                            t * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s + 0.00516) +
                            (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s + 0.26688);
    sky.zenith = {zenith_Y, zenith_x, zenith_y};
    for (int i = 0; i < 3; ++i) sky.zenith_over_f0[i] = sky.zenith[i] / perez(sky.abcd[i], sky.e[i], 1.0, theta_s);
    return sky;
}

glm::dvec3 preetham_Yxy(const PreethamSky& sky, glm::dvec3 sun, glm::dvec3 dir) {
    const glm::dvec3 s = glm::normalize(glm::dvec3(sun.x, std::max(sun.y, 0.0), sun.z));
    const double gamma = std::acos(std::clamp(glm::dot(s, dir), -1.0, 1.0));
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) out[i] = sky.zenith_over_f0[i] * perez(sky.abcd[i], sky.e[i], dir.y, gamma);
    return out;
}

glm::dvec3 sky_white_balance(const PreethamSky& sky, glm::dvec3 sun) {
    // The horizon's colour averaged over eight azimuths, 1 degree up.
    glm::dvec3 rgb{0.0};
    for (int i = 0; i < 8; ++i) {
        const double azimuth = 2.0 * M_PI * i / 8.0;
        rgb += linear_srgb_from_Yxy(
            preetham_Yxy(sky, sun, glm::normalize(glm::dvec3(std::cos(azimuth), 0.0175, std::sin(azimuth)))));
    }
    if (!(rgb.r > 0.0 && rgb.g > 0.0 && rgb.b > 0.0)) return glm::dvec3(1.0);
    return glm::dvec3(0.94 * rgb.g / rgb.r, 1.0, 1.1 * rgb.g / rgb.b);
}

glm::dvec3 linear_srgb_from_Yxy(glm::dvec3 Yxy) {
    const double Y = Yxy.x, x = Yxy.y, y = std::max(Yxy.z, 1e-6);
    const double X = x * Y / y, Z = (1.0 - x - y) * Y / y;
    return {3.2406 * X - 1.5372 * Y - 0.4986 * Z, -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
            0.0557 * X - 0.2040 * Y + 1.0570 * Z};
}

}  // namespace tidewater::render::detail
