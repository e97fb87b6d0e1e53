#include "tidewater/wakes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "host_device.h"
#include "tidewater/constants.hpp"

namespace tidewater {

namespace {

bool finite(glm::dvec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

Status check_point(const DisturbancePoint& p, const std::string& where) {
    if (!finite(p.position))
        return Error{ErrorCode::invalid_argument, fmt::format("{}: position is not finite", where)};
    if (!std::isfinite(p.strength))
        return Error{ErrorCode::invalid_argument, fmt::format("{}: strength {} is not finite", where, p.strength)};
    if (!(p.source_size > 0.0) || !std::isfinite(p.source_size))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: source_size {} must be > 0 m", where, p.source_size)};
    if (!std::isfinite(p.emitted))
        return Error{ErrorCode::invalid_argument, fmt::format("{}: emitted is not finite", where)};
    if (!(p.steepness >= 0.0 && p.steepness <= 1.0))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: steepness {} must be in [0, 1]", where, p.steepness)};
    if (!(p.turbulence >= 0.0 && p.turbulence <= 1.0))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: turbulence {} must be in [0, 1]", where, p.turbulence)};
    return {};
}

/// The point `distance` m along a polyline (straight on past its end; its first point
/// before its start).
glm::dvec2 along(const std::vector<glm::dvec2>& path, double distance) {
    double walked = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const double length = glm::length(path[i + 1] - path[i]);
        if (distance <= walked + length && length > 0.0)
            return path[i] + (path[i + 1] - path[i]) * ((distance - walked) / length);
        walked += length;
    }
    if (distance <= 0.0) return path.front();
    // Beyond the end: straight on along the last leg (a heading's chord may look ahead).
    const glm::dvec2 last = path.back() - path[path.size() - 2];
    const double length = glm::length(last);
    return path.back() + (length > 0.0 ? last / length : glm::dvec2(1.0, 0.0)) * (distance - walked);
}

glm::dvec2 rotate(glm::dvec2 body, double heading) {
    const double c = std::cos(heading), s = std::sin(heading);
    // Body frame (forward, starboard): forward is (c, s), starboard (-s, c) (facing +x
    // with y up, +z is on the right).
    return {body.x * c - body.y * s, body.x * s + body.y * c};
}

}  // namespace

std::size_t Wakes::point_count() const {
    std::size_t n = splashes.size();
    for (const WakeChain& c : chains) n += c.points.size();
    return n;
}

Status Wakes::validate(const std::string& context) const {
    if (point_count() > gpu::kMaxWakePoints)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} disturbance points, more than the {} a frame may hold", context, point_count(),
                                 gpu::kMaxWakePoints)};
    for (std::size_t c = 0; c < chains.size(); ++c) {
        const WakeChain& chain = chains[c];
        if (!(chain.max_age > 0.0) || !std::isfinite(chain.max_age))
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: chains[{}].max_age {} must be > 0 s", context, c, chain.max_age)};
        for (std::size_t i = 0; i < chain.points.size(); ++i) {
            if (auto st = check_point(chain.points[i], fmt::format("{}: chains[{}].points[{}]", context, c, i)); !st)
                return st;
            if (i > 0 && !(chain.points[i].emitted > chain.points[i - 1].emitted))
                return Error{
                    ErrorCode::invalid_argument,
                    fmt::format("{}: chains[{}].points[{}] was emitted at {} s, not after the point before it ({} s)",
                                context, c, i, chain.points[i].emitted, chain.points[i - 1].emitted)};
        }
    }
    for (std::size_t i = 0; i < splashes.size(); ++i)
        if (auto st = check_point(splashes[i], fmt::format("{}: splashes[{}]", context, i)); !st) return st;
    if (!splash_emitters.empty() && splash_emitters.size() != splashes.size())
        return Error{ErrorCode::invalid_argument, fmt::format("{}: {} splash emitters for {} splashes", context,
                                                              splash_emitters.size(), splashes.size())};
    if (!(splash_max_age > 0.0) || !std::isfinite(splash_max_age))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: splash_max_age {} must be > 0 s", context, splash_max_age)};
    return {};
}

BoatWakeShape boat_wake_shape(const BoatHull& hull) {
    BoatWakeShape s;
    s.bow_size = 0.5 * hull.length;
    // A Gaussian patch exp(-pi^2 r^2 / b^2) of head h presses with g h b^2 / pi; the two
    // bow chains share the hull's mean draft.
    const double head = kBoatBlockCoefficient * hull.draft;
    s.bow_strength = 0.5 * kGravity * head * s.bow_size * s.bow_size / kPi;
    s.bow_spacing = hull.length / 8.0;
    s.stern_spacing = 0.5 * hull.beam;
    s.port_bow = {0.25 * hull.length, -0.25 * hull.beam};
    s.starboard_bow = {0.25 * hull.length, 0.25 * hull.beam};
    s.stern = {-0.5 * hull.length, 0.0};
    return s;
}

std::size_t boat_wake_points(const BoatHull& hull, double speed) {
    const BoatWakeShape s = boat_wake_shape(hull);
    const double bow = std::ceil(speed * kBoatBowMaxAge / s.bow_spacing) + 2.0;
    const double stern = std::ceil(speed * kBoatSternMaxAge / s.stern_spacing) + 2.0;
    return static_cast<std::size_t>(2.0 * bow + stern);
}

namespace {

DisturbancePoint bow_point(const BoatWakeShape& s, glm::dvec2 at, double time) {
    DisturbancePoint p;
    p.position = at;
    p.strength = s.bow_strength;
    p.source_size = s.bow_size;
    p.emitted = time;
    p.steepness = 0.6;
    p.turbulence = 0.0;  // foam at the bow comes from its waves folding (the Jacobian)
    return p;
}

DisturbancePoint stern_point(const BoatHull& hull, glm::dvec2 at, double time) {
    DisturbancePoint p;
    p.position = at;
    p.strength = 0.0;  // the churn makes foam, not waves
    p.source_size = hull.beam;
    p.emitted = time;
    p.steepness = 0.0;
    p.turbulence = 1.0;
    return p;
}

constexpr double kBowMaxAge = kBoatBowMaxAge;
constexpr double kSternMaxAge = kBoatSternMaxAge;

void drop_aged(WakeChain& chain, double time) {
    const auto first = std::find_if(chain.points.begin(), chain.points.end(),
                                    [&](const DisturbancePoint& p) { return time - p.emitted < chain.max_age; });
    chain.points.erase(chain.points.begin(), first);
}

/// A boat's three chains, empty: port bow, starboard bow, stern.
void start_chains(WakeChain (&chains)[3], int emitter) {
    for (WakeChain& c : chains) {
        c.points.clear();
        c.emitter = emitter;
        c.max_age = kBowMaxAge;
    }
    chains[2].max_age = kSternMaxAge;
}

/// Lays the bow points (port and starboard) or the stern point of a boat whose centre is
/// at `centre` with `heading` at clock time `time`.
void lay_points(const BoatWakeShape& s, const BoatHull& hull, glm::dvec2 centre, double heading, double time, bool bow,
                WakeChain (&chains)[3]) {
    auto push = [&](WakeChain& c, DisturbancePoint p) {
        if (c.points.empty() || p.emitted > c.points.back().emitted) c.points.push_back(p);
    };
    if (bow) {
        push(chains[0], bow_point(s, centre + rotate(s.port_bow, heading), time));
        push(chains[1], bow_point(s, centre + rotate(s.starboard_bow, heading), time));
    } else {
        push(chains[2], stern_point(hull, centre + rotate(s.stern, heading), time));
    }
}

}  // namespace

BoatWakeEmitter::BoatWakeEmitter(const BoatHull& hull, int emitter)
    : hull_(hull), shape_(boat_wake_shape(hull)), emitter_(emitter) {
    start_chains(chains_, emitter);
}

void BoatWakeEmitter::lay(double& next, double spacing, const Pose& a, const Pose& b, bool bow) {
    for (; next <= b.track; next += spacing) {
        const double f = b.track > a.track ? (next - a.track) / (b.track - a.track) : 1.0;
        const glm::dvec2 centre = a.position + (b.position - a.position) * f;
        const double heading = a.heading + std::remainder(b.heading - a.heading, kTwoPi) * f;  // the short way round
        lay_points(shape_, hull_, centre, heading, a.time + (b.time - a.time) * f, bow, chains_);
    }
}

Status BoatWakeEmitter::advance(glm::dvec2 position, double heading, double time) {
    if (!finite(position) || !std::isfinite(heading) || !std::isfinite(time))
        return Error{ErrorCode::invalid_argument, "boat wake: the pose or its time is not finite"};
    if (started_ && !(time > last_.time))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("boat wake: pose at {} s does not follow the last one ({} s)", time, last_.time)};
    const Pose now{position, heading, time, started_ ? last_.track + glm::length(position - last_.position) : 0.0};
    if (!started_) {
        started_ = true;
        last_ = now;
        next_bow_ = next_stern_ = 0.0;
    }
    lay(next_bow_, shape_.bow_spacing, last_, now, true);
    lay(next_stern_, shape_.stern_spacing, last_, now, false);
    last_ = now;
    // Points that aged out are dropped as the boat goes (the chains stay short).
    for (WakeChain& c : chains_) drop_aged(c, time);
    return {};
}

void BoatWakeEmitter::append_to(Wakes& wakes, double time) const {
    WakeChain chains[3] = {chains_[0], chains_[1], chains_[2]};
    // Each chain ends at the boat as it is now, so its last segment grows smoothly until
    // the next point is laid where the head has come to.
    if (started_) {
        lay_points(shape_, hull_, last_.position, last_.heading, last_.time, true, chains);
        lay_points(shape_, hull_, last_.position, last_.heading, last_.time, false, chains);
    }
    for (WakeChain& c : chains) {
        drop_aged(c, time);
        if (c.points.size() >= 2) wakes.chains.push_back(std::move(c));
    }
}

void scripted_boat_wake(const SceneBoat& boat, int emitter, double time, Wakes& wakes) {
    if (boat.path.size() < 2 || !(boat.speed > 0.0) || time <= boat.start) return;
    const BoatWakeShape shape = boat_wake_shape(boat.hull);
    WakeChain chains[3];
    start_chains(chains, emitter);
    const double total = boat.path_length();
    const double travelled = std::min((time - boat.start) * boat.speed, total);
    const double arrival = boat.start + total / boat.speed;
    for (int stern = 0; stern < 2; ++stern) {
        const double spacing = stern ? shape.stern_spacing : shape.bow_spacing;
        const double max_age = stern ? kSternMaxAge : kBowMaxAge;
        // Marks i * spacing along the track, from the first one still alive.
        const double oldest = std::max(0.0, (time - max_age - boat.start) * boat.speed);
        for (double i = std::ceil(oldest / spacing); i * spacing <= travelled; i += 1.0) {
            const double emitted = boat.start + i * spacing / boat.speed;
            glm::dvec2 centre;
            double heading = 0.0;
            boat.pose_at(emitted, centre, heading);
            lay_points(shape, boat.hull, centre, heading, emitted, !stern, chains);
        }
        if (time < arrival) {  // the head: the boat now (a boat that has arrived makes no more wake)
            glm::dvec2 centre;
            double heading = 0.0;
            boat.pose_at(time, centre, heading);
            lay_points(shape, boat.hull, centre, heading, time, !stern, chains);
        }
    }
    for (WakeChain& chain : chains) {
        drop_aged(chain, time);
        if (chain.points.size() >= 2) wakes.chains.push_back(std::move(chain));
    }
}

void scene_boat_wakes(const std::vector<SceneBoat>& boats, double time, Wakes& wakes) {
    for (std::size_t b = 0; b < boats.size(); ++b) scripted_boat_wake(boats[b], static_cast<int>(b), time, wakes);
}

double SceneBoat::path_length() const {
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) length += glm::length(path[i + 1] - path[i]);
    return length;
}

void SceneBoat::pose_at(double time, glm::dvec2& position, double& heading) const {
    const double total = path_length();
    const double travelled = std::clamp((time - start) * speed, 0.0, total);
    position = along(path, travelled);
    const double half = 0.5 * hull.length;
    const glm::dvec2 chord = along(path, travelled + half) - along(path, travelled - half);
    heading = glm::length(chord) > 0.0 ? std::atan2(chord.y, chord.x) : 0.0;
}

}  // namespace tidewater
