// Drift: a floating tracer carried by a scene's currents (the rivers' baked
// depth-averaged current, as query_world reports it in WorldPoint::flow), integrated
// with the classic fourth-order Runge-Kutta scheme on a fixed step.
//
// The track depends on the step only through the integrator's error (fourth order), never
// on how often a host calls: the same start, step and duration give the same track.
// It stops at `duration`, or before the first step that would end out of the water
// (on land: no body there).
// Units: metres, seconds. Threading: reentrant; the scene is only read.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {

struct DriftOptions {
    double start_time = 0.0;  ///< clock time of the first sample, s
    double duration = 60.0;   ///< s, > 0
    double dt = 1.0 / 60.0;   ///< step, s, in (0, duration]
};

struct DriftSample {
    double time = 0.0;         ///< clock time, s
    glm::dvec2 position{0.0};  ///< world xz, m
    double height = 0.0;       ///< the water surface there (waves included), world y, m
    BodyRef body;              ///< the body it floats in
};

/// The tracer's track from `start`, one sample per step (the first at start_time).
/// Fails when `start` is not in water, on bad options, or on an unbaked scene with
/// lakes or rivers.
Result<std::vector<DriftSample>> drift(const Scene& scene, glm::dvec2 start, const DriftOptions& options = {});

/// The current alone at a point, m/s: what drift integrates (0 outside rivers and plumes).
glm::dvec2 current_at(const Scene& scene, glm::dvec2 point);

}  // namespace tidewater
