// Rigid bodies floating on the water: hydrostatic pressure on every submerged triangle
// of a closed hull mesh, drag against the water's velocity (currents and waves), and a
// fixed-step integrator, so boats and barrels ride what the renderer draws.
//
// Each step queries the surface under the hull's vertices (query_world for a scene, with
// its boats' wakes, or query_surface for one body) and clips every triangle at the
// waterline: the submerged part feels p = rho g (depth below the local surface) on its
// face (exact for a flat surface: Archimedes), and quadratic drag on the normal part of
// its velocity relative to the water. Gravity acts at the centre of mass.
//
// Frame: x forward, y up, z to starboard (body); world y up. Units: metres, kilograms,
// seconds, newtons. Threading: a BuoyancyWorld is used from one thread; the water it
// reads (scene, body, wakes) must not change during a call.
#pragma once

#include <array>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

class WaterBody;
struct Scene;
struct Wakes;

inline constexpr double kWaterDensity = 1025.0;  ///< sea water, kg/m^3

/// A closed triangle mesh, outward-facing (counter-clockwise seen from outside), body frame, m.
struct HullMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    /// A box centred on the origin with sides `size` (x, y, z).
    static HullMesh box(glm::dvec3 size);
    /// box() without its top (+y) face: an open hold, to draw. Not closed: buoyancy takes
    /// the closed box.
    static HullMesh open_box(glm::dvec3 size);
    /// A sphere of `radius` round the origin: `rings` bands of 2 `rings` segments.
    static HullMesh sphere(double radius, int rings = 32);
    /// An upright cylinder (a barrel) of `radius` and `height` round the origin.
    static HullMesh cylinder(double radius, double height, int segments = 24);
    /// A workboat: a flat-bottomed hull `length` x `beam` whose sides run straight for
    /// the aft 70% and meet at the bow, 2 `draft` deep (keel at y = -draft, deck at
    /// +draft, its plan's centroid on the origin), with a deckhouse above it. Floats at
    /// `draft` with mass kWaterDensity x boat_plan_area(length, beam) x draft.
    static HullMesh boat(double length, double beam, double draft);
    /// The plan area of boat()'s hull, m^2.
    static double boat_plan_area(double length, double beam);
    double volume() const;    ///< m^3 (a closed, outward mesh)
    Status validate() const;  ///< indices in range, finite vertices, a positive volume
};

struct RigidBodyProps {
    double mass = 100.0;                   ///< kg (> 0)
    glm::dvec3 inertia{10.0, 10.0, 10.0};  ///< principal moments about the centre of mass, body axes, kg m^2 (> 0)
    HullMesh hull;                         ///< body frame, centred on the centre of mass
    double drag = 1.0;                     ///< drag coefficient of the hull's faces (>= 0)
    /// The wake emitter this body is (QueryOptions::exclude_emitter): its own wake is left
    /// out of its buoyancy. -1: none.
    int emitter = -1;

    /// Solid of uniform density: the inertia of a box, or of a cylinder about its axes.
    static RigidBodyProps solid_box(glm::dvec3 size, double mass);
    static RigidBodyProps barrel(double radius, double height, double mass);
};

struct RigidBodyState {
    glm::dvec3 position{0.0};                    ///< centre of mass, world, m
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< body to world
    glm::dvec3 velocity{0.0};                    ///< m/s
    glm::dvec3 angular_velocity{0.0};            ///< world axes, rad/s
};

/// What the bodies float on: a scene (query_world, its boats' wakes included) or one
/// body (query_surface), and any further wakes.
struct FloatingWater {
    const Scene* scene = nullptr;
    const WaterBody* body = nullptr;
    const Wakes* wakes = nullptr;
};

struct BuoyancyOptions {
    double step = 1.0 / 120.0;  ///< the fixed integration step, s (> 0)
    double gravity = 9.81;      ///< m/s^2
    double density = kWaterDensity;
};

/// Floating bodies advanced in fixed steps (semi-implicit Euler): the same motion at any
/// frame rate for the same step.
class BuoyancyWorld {
  public:
    explicit BuoyancyWorld(const BuoyancyOptions& options = {});

    /// Adds a body; returns its index. Fails on a bad mass, inertia or hull.
    Result<int> add(const RigidBodyProps& props, const RigidBodyState& state);

    /// Advances every body from the world's time by `dt` seconds in whole fixed steps (the
    /// remainder carries over to the next call). The water is read at each step's time.
    Status advance(const FloatingWater& water, double dt);
    /// One fixed step.
    Status step(const FloatingWater& water);

    double time() const { return time_; }
    const BuoyancyOptions& options() const { return options_; }
    void set_time(double t) { time_ = t; }
    const RigidBodyState& state(int body) const { return states_[static_cast<std::size_t>(body)]; }
    RigidBodyState& state(int body) { return states_[static_cast<std::size_t>(body)]; }
    std::size_t size() const { return props_.size(); }

    /// The forces of the last step on a body, world frame: total force (gravity included)
    /// and the buoyancy alone (N), and the submerged volume (m^3).
    struct Forces {
        glm::dvec3 force{0.0}, buoyancy{0.0}, torque{0.0};
        double submerged_volume = 0.0;
    };
    const Forces& forces(int body) const { return forces_[static_cast<std::size_t>(body)]; }

  private:
    BuoyancyOptions options_;
    double time_ = 0.0, carry_ = 0.0;
    std::vector<RigidBodyProps> props_;
    std::vector<RigidBodyState> states_;
    std::vector<Forces> forces_;
};

}  // namespace tidewater
