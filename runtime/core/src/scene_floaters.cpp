#include "tidewater/scene_floaters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <span>
#include <vector>

#include "tidewater/constants.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {

namespace {

RigidBodyProps float_props(const SceneFloat& f) {
    switch (f.shape) {
        case SceneFloat::Shape::box:
        case SceneFloat::Shape::open_box:  // it floats as the closed box: its hold stays dry
            return RigidBodyProps::solid_box(f.size, f.mass);
        case SceneFloat::Shape::sphere: {
            RigidBodyProps p;
            p.mass = f.mass;
            const double r = 0.5 * f.size.x;
            p.inertia = glm::dvec3(0.4 * f.mass * r * r);
            p.hull = HullMesh::sphere(r, 8);
            return p;
        }
        case SceneFloat::Shape::barrel:
            break;
    }
    RigidBodyProps p = RigidBodyProps::barrel(0.5 * f.size.x, f.size.y, f.mass);
    p.hull = HullMesh::cylinder(0.5 * f.size.x, f.size.y, 12);
    return p;
}

/// Where a float keeps the water out, in its body frame: its own shape, or for a barrel
/// the capsule inside it.
ClipVolume float_clip(const SceneFloat& f) {
    const double r = 0.5 * f.size.x;
    switch (f.shape) {
        case SceneFloat::Shape::box:
        case SceneFloat::Shape::open_box:
            return ClipVolume::box(glm::dvec3(0.0), 0.5 * f.size);
        case SceneFloat::Shape::sphere:
            return ClipVolume::sphere(glm::dvec3(0.0), r);
        case SceneFloat::Shape::barrel:
            break;
    }
    return ClipVolume::capsule(glm::dvec3(0.0), std::max(0.5 * f.size.y - r, 0.0), r);
}

/// A boat's dry inside (HullMesh::boat): the convex prism of its hull, keel to deck (the
/// plan's corners at the keel, a hair inside the hull), bow included; the deckhouse above
/// the deck is out of the water anyway.
ClipVolume boat_clip(const HullMesh& hull, double draft) {
    std::vector<glm::dvec2> plan;
    for (const glm::dvec3& v : hull.vertices)
        if (std::abs(v.y + draft) < 1e-9 * std::max(draft, 1.0)) plan.emplace_back(v.x, v.z);
    glm::dvec2 centre(0.0);
    for (const glm::dvec2& q : plan) centre += q / static_cast<double>(plan.size());
    // The plan's convex outline (Andrew's monotone chain), shrunk 2 % toward its centre.
    std::sort(plan.begin(), plan.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto turn = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> outline;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = outline.size();
        for (std::size_t k = 0; k < plan.size(); ++k) {
            const glm::dvec2 q = plan[pass == 0 ? k : plan.size() - 1 - k];
            while (outline.size() >= start + 2 && turn(outline[outline.size() - 2], outline.back(), q) <= 0.0)
                outline.pop_back();
            outline.push_back(q);
        }
        outline.pop_back();
    }
    constexpr double kInset = 0.98;
    std::vector<glm::dvec4> planes = {{0.0, 1.0, 0.0, draft * kInset}, {0.0, -1.0, 0.0, draft * kInset}};
    for (std::size_t k = 0; k < outline.size(); ++k) {
        const glm::dvec2 a = centre + kInset * (outline[k] - centre);
        const glm::dvec2 b = centre + kInset * (outline[(k + 1) % outline.size()] - centre);
        glm::dvec2 n = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
        if (glm::dot(n, centre - a) > 0.0) n = -n;  // outward
        planes.emplace_back(n.x, 0.0, n.y, glm::dot(n, a));
    }
    return ClipVolume::convex(glm::dvec3(0.0), std::move(planes));
}

/// Where the body frame's origin rests in calm water above the surface: the bottom sits
/// the Archimedes draft under it (a sphere's centre at the surface, near enough).
double rest_height(const SceneFloat& f) {
    if (f.shape == SceneFloat::Shape::sphere) return 0.0;
    const bool boxed = f.shape == SceneFloat::Shape::box || f.shape == SceneFloat::Shape::open_box;
    const double plan = boxed ? f.size.x * f.size.z : 0.25 * kPi * f.size.x * f.size.x;
    return 0.5 * f.size.y - f.mass / (kWaterDensity * plan);
}

/// The rotation that points the body's x axis along `heading` (radians from +x toward +z).
glm::dquat yaw(double heading) {
    return glm::angleAxis(-heading, glm::dvec3(0.0, 1.0, 0.0));
}

}  // namespace

Result<SceneFloaters> SceneFloaters::create(std::shared_ptr<const Scene> scene, double start, double step) {
    if (!scene) return Error{ErrorCode::invalid_argument, "scene floaters: no scene"};
    if (!(step > 0.0) || step > 0.5)
        return Error{ErrorCode::invalid_argument, fmt::format("scene floaters: step {} s must be in (0, 0.5]", step)};
    if (!std::isfinite(start))
        return Error{ErrorCode::invalid_argument, "scene floaters: the start time is not finite"};
    SceneFloaters f(scene, step);
    const double from = start - kSceneFloatSettle;
    f.world_.set_time(from);
    for (std::size_t i = 0; i < scene->boats.size(); ++i) {
        const SceneBoat& b = scene->boats[i];
        // A boat over land would sink through it (there is no contact): refuse the path.
        const double length = b.path_length(), spacing = 0.5 * b.hull.length;
        for (double d = 0.0; d <= length + 0.5 * spacing; d += spacing) {
            glm::dvec2 at;
            double heading = 0.0;
            b.pose_at(b.start + std::min(d, length) / b.speed, at, heading);
            if (query_world_point(*scene, from, at).body.kind == BodyKind::none)
                return Error{
                    ErrorCode::invalid_argument,
                    fmt::format("boats/{} ({}): its path runs over land at ({:.1f}, {:.1f}), {:.0f} m along it", i,
                                b.name, at.x, at.y, std::min(d, length))};
        }
        // Inertia as a solid box round the hull; the boat's own hull for the water.
        const double mass = kWaterDensity * HullMesh::boat_plan_area(b.hull.length, b.hull.beam) * b.hull.draft;
        RigidBodyProps props =
            RigidBodyProps::solid_box(glm::dvec3(b.hull.length, 2.0 * b.hull.draft, b.hull.beam), mass);
        props.hull = HullMesh::boat(b.hull.length, b.hull.beam, b.hull.draft);
        props.emitter = static_cast<int>(i);  // scene_boat_wakes: boat i is emitter i
        RigidBodyState s;
        glm::dvec2 at;
        double heading = 0.0;
        b.pose_at(from, at, heading);
        // The water under it without its own wake (its buoyancy leaves that out too).
        QueryOptions own;
        own.exclude_emitter = static_cast<int>(i);
        WorldPoint under;
        if (auto st =
                query_world(*scene, from, std::span<const glm::dvec2>(&at, 1), std::span<WorldPoint>(&under, 1), own);
            !st)
            return st.error();
        s.position = {at.x, under.surface.height, at.y};
        s.orientation = yaw(heading);
        glm::dvec2 ahead;
        double heading_ahead = 0.0;
        b.pose_at(from + step, ahead, heading_ahead);
        s.velocity = glm::dvec3(ahead.x - at.x, 0.0, ahead.y - at.y) / step;  // under way from the start
        auto id = f.world_.add(props, s);
        if (!id) return Error{id.error().code, fmt::format("boats/{} ({}): {}", i, b.name, id.error().message)};
        f.bodies_.push_back(
            {b.name, props.hull, glm::vec3(0.62f, 0.16f, 0.10f), true, boat_clip(props.hull, b.hull.draft)});
    }
    for (std::size_t i = 0; i < scene->floats.size(); ++i) {
        const SceneFloat& sf = scene->floats[i];
        const RigidBodyProps props = float_props(sf);
        RigidBodyState s;
        const WorldPoint under = query_world_point(*scene, from, sf.at);
        if (under.body.kind == BodyKind::none)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("floats/{} ({}): ({}, {}) is on land", i, sf.name, sf.at.x, sf.at.y)};
        s.position = {sf.at.x, under.surface.height + rest_height(sf), sf.at.y};
        auto id = f.world_.add(props, s);
        if (!id) return Error{id.error().code, fmt::format("floats/{} ({}): {}", i, sf.name, id.error().message)};
        // An open box is drawn without its lid; it floats as the closed box.
        const HullMesh drawn = sf.shape == SceneFloat::Shape::open_box ? HullMesh::open_box(sf.size) : props.hull;
        f.bodies_.push_back({sf.name, drawn, sf.color, false, float_clip(sf)});
    }
    if (auto st = f.advance_to(start); !st) return st.error();
    return f;
}

Status SceneFloaters::set_scene(std::shared_ptr<const Scene> scene) {
    if (!scene) return Error{ErrorCode::invalid_argument, "scene floaters: no scene"};
    if (scene->boats.size() != scene_->boats.size() || scene->floats.size() != scene_->floats.size())
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("scene floaters: the scene has {} boats and {} floats, these {} and {}: create them again",
                        scene->boats.size(), scene->floats.size(), scene_->boats.size(), scene_->floats.size())};
    scene_ = std::move(scene);
    return {};
}

Status SceneFloaters::advance_to(double time) {
    if (!std::isfinite(time)) return Error{ErrorCode::invalid_argument, "scene floaters: the time is not finite"};
    const FloatingWater water{scene_.get(), nullptr, nullptr};
    const double step = world_.options().step;
    while (world_.time() + 0.5 * step <= time) {
        if (auto st = world_.step(water); !st) return st;
        hold_boats_to_their_paths();
    }
    return {};
}

void SceneFloaters::hold_boats_to_their_paths() {
    const double t = world_.time(), dt = world_.options().step;
    for (std::size_t i = 0; i < scene_->boats.size(); ++i) {
        const SceneBoat& b = scene_->boats[i];
        glm::dvec2 at, ahead;
        double heading = 0.0, heading_ahead = 0.0;
        b.pose_at(t, at, heading);
        b.pose_at(t + dt, ahead, heading_ahead);
        RigidBodyState& s = world_.state(static_cast<int>(i));
        s.position.x = at.x;
        s.position.z = at.y;
        const glm::dvec2 v = (ahead - at) / dt;
        s.velocity.x = v.x;
        s.velocity.z = v.y;
        // Turn the body about the vertical so its x axis points along the path, keeping its pitch and roll.
        const glm::dvec3 forward = s.orientation * glm::dvec3(1.0, 0.0, 0.0);
        const double current = std::atan2(forward.z, forward.x);
        s.orientation = glm::normalize(yaw(std::remainder(heading - current, kTwoPi)) * s.orientation);
        s.angular_velocity.y = -std::remainder(heading_ahead - heading, kTwoPi) / dt;
    }
}

SceneFloaters::Pose SceneFloaters::pose(std::size_t body) const {
    const RigidBodyState& s = world_.state(static_cast<int>(body));
    return {s.position, s.orientation};
}

}  // namespace tidewater
