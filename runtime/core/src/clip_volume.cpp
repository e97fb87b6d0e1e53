#include "tidewater/clip_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <utility>

namespace tidewater {

Result<std::shared_ptr<const DistanceTexture>> DistanceTexture::create(glm::uvec3 size, std::vector<float> distances) {
    auto refuse = [](const std::string& what) {
        return Error{ErrorCode::invalid_argument, fmt::format("distance texture: {}", what)};
    };
    for (int c = 0; c < 3; ++c)
        if (size[c] < kMinSide || size[c] > kMaxSide)
            return refuse(
                fmt::format("{} samples along {}; each side has {} to {}", size[c], "xyz"[c], kMinSide, kMaxSide));
    const std::size_t samples = std::size_t{size.x} * size.y * size.z;
    if (distances.size() != samples)
        return refuse(fmt::format("{} distances for {} x {} x {} samples ({})", distances.size(), size.x, size.y,
                                  size.z, samples));
    bool inside = false;
    for (std::size_t i = 0; i < samples; ++i) {
        if (!std::isfinite(distances[i]) || std::abs(distances[i]) > 1e5f)
            return refuse(fmt::format("sample {} is {} (finite, |value| <= 1e5 m)", i, distances[i]));
        inside = inside || distances[i] < 0.0f;
    }
    if (!inside) return refuse("no sample is negative: the texture is nowhere inside");
    return std::shared_ptr<const DistanceTexture>(new DistanceTexture(size, std::move(distances)));
}

// Trilinear between the samples of the box's nearest point, plus the distance to it; the
// twin of clip_volumes.glsl's texture_distance.
double DistanceTexture::distance(glm::dvec3 local, glm::dvec3 half_extents) const {
    const glm::dvec3 nearest = glm::clamp(local, -half_extents, half_extents);
    const double outside = glm::length(local - nearest);
    const glm::dvec3 last = glm::dvec3(size_) - 1.0;
    const glm::dvec3 u = (nearest + half_extents) / (2.0 * half_extents) * last;
    const glm::dvec3 cell = glm::min(glm::floor(u), last - 1.0);
    const glm::dvec3 f = u - cell;
    const std::size_t i = static_cast<std::size_t>(cell.x), j = static_cast<std::size_t>(cell.y),
                      k = static_cast<std::size_t>(cell.z);
    const std::size_t row = size_.x, slice = std::size_t{size_.x} * size_.y;
    auto at = [&](std::size_t di, std::size_t dj, std::size_t dk) {
        return static_cast<double>(distances_[(i + di) + row * (j + dj) + slice * (k + dk)]);
    };
    auto along_x = [&](std::size_t dj, std::size_t dk) { return glm::mix(at(0, dj, dk), at(1, dj, dk), f.x); };
    const double near_z = glm::mix(along_x(0, 0), along_x(1, 0), f.y);
    const double far_z = glm::mix(along_x(0, 1), along_x(1, 1), f.y);
    return glm::mix(near_z, far_z, f.z) + outside;
}

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

ClipVolume ClipVolume::convex(glm::dvec3 center, std::vector<glm::dvec4> planes, glm::dquat orientation) {
    ClipVolume v;
    v.shape = Shape::convex;
    v.center = center;
    v.orientation = orientation;
    for (glm::dvec4& plane : planes) {
        const double length = glm::length(glm::dvec3(plane));
        if (length > 0.0) plane /= length;  // a zero normal stays for validate to refuse
    }
    v.planes = std::move(planes);
    return v;
}

Result<ClipVolume> ClipVolume::convex_mesh(glm::dvec3 center, std::span<const glm::dvec3> vertices,
                                           std::span<const std::array<std::uint32_t, 3>> triangles,
                                           glm::dquat orientation) {
    auto refuse = [](const std::string& what) {
        return Error{ErrorCode::invalid_argument, fmt::format("convex clip volume: {}", what)};
    };
    if (vertices.size() < 4 || triangles.size() < 4) return refuse("a closed mesh needs 4 vertices and 4 triangles");
    double extent = 0.0;
    for (const glm::dvec3& v : vertices) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return refuse("a vertex is not finite");
        extent = std::max({extent, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    }
    // Closed: every edge is shared by exactly two triangles, once each way.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = t[static_cast<std::size_t>(e)], b = t[static_cast<std::size_t>((e + 1) % 3)];
            if (a >= vertices.size() || b >= vertices.size()) return refuse("a triangle's index is out of range");
            ++edges[{a, b}];
        }
    for (const auto& [edge, count] : edges)
        if (count != 1 || edges.count({edge.second, edge.first}) == 0 || edges.at({edge.second, edge.first}) != 1)
            return refuse(
                fmt::format("the mesh is not closed and consistently wound (edge {}-{})", edge.first, edge.second));
    const double tolerance = 1e-6 * std::max(extent, 1.0);
    std::vector<glm::dvec4> planes;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const glm::dvec3 a = vertices[triangles[i][0]], b = vertices[triangles[i][1]], c = vertices[triangles[i][2]];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double area2 = glm::length(n);
        if (!(area2 > tolerance * tolerance)) continue;  // a sliver adds no face
        const glm::dvec3 unit = n / area2;
        const glm::dvec4 plane(unit, glm::dot(unit, a));
        const bool known = std::any_of(planes.begin(), planes.end(), [&](const glm::dvec4& q) {
            return glm::dot(glm::dvec3(q), unit) > 1.0 - 1e-9 && std::abs(q.w - plane.w) <= tolerance;
        });
        if (!known) planes.push_back(plane);
    }
    if (planes.size() < 4) return refuse("the mesh is flat (fewer than 4 faces with area)");
    if (planes.size() > kMaxPlanes)
        return refuse(fmt::format("{} faces; at most {} (simplify the mesh)", planes.size(), kMaxPlanes));
    // Convex and outward: no vertex in front of a face.
    for (std::size_t p = 0; p < planes.size(); ++p)
        for (std::size_t v = 0; v < vertices.size(); ++v)
            if (glm::dot(glm::dvec3(planes[p]), vertices[v]) > planes[p].w + tolerance)
                return refuse(
                    fmt::format("the mesh is not convex (or not wound outward): vertex {} lies {:.3g} m in "
                                "front of a face",
                                v, glm::dot(glm::dvec3(planes[p]), vertices[v]) - planes[p].w));
    return convex(center, std::move(planes), orientation);
}

ClipVolume ClipVolume::distance_texture(glm::dvec3 center, glm::dvec3 half_extents,
                                        std::shared_ptr<const DistanceTexture> texture, glm::dquat orientation) {
    ClipVolume v;
    v.shape = Shape::distance_texture;
    v.center = center;
    v.half_extents = half_extents;
    v.texture = std::move(texture);
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
        case ClipVolume::Shape::convex: {
            double d = -std::numeric_limits<double>::infinity();
            for (const glm::dvec4& plane : volume.planes) d = std::max(d, glm::dot(glm::dvec3(plane), local) - plane.w);
            return volume.planes.empty() ? 1.0 : d;
        }
        case ClipVolume::Shape::distance_texture:
            return volume.texture ? volume.texture->distance(local, volume.half_extents) : 1.0;
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
        case ClipVolume::Shape::distance_texture:
            if (!volume.texture) return error("texture", "a distance-texture volume needs its texture");
            [[fallthrough]];
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
        case ClipVolume::Shape::convex:
            if (volume.planes.size() < 4 || volume.planes.size() > ClipVolume::kMaxPlanes)
                return error("planes", fmt::format("{} planes; a convex volume has 4 to {}", volume.planes.size(),
                                                   ClipVolume::kMaxPlanes));
            for (std::size_t i = 0; i < volume.planes.size(); ++i) {
                const glm::dvec4& plane = volume.planes[i];
                const double length = glm::length(glm::dvec3(plane));
                if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-6)
                    return error(fmt::format("planes/{}", i).c_str(), "the normal must be a finite unit vector");
                if (!std::isfinite(plane.w) || std::abs(plane.w) > 1e5)
                    return error(fmt::format("planes/{}", i).c_str(),
                                 fmt::format("offset {} is out of range (|value| <= 1e5 m)", plane.w));
            }
            break;
    }
    return {};
}

}  // namespace tidewater
