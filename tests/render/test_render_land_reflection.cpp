// Land reflected where it is, on lavapipe under the validation layer: the water's
// reflection of a hill does not depend on whether the camera sees the hill.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "render_fixture.hpp"

namespace tidewater {
namespace {

/// The mean colour of the water in cells of 1 m, from where each pixel's ray meets the
/// rest level, for the cells short of the shore at x = 45 m (at least `min_pixels` each).
std::map<std::pair<int, int>, Rgb> water_cells(const render::RgbaImage& img, const render::Camera& camera,
                                               int min_pixels) {
    const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);
    const auto c = render::near_plane_corners(camera, static_cast<double>(w) / h);
    std::map<std::pair<int, int>, std::pair<Rgb, int>> sums;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w, v = 1.0 - (y + 0.5) / h;
            const glm::dvec3 bottom = c[0] + (c[1] - c[0]) * u, top = c[3] + (c[2] - c[3]) * u;
            const glm::dvec3 d = glm::normalize(bottom + (top - bottom) * v - camera.position);
            if (d.y > -0.01) continue;
            const glm::dvec3 p = camera.position + d * (-camera.position.y / d.y);
            if (p.x > 45.0) continue;
            auto& [sum, n] = sums[{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.z))}];
            const Rgb px = test::pixel(img, x, y);
            sum.r += px.r;
            sum.g += px.g;
            sum.b += px.b;
            ++n;
        }
    std::map<std::pair<int, int>, Rgb> out;
    for (const auto& [cell, s] : sums)
        if (s.second >= min_pixels) out[cell] = Rgb{s.first.r / s.second, s.first.g / s.second, s.first.b / s.second};
    return out;
}

/// A green hill rising from a beach across calm water (a plane climbing 0.3 m a metre from
/// a shore 50 m off): the camera 4 m up looks down at the water 20 m away with a field of 20
/// degrees, which leaves the grass the water reflects above the frame's top edge, and with
/// 60 degrees, which shows it. The same water (1 m cells) must look the same in both
/// frames: within 8/255 on average over the cells, the largest channel's difference. (Taking
/// the reflection from the frame's copy wherever the reflected point projected, the narrow
/// frame's water carried streaks of the beach at its top edge: 16.6/255 on average.)
TEST_F(RenderTest, ReflectedLandIsItsOwnColourWhereTheCameraDoesNotSeeIt) {
    const Scene scene =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"plane": {"height": -15, "slope": [0.3, 0.0]}},
        "ocean": {"waves": [{"direction": 180, "wavelength": 8, "amplitude": 0.05, "steepness": 0.3},
                            {"direction": 160, "wavelength": 5, "amplitude": 0.03, "steepness": 0.3}]}})");
    render::FrameInfo frame;
    frame.time = 3.0;
    frame.camera.position = {0.0, 4.0, 0.0};
    frame.camera.target = {20.0, 0.0, 0.0};
    frame.camera.fov_y_deg = 20.0;
    const auto narrow_img = render(scene, frame, 480, 270);
    const render::Camera narrow_camera = frame.camera;
    frame.camera.fov_y_deg = 60.0;
    const auto wide_img = render(scene, frame, 480, 270);
    ASSERT_GT(narrow_img.width, 0u);
    ASSERT_GT(wide_img.width, 0u);
    const auto narrow = water_cells(narrow_img, narrow_camera, 20);
    const auto wide = water_cells(wide_img, frame.camera, 4);
    std::vector<double> differences;
    for (const auto& [cell, a] : narrow) {
        const auto it = wide.find(cell);
        if (it == wide.end()) continue;
        const Rgb& b = it->second;
        differences.push_back(std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}));
    }
    ASSERT_GT(differences.size(), 300u);
    double mean = 0.0;
    for (double d : differences) mean += d / static_cast<double>(differences.size());
    std::printf("reflected land: %zu cells in both frames, mean difference %.1f/255\n", differences.size(),
                mean * 255.0);
    EXPECT_LT(mean, 8.0 / 255.0);
}

}  // namespace
}  // namespace tidewater
