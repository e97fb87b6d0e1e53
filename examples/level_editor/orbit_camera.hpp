// The viewport's orbit camera: yaw, pitch and distance round a target point, and the ray
// under a cursor position. Units: metres, degrees for the field of view.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <tidewater/render/renderer.hpp>

namespace tidewater::editor {

struct OrbitCamera {
    glm::dvec3 target{0.0};
    double yaw = 0.0, pitch = 0.3, distance = 500.0;  // radians, radians, m
    double fov_y_deg = 50.0;

    static OrbitCamera looking(glm::dvec3 position, glm::dvec3 target, double fov) {
        OrbitCamera c;
        const glm::dvec3 d = position - target;
        c.target = target;
        c.distance = glm::length(d);
        c.yaw = std::atan2(d.z, d.x);
        c.pitch = std::asin(std::clamp(d.y / c.distance, -1.0, 1.0));
        c.fov_y_deg = fov;
        return c;
    }
    glm::dvec3 position() const {
        return target +
               distance * glm::dvec3(std::cos(pitch) * std::cos(yaw), std::sin(pitch), std::cos(pitch) * std::sin(yaw));
    }
    render::Camera camera() const {
        render::Camera c;
        c.position = position();
        c.target = target;
        c.fov_y_deg = fov_y_deg;
        return c;
    }
    void orbit(double dx, double dy) {
        yaw += dx * 0.005;
        pitch = std::clamp(pitch + dy * 0.005, 0.02, 1.5);
    }
    void zoom(double steps) { distance = std::clamp(distance * std::pow(0.9, steps), 5.0, 20000.0); }
    void pan(double dx, double dy) {
        const glm::dvec3 forward = glm::normalize(target - position());
        const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
        const glm::dvec3 ahead = glm::normalize(glm::dvec3(forward.x, 0.0, forward.z));
        target += (-dx * right + dy * ahead) * distance * 0.0015;
    }
    /// The world ray through pixel (x, y) of a width x height viewport (origin top left).
    glm::dvec3 ray(double x, double y, double width, double height) const {
        const glm::dvec3 forward = glm::normalize(target - position());
        const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
        const glm::dvec3 up = glm::cross(right, forward);
        const double tan_half = std::tan(0.5 * fov_y_deg * 3.141592653589793 / 180.0);
        const double ndc_x = 2.0 * x / width - 1.0, ndc_y = 1.0 - 2.0 * y / height;
        return glm::normalize(forward + right * (ndc_x * tan_half * width / height) + up * (ndc_y * tan_half));
    }
};

}  // namespace tidewater::editor
