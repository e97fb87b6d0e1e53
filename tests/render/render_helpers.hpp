// Rendering helpers for tests: render a scene offscreen and look at pixels.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

#include "frame_constants.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"

namespace tidewater::test {

struct Rgb {
    double r = 0, g = 0, b = 0;  // 0..1
};

/// The default island seen from 30 m up and 160 m out, at 2 s: a frame tests draw when
/// what it shows does not matter.
inline render::FrameInfo island_frame() {
    render::FrameInfo frame;
    frame.camera.position = {0.0, 30.0, 160.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.time = 2.0;
    return frame;
}

inline Rgb pixel(const render::RgbaImage& img, int x, int y) {
    const std::size_t i =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
    return {img.pixels[i] / 255.0, img.pixels[i + 1] / 255.0, img.pixels[i + 2] / 255.0};
}

/// The unit direction from the camera through the centre of pixel (x, y) of a w x h frame
/// (rows down from the top), from the near plane's corners.
inline glm::dvec3 pixel_ray(const render::Camera& camera, int w, int h, int x, int y) {
    const auto c = render::near_plane_corners(camera, static_cast<double>(w) / h);
    const double u = (x + 0.5) / w, v = 1.0 - (y + 0.5) / h;  // v up from the bottom
    const glm::dvec3 bottom = c[0] + (c[1] - c[0]) * u, top = c[3] + (c[2] - c[3]) * u;
    return glm::normalize(bottom + (top - bottom) * v - camera.position);
}

/// `measured` against `theory` times one scale (least squares through the origin), and
/// the share of measured's variance about its mean the scaled theory explains.
struct ScaleFit {
    double scale = 0.0;
    double r2 = 0.0;
};
inline ScaleFit fit_one_scale(const std::vector<double>& measured, const std::vector<double>& theory) {
    double mt = 0.0, tt = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < measured.size(); ++i) {
        mt += measured[i] * theory[i];
        tt += theory[i] * theory[i];
        mean += measured[i] / static_cast<double>(measured.size());
    }
    ScaleFit fit;
    fit.scale = mt / tt;
    double residual = 0.0, total = 0.0;
    for (std::size_t i = 0; i < measured.size(); ++i) {
        residual += std::pow(measured[i] - fit.scale * theory[i], 2.0);
        total += std::pow(measured[i] - mean, 2.0);
    }
    fit.r2 = 1.0 - residual / total;
    return fit;
}

/// Mean |a - b| over the colour channels of two pictures of one size, 0..1.
inline double mean_difference(const render::RgbaImage& a, const render::RgbaImage& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4)
        for (std::size_t k = 0; k < 3; ++k) sum += std::abs(int(a.pixels[i + k]) - int(b.pixels[i + k]));
    return sum / static_cast<double>(a.pixels.size() / 4 * 3) / 255.0;
}

/// How far a picture is from a reference of its size: per pixel, the largest difference of
/// its colour channels (0..1); their mean and 99th percentile.
struct ImageDifference {
    double mean = 0.0, p99 = 0.0;
};
template <class ImageA, class ImageB>
ImageDifference image_difference(const ImageA& a, const ImageB& b) {
    if (a.pixels.size() != b.pixels.size() || a.pixels.empty()) return {1.0, 1.0};
    std::vector<int> diffs;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
        int d = 0;
        for (std::size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a.pixels[i + k]) - int(b.pixels[i + k])));
        diffs.push_back(d);
        sum += d;
    }
    std::sort(diffs.begin(), diffs.end());
    return {sum / static_cast<double>(diffs.size()) / 255.0, diffs[diffs.size() * 99 / 100] / 255.0};
}

/// Mean colour of a (2r+1)^2 block around (x, y).
inline Rgb block(const render::RgbaImage& img, int x, int y, int r = 3) {
    Rgb sum;
    int n = 0;
    for (int j = std::max(0, y - r); j <= std::min(img.height - 1, y + r); ++j)
        for (int i = std::max(0, x - r); i <= std::min(img.width - 1, x + r); ++i) {
            const Rgb p = pixel(img, i, j);
            sum.r += p.r;
            sum.g += p.g;
            sum.b += p.b;
            ++n;
        }
    return {sum.r / n, sum.g / n, sum.b / n};
}

/// Where a world point lands in the image (same camera maths as the renderer), if in front.
inline std::optional<glm::ivec2> project(const render::Camera& cam, int width, int height, glm::dvec3 world) {
    const glm::dmat4 view = glm::lookAt(cam.position, cam.target, glm::dvec3(0, 1, 0));
    const glm::dmat4 proj =
        glm::dmat4(render::detail::reversed_z_projection(cam.fov_y_deg, double(width) / height, cam.near_plane));
    const glm::dvec4 clip = proj * view * glm::dvec4(world, 1.0);
    if (clip.w <= 0.0) return std::nullopt;
    const double x = (clip.x / clip.w * 0.5 + 0.5) * width, y = (clip.y / clip.w * 0.5 + 0.5) * height;
    if (x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
    return glm::ivec2(static_cast<int>(x), static_cast<int>(y));
}

}  // namespace tidewater::test
