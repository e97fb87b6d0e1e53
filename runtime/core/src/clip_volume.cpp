#include "tidewater/clip_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tidewater {

ClipVolume ClipVolume::box(glm::dvec3 center, glm::dvec3 half_extents, glm::dquat orientation) {
    ClipVolume v;
    v.shape = Shape::box;
    v.center = center;
    v.half_extents = half_extents;
    v.orientation = orientation;
    return v;
}

ClipVolume ClipVolume::sphere(glm::dvec3 center, double radius) {
    ClipVolume v;
    v.shape = Shape::sphere;
    v.center = center;
    v.radius = radius;
    return v;
}

ClipVolume ClipVolume::capsule(glm::dvec3 center, double half_length, double radius, glm::dquat orientation) {
    ClipVolume v;
    v.shape = Shape::capsule;
    v.center = center;
    v.half_length = half_length;
    v.radius = radius;
    v.orientation = orientation;
    return v;
}

double clip_distance(const ClipVolume& volume, glm::dvec3 p) {
    // In the volume's own frame.
    const glm::dvec3 local = glm::conjugate(glm::normalize(volume.orientation)) * (p - volume.center);
    switch (volume.shape) {
        case ClipVolume::Shape::box: {
            const glm::dvec3 q = glm::abs(local) - volume.half_extents;
            const double outside = glm::length(glm::max(q, glm::dvec3(0.0)));
            return outside + std::min(std::max({q.x, q.y, q.z}), 0.0);
        }
        case ClipVolume::Shape::sphere:
            return glm::length(local) - volume.radius;
        case ClipVolume::Shape::capsule: {
            const double y = std::clamp(local.y, -volume.half_length, volume.half_length);
            return glm::length(local - glm::dvec3(0.0, y, 0.0)) - volume.radius;
        }
    }
    return 1.0;
}

bool inside_any(std::span<const ClipVolume> volumes, glm::dvec3 p) {
    return std::any_of(volumes.begin(), volumes.end(), [&](const ClipVolume& v) { return clip_distance(v, p) < 0.0; });
}

Status validate(const ClipVolume& volume, const std::string& context) {
    auto size_ok = [](double v) { return std::isfinite(v) && v > 0.0 && v <= 1e5; };
    auto error = [&](const char* field, const std::string& what) {
        return Error{ErrorCode::schema_error, fmt::format("{}/{}: {}", context, field, what)};
    };
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(volume.center[c]) || std::abs(volume.center[c]) > 1e7)
            return error("center", fmt::format("{} is out of range (|value| <= 1e7 m)", volume.center[c]));
    const glm::dquat q = volume.orientation;
    const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!std::isfinite(norm) || norm < 1e-9) return error("orientation", "must be a finite, non-zero quaternion");
    switch (volume.shape) {
        case ClipVolume::Shape::box:
            for (int c = 0; c < 3; ++c)
                if (!size_ok(volume.half_extents[c]))
                    return error("half_extents",
                                 fmt::format("{} is out of range (0 < value <= 1e5 m)", volume.half_extents[c]));
            break;
        case ClipVolume::Shape::capsule:
            if (!(std::isfinite(volume.half_length) && volume.half_length >= 0.0 && volume.half_length <= 1e5))
                return error("half_length", fmt::format("{} is out of range (0 to 1e5 m)", volume.half_length));
            [[fallthrough]];
        case ClipVolume::Shape::sphere:
            if (!size_ok(volume.radius))
                return error("radius", fmt::format("{} is out of range (0 < value <= 1e5 m)", volume.radius));
            break;
    }
    return {};
}

}  // namespace tidewater
