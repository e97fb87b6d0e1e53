#include "tidewater/drift.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tidewater/baked_scene.hpp"
#include "water/body_at.hpp"

namespace tidewater {

namespace {

/// The largest track drift writes: a guard against a step far too small for the duration.
constexpr double kMaxDriftSteps = 1.0e7;

const detail::WaterBodiesBake* bodies_of(const Scene& scene) {
    return scene.bake ? scene.bake->bodies.get() : nullptr;
}

}  // namespace

glm::dvec2 current_at(const Scene& scene, glm::dvec2 point) {
    return detail::BodyFinder(scene, bodies_of(scene)).find(point).flow;
}

Result<std::vector<DriftSample>> drift(const Scene& scene, glm::dvec2 start, const DriftOptions& options) {
    if (!std::isfinite(start.x) || !std::isfinite(start.y))
        return Error{ErrorCode::invalid_argument, "drift: the start point is not finite"};
    if (!std::isfinite(options.start_time))
        return Error{ErrorCode::invalid_argument, "drift: start_time is not finite"};
    if (!(options.duration > 0.0) || !std::isfinite(options.duration))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("drift: duration {} s must be finite and > 0", options.duration)};
    if (!(options.dt > 0.0) || !(options.dt <= options.duration))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("drift: dt {} s must be > 0 and at most the duration", options.dt)};
    const double steps_wanted = std::ceil(options.duration / options.dt - 1e-9);
    if (steps_wanted > kMaxDriftSteps)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("drift: {} steps of {} s; at most {:.0f}: take a longer step", steps_wanted,
                                 options.dt, kMaxDriftSteps)};
    const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
    if (has_bodies && !scene.baked())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("drift: {} has lakes or rivers but is not baked: pass it through bake_scene first",
                                 scene_label(scene))};

    const detail::BodyFinder finder(scene, bodies_of(scene));
    const detail::PointBody first = finder.find(start);
    if (first.body.kind == BodyKind::none)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("drift: the start ({}, {}) is not in water", start.x, start.y)};
    const auto flow = [&](glm::dvec2 p) { return finder.find(p).flow; };
    const auto steps = static_cast<std::size_t>(steps_wanted);
    std::vector<DriftSample> track;
    track.reserve(steps + 1);
    glm::dvec2 p = start;
    BodyRef body = first.body;
    for (std::size_t k = 0;; ++k) {
        const double t = options.start_time + std::min(static_cast<double>(k) * options.dt, options.duration);
        track.push_back({t, p, query_world_point(scene, t, p).surface.height, body});
        if (k == steps) break;
        const double h = std::min(options.dt, options.duration - static_cast<double>(k) * options.dt);
        // The current is steady: RK4 in space alone.
        const glm::dvec2 k1 = flow(p), k2 = flow(p + 0.5 * h * k1), k3 = flow(p + 0.5 * h * k2), k4 = flow(p + h * k3);
        const glm::dvec2 next = p + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        const detail::PointBody there = finder.find(next);
        if (there.body.kind == BodyKind::none) break;  // it left the water
        p = next;
        body = there.body;
    }
    return track;
}

}  // namespace tidewater
