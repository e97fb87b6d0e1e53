#include "float_uploads.hpp"

#include <fmt/format.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "tidewater/buoyancy.hpp"
#include "tidewater/scene_floaters.hpp"

namespace tidewater::render {

std::vector<FloatDraw> float_draws(const SceneFloaters& floaters) {
    std::vector<FloatDraw> draws;
    draws.reserve(floaters.bodies().size());
    for (std::size_t b = 0; b < floaters.bodies().size(); ++b) {
        const SceneFloaters::Pose pose = floaters.pose(b);
        const SceneFloaters::Body& body = floaters.bodies()[b];
        draws.push_back({&body.hull, pose.position, pose.orientation, body.color, body.clip});
    }
    return draws;
}

}  // namespace tidewater::render

namespace tidewater::render::detail {

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

Result<FloatUpload> pack_floats(std::span<const FloatDraw> floats, glm::dvec2 origin) {
    FloatUpload out;
    const glm::dvec3 origin3(origin.x, 0.0, origin.y);
    for (std::size_t i = 0; i < floats.size(); ++i) {
        const FloatDraw& f = floats[i];
        const std::string what = fmt::format("renderer: FrameInfo::floats[{}]", i);
        if (f.hull == nullptr) return Error{ErrorCode::invalid_argument, what + ": no hull"};
        if (auto st = f.hull->validate(); !st)
            return Error{ErrorCode::invalid_argument, what + ": " + st.error().message};
        const glm::dvec4 q(f.orientation.x, f.orientation.y, f.orientation.z, f.orientation.w);
        if (!finite(f.position) || !std::isfinite(q.x + q.y + q.z + q.w) || glm::length(q) < 1e-6)
            return Error{ErrorCode::invalid_argument,
                         what + ": the position and orientation must be finite (a non-zero quaternion)"};
        if (!(f.color.r >= 0.0f && f.color.g >= 0.0f && f.color.b >= 0.0f && f.color.r <= 1.0f && f.color.g <= 1.0f &&
              f.color.b <= 1.0f))
            return Error{ErrorCode::invalid_argument, what + ": color must be linear RGB in 0..1"};
        const std::size_t count = 3 * f.hull->triangles.size();
        if (out.vertices.size() + count > kMaxFloatVertices)
            return Error{
                ErrorCode::invalid_argument,
                fmt::format("{}: the floats' hulls hold more than {} triangles in all", what, kMaxFloatVertices / 3)};
        const glm::dquat rotation = glm::normalize(f.orientation);
        FloatUpload::Draw draw;
        draw.first = static_cast<std::uint32_t>(out.vertices.size());
        draw.count = static_cast<std::uint32_t>(count);
        draw.color = f.color;
        for (const auto& t : f.hull->triangles) {
            glm::dvec3 p[3];
            for (std::size_t k = 0; k < 3; ++k) p[k] = f.position + rotation * f.hull->vertices[t[k]] - origin3;
            const glm::dvec3 c = glm::cross(p[1] - p[0], p[2] - p[0]);
            const double len = glm::length(c);
            const glm::vec3 n = len > 0.0 ? glm::vec3(c / len) : glm::vec3(0.0f, 1.0f, 0.0f);
            for (const glm::dvec3& v : p) out.vertices.push_back({glm::vec3(v), n});
        }
        out.draws.push_back(draw);
    }
    return out;
}

}  // namespace tidewater::render::detail
