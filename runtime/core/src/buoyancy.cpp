#include "tidewater/buoyancy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <map>

#include "tidewater/constants.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {

HullMesh HullMesh::box(glm::dvec3 size) {
    const glm::dvec3 h = 0.5 * size;
    HullMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
    // Two triangles per face, counter-clockwise seen from outside.
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        m.triangles.push_back({f[0], f[1], f[2]});
        m.triangles.push_back({f[0], f[2], f[3]});
    }
    return m;
}

HullMesh HullMesh::open_box(glm::dvec3 size) {
    HullMesh m = box(size);
    // box()'s fourth face, {2, 6, 7, 3}, is its top.
    m.triangles.erase(m.triangles.begin() + 6, m.triangles.begin() + 8);
    return m;
}

HullMesh HullMesh::sphere(double radius, int rings) {
    HullMesh m;
    const int segments = 2 * rings;
    m.vertices.push_back({0.0, radius, 0.0});
    for (int r = 1; r < rings; ++r) {
        const double polar = kPi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double azimuth = kTwoPi * s / segments;
            m.vertices.push_back(radius * glm::dvec3(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                                     std::sin(polar) * std::sin(azimuth)));
        }
    }
    m.vertices.push_back({0.0, -radius, 0.0});
    const auto ring = [&](int r, int s) { return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments)); };
    const auto bottom = static_cast<std::uint32_t>(m.vertices.size() - 1);
    for (int s = 0; s < segments; ++s) {
        m.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
        for (int r = 1; r + 1 < rings; ++r) {
            m.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s + 1)});
            m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r + 1, s)});
        }
        m.triangles.push_back({bottom, ring(rings - 1, s), ring(rings - 1, s + 1)});
    }
    return m;
}

HullMesh HullMesh::cylinder(double radius, double height, int segments) {
    HullMesh m;
    const double h = 0.5 * height;
    for (int s = 0; s < segments; ++s) {
        const double a = kTwoPi * s / segments;
        m.vertices.push_back({radius * std::cos(a), h, radius * std::sin(a)});
        m.vertices.push_back({radius * std::cos(a), -h, radius * std::sin(a)});
    }
    m.vertices.push_back({0.0, h, 0.0});
    m.vertices.push_back({0.0, -h, 0.0});
    const auto top = static_cast<std::uint32_t>(2 * segments), bottom = top + 1;
    for (int s = 0; s < segments; ++s) {
        const auto t0 = static_cast<std::uint32_t>(2 * s), b0 = t0 + 1;
        const auto t1 = static_cast<std::uint32_t>(2 * ((s + 1) % segments)), b1 = t1 + 1;
        m.triangles.push_back({t0, t1, b1});
        m.triangles.push_back({t0, b1, b0});
        m.triangles.push_back({top, t1, t0});
        m.triangles.push_back({bottom, b0, b1});
    }
    return m;
}

namespace {

/// A convex prism over `outline` (x, z) from y0 to y1, appended to `m`, each face wound
/// counter-clockwise seen from outside.
void add_prism(HullMesh& m, const std::vector<glm::dvec2>& outline, double y0, double y1) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    const auto n = static_cast<std::uint32_t>(outline.size());
    glm::dvec3 centre(0.0, 0.5 * (y0 + y1), 0.0);
    for (const glm::dvec2& p : outline) {
        m.vertices.push_back({p.x, y0, p.y});
        m.vertices.push_back({p.x, y1, p.y});
        centre += glm::dvec3(p.x, 0.0, p.y) / double(n);
    }
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        faces.push_back({base + 2 * i, base + 2 * j, base + 2 * j + 1});  // side
        faces.push_back({base + 2 * i, base + 2 * j + 1, base + 2 * i + 1});
        if (i >= 1 && i + 1 < n) {
            faces.push_back({base, base + 2 * i, base + 2 * j});              // bottom fan
            faces.push_back({base + 1, base + 2 * i + 1, base + 2 * j + 1});  // top fan
        }
    }
    for (auto f : faces) {  // a convex solid: each face's normal points away from its centre
        const glm::dvec3 a = m.vertices[f[0]], b = m.vertices[f[1]], c = m.vertices[f[2]];
        if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - centre) < 0.0) std::swap(f[1], f[2]);
        m.triangles.push_back(f);
    }
}

std::vector<glm::dvec2> boat_plan(double length, double beam) {
    const double shoulder = 0.2 * length, half = 0.5 * beam;
    std::vector<glm::dvec2> plan = {
        {-0.5 * length, -half}, {shoulder, -half}, {0.5 * length, 0.0}, {shoulder, half}, {-0.5 * length, half}};
    // Put the plan's centroid (rectangle aft, triangle forward) on the origin.
    const double rect = (shoulder + 0.5 * length) * beam, tri = 0.5 * (0.5 * length - shoulder) * beam;
    const double cx =
        (rect * 0.5 * (shoulder - 0.5 * length) + tri * (shoulder + (0.5 * length - shoulder) / 3.0)) / (rect + tri);
    for (glm::dvec2& p : plan) p.x -= cx;
    return plan;
}

}  // namespace

double HullMesh::boat_plan_area(double length, double beam) {
    return 0.85 * length * beam;
}

HullMesh HullMesh::boat(double length, double beam, double draft) {
    HullMesh m;
    add_prism(m, boat_plan(length, beam), -draft, draft);
    const double house_x = -0.1 * length, house_l = 0.25 * length, house_b = 0.25 * beam;
    add_prism(m,
              {{house_x - 0.5 * house_l, -house_b},
               {house_x + 0.5 * house_l, -house_b},
               {house_x + 0.5 * house_l, house_b},
               {house_x - 0.5 * house_l, house_b}},
              draft, draft + std::max(1.0, 1.5 * draft));
    return m;
}

double HullMesh::volume() const {
    double v = 0.0;
    for (const auto& t : triangles) v += glm::dot(vertices[t[0]], glm::cross(vertices[t[1]], vertices[t[2]])) / 6.0;
    return v;
}

Status HullMesh::validate() const {
    if (triangles.empty()) return Error{ErrorCode::invalid_argument, "hull: no triangles"};
    for (const glm::dvec3& p : vertices)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return Error{ErrorCode::invalid_argument, "hull: a vertex is not finite"};
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (std::uint32_t k : triangles[i])
            if (k >= vertices.size())
                return Error{ErrorCode::invalid_argument,
                             fmt::format("hull: triangle {} names vertex {} of {}", i, k, vertices.size())};
    if (!(volume() > 0.0))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("hull: volume {} m^3 is not positive (not closed, or facing inward)", volume())};
    return {};
}

RigidBodyProps RigidBodyProps::solid_box(glm::dvec3 size, double mass) {
    RigidBodyProps p;
    p.mass = mass;
    p.inertia = mass / 12.0 *
                glm::dvec3(size.y * size.y + size.z * size.z, size.x * size.x + size.z * size.z,
                           size.x * size.x + size.y * size.y);
    p.hull = HullMesh::box(size);
    return p;
}

RigidBodyProps RigidBodyProps::barrel(double radius, double height, double mass) {
    RigidBodyProps p;
    p.mass = mass;
    const double across = mass * (3.0 * radius * radius + height * height) / 12.0;
    p.inertia = {across, 0.5 * mass * radius * radius, across};
    p.hull = HullMesh::cylinder(radius, height);
    return p;
}

BuoyancyWorld::BuoyancyWorld(const BuoyancyOptions& options) : options_(options) {}

Result<int> BuoyancyWorld::add(const RigidBodyProps& props, const RigidBodyState& state) {
    if (!(props.mass > 0.0) || !std::isfinite(props.mass))
        return Error{ErrorCode::invalid_argument, fmt::format("floating body: mass {} kg must be > 0", props.mass)};
    if (!(props.inertia.x > 0.0 && props.inertia.y > 0.0 && props.inertia.z > 0.0))
        return Error{ErrorCode::invalid_argument,
                     "floating body: every principal moment of inertia must be > 0 kg m^2"};
    if (!(props.drag >= 0.0) || !std::isfinite(props.drag))
        return Error{ErrorCode::invalid_argument, fmt::format("floating body: drag {} must be >= 0", props.drag)};
    if (auto st = props.hull.validate(); !st)
        return Error{ErrorCode::invalid_argument, "floating body: " + st.error().message};
    if (!(options_.step > 0.0)) return Error{ErrorCode::invalid_argument, "floating body: the step must be > 0 s"};
    props_.push_back(props);
    states_.push_back(state);
    forces_.emplace_back();
    return static_cast<int>(props_.size() - 1);
}

namespace {

/// The water at world points (x, z) for one body (leaving its own wake out).
Status water_at(const FloatingWater& water, double time, int exclude, const std::vector<glm::dvec2>& points,
                std::vector<SurfacePoint>& out) {
    QueryOptions options;
    options.wakes = water.wakes;
    options.exclude_emitter = exclude;
    out.resize(points.size());
    if (water.scene != nullptr) {
        std::vector<WorldPoint> world(points.size());
        if (auto st = query_world(*water.scene, time, points, world, options); !st) return st;
        for (std::size_t i = 0; i < points.size(); ++i) out[i] = world[i].surface;
        return {};
    }
    if (water.body != nullptr) return query_surface(*water.body, time, points, out, options);
    return Error{ErrorCode::invalid_argument, "floating bodies: no water (give a scene or a body)"};
}

struct Piece {
    glm::dvec3 p[3];
    double depth[3];
    glm::dvec3 water_velocity;
};

/// The part of triangle (p, depth) below the surface (depth > 0), as up to two triangles.
int submerged(const glm::dvec3 (&p)[3], const double (&d)[3], Piece (&out)[2], glm::dvec3 water_velocity) {
    int wet = 0;
    for (double x : d) wet += x > 0.0 ? 1 : 0;
    auto cut = [&](int a, int b) { return p[a] + (p[b] - p[a]) * (d[a] / (d[a] - d[b])); };
    if (wet == 0) return 0;
    if (wet == 3) {
        out[0] = {{p[0], p[1], p[2]}, {d[0], d[1], d[2]}, water_velocity};
        return 1;
    }
    if (wet == 1) {
        const int i = d[0] > 0.0 ? 0 : d[1] > 0.0 ? 1 : 2, j = (i + 1) % 3, k = (i + 2) % 3;
        out[0] = {{p[i], cut(i, j), cut(i, k)}, {d[i], 0.0, 0.0}, water_velocity};
        return 1;
    }
    const int k = d[0] <= 0.0 ? 0 : d[1] <= 0.0 ? 1 : 2, i = (k + 1) % 3, j = (k + 2) % 3;  // k is dry
    const glm::dvec3 qi = cut(i, k), qj = cut(j, k);
    out[0] = {{p[i], p[j], qj}, {d[i], d[j], 0.0}, water_velocity};
    out[1] = {{p[i], qj, qi}, {d[i], 0.0, 0.0}, water_velocity};
    return 2;
}

}  // namespace

Status BuoyancyWorld::advance(const FloatingWater& water, double dt) {
    if (!(dt >= 0.0) || !std::isfinite(dt))
        return Error{ErrorCode::invalid_argument, fmt::format("floating bodies: dt {} s", dt)};
    carry_ += dt;
    while (carry_ >= options_.step * (1.0 - 1e-9)) {
        if (auto st = step(water); !st) return st;
        carry_ -= options_.step;
    }
    return {};
}

Status BuoyancyWorld::step(const FloatingWater& water) {
    const double rho = options_.density, g = options_.gravity, h = options_.step;
    // The water under every body's vertices, one query per emitter left out.
    std::map<int, std::vector<std::size_t>> by_emitter;
    for (std::size_t b = 0; b < props_.size(); ++b) by_emitter[props_[b].emitter].push_back(b);
    std::vector<std::vector<glm::dvec3>> world(props_.size());
    std::vector<std::vector<SurfacePoint>> surface(props_.size());
    for (const auto& [emitter, bodies] : by_emitter) {
        std::vector<glm::dvec2> points;
        for (std::size_t b : bodies) {
            const glm::dmat3 rotate = glm::mat3_cast(states_[b].orientation);
            for (const glm::dvec3& v : props_[b].hull.vertices) {
                world[b].push_back(states_[b].position + rotate * v);
                points.push_back({world[b].back().x, world[b].back().z});
            }
        }
        std::vector<SurfacePoint> out;
        if (auto st = water_at(water, time_, emitter, points, out); !st) return st;
        std::size_t k = 0;
        for (std::size_t b : bodies) {
            surface[b].assign(out.begin() + static_cast<std::ptrdiff_t>(k),
                              out.begin() + static_cast<std::ptrdiff_t>(k + world[b].size()));
            k += world[b].size();
        }
        // The water is finite wherever it is queried; should it not be, say where rather
        // than carry a NaN into the bodies' state.
        for (std::size_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(out[i].height) ||
                !std::isfinite(out[i].velocity.x + out[i].velocity.y + out[i].velocity.z))
                return Error{ErrorCode::internal,
                             fmt::format("floating bodies: the water at ({}, {}) at t = {} s is not finite",
                                         points[i].x, points[i].y, time_)};
    }
    for (std::size_t b = 0; b < props_.size(); ++b) {
        const RigidBodyProps& props = props_[b];
        RigidBodyState& s = states_[b];
        Forces f;
        f.force = {0.0, -props.mass * g, 0.0};
        for (const auto& t : props.hull.triangles) {
            const glm::dvec3 p[3] = {world[b][t[0]], world[b][t[1]], world[b][t[2]]};
            const double d[3] = {surface[b][t[0]].height - p[0].y, surface[b][t[1]].height - p[1].y,
                                 surface[b][t[2]].height - p[2].y};
            const glm::dvec3 water_velocity =
                (surface[b][t[0]].velocity + surface[b][t[1]].velocity + surface[b][t[2]].velocity) / 3.0;
            Piece pieces[2];
            const int n = submerged(p, d, pieces, water_velocity);
            for (int i = 0; i < n; ++i) {
                const Piece& q = pieces[i];
                const glm::dvec3 cross = glm::cross(q.p[1] - q.p[0], q.p[2] - q.p[0]);
                const double area = 0.5 * glm::length(cross);
                if (area <= 0.0) continue;
                const glm::dvec3 normal = cross / (2.0 * area);
                // Pressure rho g depth, linear over the piece: its force and its moment exactly.
                const double mean_depth = (q.depth[0] + q.depth[1] + q.depth[2]) / 3.0;
                const glm::dvec3 pressure = -rho * g * mean_depth * area * normal;
                const glm::dvec3 r[3] = {q.p[0] - s.position, q.p[1] - s.position, q.p[2] - s.position};
                const glm::dvec3 moment_arm =
                    (area / 12.0) * ((r[0] + r[1] + r[2]) * (q.depth[0] + q.depth[1] + q.depth[2]) + r[0] * q.depth[0] +
                                     r[1] * q.depth[1] + r[2] * q.depth[2]);
                f.buoyancy += pressure;
                f.torque += -rho * g * glm::cross(moment_arm, normal);
                // Drag on the face's motion through the water along its normal.
                const glm::dvec3 centre = (r[0] + r[1] + r[2]) / 3.0;
                const glm::dvec3 relative = s.velocity + glm::cross(s.angular_velocity, centre) - q.water_velocity;
                const double along = glm::dot(relative, normal);
                const glm::dvec3 drag = -0.5 * rho * props.drag * area * std::abs(along) * along * normal;
                f.force += drag;
                f.torque += glm::cross(centre, drag);
            }
        }
        f.force += f.buoyancy;
        f.submerged_volume = f.buoyancy.y / (rho * g);
        // Semi-implicit Euler: velocities from the forces, then positions from the velocities.
        s.velocity += f.force / props.mass * h;
        s.position += s.velocity * h;
        const glm::dmat3 rotate = glm::mat3_cast(s.orientation);
        const glm::dmat3 inertia = rotate *
                                   glm::dmat3(props.inertia.x, 0, 0, 0, props.inertia.y, 0, 0, 0, props.inertia.z) *
                                   glm::transpose(rotate);
        const glm::dvec3 momentum = inertia * s.angular_velocity;
        s.angular_velocity += glm::inverse(inertia) * (f.torque - glm::cross(s.angular_velocity, momentum)) * h;
        const glm::dquat spin(0.0, s.angular_velocity.x, s.angular_velocity.y, s.angular_velocity.z);
        s.orientation = glm::normalize(s.orientation + (0.5 * h) * (spin * s.orientation));
        forces_[b] = f;
    }
    time_ += h;
    return {};
}

}  // namespace tidewater
