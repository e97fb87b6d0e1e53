// A scene's boats and floats as rigid bodies riding its water: the boats keep to their
// scripted paths and headings (SceneBoat::pose_at) while heaving, pitching and rolling
// on the water without their own wakes; the floats (barrels, boxes, buoys) drift freely
// on the waves, currents and the boats' wakes. What a host or the demo draws with them.
//
// Deterministic: the bodies start at rest on the water kSceneFloatSettle seconds before
// the start time and are advanced in fixed steps (BuoyancyWorld), so the same start and
// step give the same motion whatever the frame rate.
// Threading: one thread at a time; the scene is shared and must not change meanwhile.
// Units: metres, seconds, kilograms; world frame y up.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "tidewater/buoyancy.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

/// How long before the start time the bodies are set afloat, s: long enough for a
/// barrel's or a boat's heave and roll to settle from its rest placement.
inline constexpr double kSceneFloatSettle = 12.0;

class SceneFloaters {
  public:
    struct Body {
        std::string name;
        HullMesh hull;          ///< body frame, m (x forward, y up, z to starboard)
        glm::vec3 color{0.8f};  ///< paint, linear RGB
        bool boat = false;      ///< a scene boat (kept to its path) or a free float
        /// Body frame: where it keeps the water out (tidewater/clip_volume.hpp): a box's,
        /// a sphere's own shape, the capsule inside a barrel, a boat's hull (the convex
        /// prism of its plan, keel to deck, a hair inside).
        ClipVolume clip;
    };
    struct Pose {
        glm::dvec3 position{0.0};                    ///< the body frame's origin, world, m
        glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< body to world
    };

    /// The scene's boats (scene.boats, in order) then its floats, afloat at clock time
    /// `start`, advanced in steps of `step` seconds. The scene must be baked if it has a
    /// shore model (query_world's rule). Fails on a bad step or a query that fails.
    static Result<SceneFloaters> create(std::shared_ptr<const Scene> scene, double start, double step = 1.0 / 30.0);

    /// Carries on over an edited copy of the scene (a re-bake, a new preset) with the
    /// same boats and floats, keeping every body's motion. Fails if they differ in number.
    Status set_scene(std::shared_ptr<const Scene> scene);

    /// Advances to clock time `time` (>= time()) in whole steps.
    Status advance_to(double time);
    double time() const { return world_.time(); }
    const std::vector<Body>& bodies() const { return bodies_; }
    Pose pose(std::size_t body) const;

  private:
    SceneFloaters(std::shared_ptr<const Scene> scene, double step)
        : scene_(std::move(scene)), world_(BuoyancyOptions{step}) {}
    void hold_boats_to_their_paths();

    std::shared_ptr<const Scene> scene_;
    BuoyancyWorld world_;
    std::vector<Body> bodies_;
};

}  // namespace tidewater
