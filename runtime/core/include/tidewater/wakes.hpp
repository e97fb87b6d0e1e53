// Wakes: boats, splashes and other disturbances of the water, as one more set of waves
// in the one water evaluation (queries, and the renderer through its GLSL twin).
//
// A disturbance is a pressure pulse at a fixed place (DisturbancePoint). On deep water
// each one spreads as the Cauchy-Poisson response to an impulse, its waves shorter than
// its source size damped; a chain of them along a boat's track, integrated segment by
// segment, is Kelvin's wake (19.47 degree cusps, transverse waves of 2 pi U^2 / g on the
// track, divergent waves beside it). The formula is in detail/wake_point.hpp.
//
// Who makes them:
// - BoatWakeEmitter: a boat whose poses the host feeds (a player's boat), or
// - scripted_boat_wake: a scene's boat on its path (Scene::boats), the same wake at a
//   clock time whatever the frame rate or the order of the queries.
// Pass a Wakes to the queries through QueryOptions::wakes (and to the renderer through
// FrameInfo::wakes); query_world, the GPU queries and the renderer add the scene's
// scripted boats themselves.
//
// Units: metres, seconds, radians; positions are world (x, z).
// Threading: plain values; an emitter is used from one thread at a time, and a Wakes
// is only read by the queries (share it freely between them).
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

/// One disturbance: a pressure pulse on the water, fixed where it was made.
struct DisturbancePoint {
    glm::dvec2 position{0.0};  ///< world (x, z) where it was made, m
    /// The pulse's strength, the integral of pressure / density over its patch: in a chain,
    /// the strength while the source passes (m^4/s^2; a segment carries it times its
    /// duration; a hull of displaced volume V presses with at most g V); for a lone point
    /// (a splash), its whole impulse (m^4/s).
    double strength = 0.0;
    /// Width b of the pressure patch exp(-pi^2 r^2 / b^2), m (> 0): waves shorter than
    /// about b / 2 are not made.
    double source_size = 1.0;
    double emitted = 0.0;     ///< clock time it was made, s
    double steepness = 0.5;   ///< Gerstner Q of its waves, [0, 1]
    double turbulence = 0.0;  ///< foam it makes, [0, 1] when made, decaying over 30 s
};

/// Disturbances made one after another by one source (a boat's bow), evaluated segment
/// by segment so that its waves form one continuous front.
struct WakeChain {
    int emitter = 0;  ///< who made it: a floating body can leave its own wake out
    /// Oldest first; emission times strictly increase.
    std::vector<DisturbancePoint> points;
    /// Points older than this are gone (s, > 0); their strength fades out over the last
    /// fifth of it, so that none vanishes at once.
    double max_age = 240.0;
};

/// Everything that disturbs the water at one moment.
struct Wakes {
    std::vector<WakeChain> chains;
    /// Lone points (splashes): strength is their impulse, m^4/s.
    std::vector<DisturbancePoint> splashes;
    std::vector<int> splash_emitters;  ///< who made each splash (empty: emitter 0)
    double splash_max_age = 60.0;      ///< s, as WakeChain::max_age

    std::size_t point_count() const;
    /// Finite values in range, increasing emission times, at most kMaxWakePoints
    /// (4096) points; `context` names the source in messages.
    Status validate(const std::string& context = "wakes") const;
};

/// The hull a boat makes its wake with.
struct BoatHull {
    double length = 20.0;  ///< m (> 0)
    double beam = 6.0;     ///< m (> 0)
    double draft = 1.5;    ///< m (> 0)
};

/// How a boat makes its wake, from its hull: two bow chains (port and starboard, at the
/// bow shoulders, a quarter length forward and a quarter beam out) each pressing with a
/// Gaussian patch of width L / 2 whose head is the hull's mean draft (block coefficient
/// kBoatBlockCoefficient times the draft), and a stern chain that only churns foam.
/// Points are laid every L / 8 of track (half the shortest wave the patch makes, L / 4
/// where its filter is e^-4; each segment is integrated with its phase step, so fronts
/// neither scallop nor alias); the stern's every B / 2.
struct BoatWakeShape {
    double bow_size = 0.0;                                     ///< source size of the bow chains, m
    double bow_strength = 0.0;                                 ///< each bow chain's strength, m^4/s^2
    double bow_spacing = 0.0;                                  ///< m of track between bow points
    double stern_spacing = 0.0;                                ///< m of track between stern points
    glm::dvec2 port_bow{0.0}, starboard_bow{0.0}, stern{0.0};  ///< body frame (forward, starboard), m
};
inline constexpr double kBoatBlockCoefficient = 0.5;
/// How long a boat's bow points (its waves) and stern points (its churned foam) live, s.
inline constexpr double kBoatBowMaxAge = 360.0;
inline constexpr double kBoatSternMaxAge = 90.0;
BoatWakeShape boat_wake_shape(const BoatHull& hull);
/// The most disturbance points a boat at `speed` (m/s) holds in its wake.
std::size_t boat_wake_points(const BoatHull& hull, double speed);

/// A boat whose poses the host feeds, frame by frame: it lays its chains' points at
/// fixed distances along the track it sails (positions and times interpolated between
/// poses), so the wake does not depend on the frame rate.
class BoatWakeEmitter {
  public:
    BoatWakeEmitter(const BoatHull& hull, int emitter);

    /// The boat's centre at clock time `time`: world (x, z), heading in radians from +x
    /// toward +z. Times must increase; the first pose starts the track.
    Status advance(glm::dvec2 position, double heading, double time);
    /// Appends its three chains, each ending at the last pose, to `wakes`, leaving out
    /// points older than their chain's max_age at `time`.
    void append_to(Wakes& wakes, double time) const;

    int emitter() const { return emitter_; }
    const BoatWakeShape& shape() const { return shape_; }

  private:
    struct Pose {
        glm::dvec2 position;
        double heading, time, track;
    };
    /// Lays the bow (or stern) points at the track marks from `next` up to pose b.
    void lay(double& next, double spacing, const Pose& a, const Pose& b, bool bow);

    BoatHull hull_;
    BoatWakeShape shape_;
    int emitter_ = 0;
    bool started_ = false;
    Pose last_{};
    double next_bow_ = 0.0, next_stern_ = 0.0;  ///< track distance of the next points
    WakeChain chains_[3];                       ///< port bow, starboard bow, stern
};

/// A boat that sails a path at constant speed (Scene::boats, "boats" in scene JSON).
struct SceneBoat {
    std::string name;
    std::vector<glm::dvec2> path;  ///< world (x, z), m; >= 2 points
    double speed = 5.0;            ///< m/s (> 0)
    BoatHull hull;
    double start = 0.0;  ///< clock time it leaves the first point, s
    /// Where it is at clock time `time` (centre and heading, radians); it stays at the end.
    void pose_at(double time, glm::dvec2& position, double& heading) const;
    double path_length() const;
};

/// The wake of a scripted boat at clock time `time`, appended to `wakes` as three chains
/// with emitter `emitter`: each point where the boat laid it, a pure function of the
/// path and the time.
void scripted_boat_wake(const SceneBoat& boat, int emitter, double time, Wakes& wakes);

/// The wakes of a scene's boats (Scene::boats) at clock time `time`, appended to `wakes`:
/// boat i is emitter i. What the queries and the renderer add for a scene.
void scene_boat_wakes(const std::vector<SceneBoat>& boats, double time, Wakes& wakes);

}  // namespace tidewater
