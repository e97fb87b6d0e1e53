// Eulerian surface queries: what is the water doing at fixed (x, z)?
//
// Gerstner waves move particles horizontally, so the particle now at (x, z)
// rests elsewhere (x0). Each query solves x0 + d(x0, t) = (x, z) by Newton's
// method on the 2x2 system (exact Jacobian, step kept within the largest
// possible displacement), then reports the surface there. It converges for
// every fold-free set; the height error is far below 1 mm.
//
// Units: metres, seconds; heights are world y (the body's level plus eta).
// Threading: every function here is reentrant and deterministic: the same
// inputs give bit-identical outputs for any thread count.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>

#include "tidewater/clip_volume.hpp"
#include "tidewater/result.hpp"
#include "tidewater/water_body.hpp"

namespace tidewater {

/// Depth and shore distance of water with no known bottom or shore.
inline constexpr double kDeepWater = std::numeric_limits<double>::infinity();

struct SurfacePoint {
    double height = 0.0;               ///< World y of the surface, m.
    glm::dvec3 normal{0.0, 1.0, 0.0};  ///< Unit normal of the displaced surface.
    glm::dvec2 displacement{0.0};      ///< Horizontal offset of this particle from its rest position, m.
    glm::dvec3 velocity{0.0};          ///< Water particle velocity, m/s.
    double jacobian = 1.0;             ///< Horizontal-map determinant; -> 0 where crests fold (foam).
    /// Still-water depth at the query point: the body's level minus the terrain there, m
    /// (< 0 on land), from the shore model's grid. +infinity where the body has no shore
    /// model or the point lies beyond its coastal band in open water (no bottom is known:
    /// query_world fills it in from the terrain), -infinity a tile or more inland.
    double depth = kDeepWater;
    /// Signed distance from the query point to the shoreline, m (+ over water, - on land),
    /// from the shore model; +-infinity without one or beyond its coastal band, as `depth`.
    double shore_distance = kDeepWater;
    /// The surface stands above the terrain at the query point: height > level - depth.
    bool wet = true;
    /// 0..1: the foam the physics makes: the larger of the breaking and the crest foam, which is
    /// crest_foam(jacobian, the body's J*) plus what this particle's crests left over the last 2 s,
    /// fading as exp(-age / 1 s), capped at 1 (whitecaps leave a fading trail; river waves, which ride
    /// their current, leave none). The water shader adds visual detail on top (foam riding the crests,
    /// swash bands along the coast).
    double foam = 0.0;
    /// The wakes' share of the height, m (QueryOptions::wakes; the scene's boats in query_world).
    double wake = 0.0;
    int iterations = 0;  ///< Newton evaluations used.
    bool converged = true;
};

namespace detail {
/// SurfacePoint::wet, the one definition every backend uses.
inline bool surface_wet(double height, double level, double depth) {
    return height > level - depth;
}
}  // namespace detail

struct Wakes;

struct QueryOptions {
    /// Worker threads; 0 uses every hardware thread. Small batches run on the caller's thread.
    unsigned threads = 1;
    /// Wakes on the water (tidewater/wakes.hpp): their waves join the body's in the one
    /// evaluation and their turbulence adds foam. Only read; must outlive the call.
    const Wakes* wakes = nullptr;
    /// Leave this emitter's wakes out (a boat riding its own wake); -1: none.
    int exclude_emitter = -1;
    /// Where the water is removed besides the scene's own (tidewater/clip_volume.hpp): the
    /// host's moving volumes, a float's hull. Read by the queries of a whole scene
    /// (query_world, query_submersion), which report the surface inside them dry. Only
    /// read; must outlive the call.
    std::span<const ClipVolume> clip_volumes = {};
};

/// Full surface state at each point (x, z) at clock time `time` (the body's
/// time offset is added). `out.size()` must equal `points.size()`.
Status query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                     std::span<SurfacePoint> out, const QueryOptions& options = {});

/// Heights only (world y), the fast path for buoyancy and gameplay.
Status query_heights(const WaterBody& body, double time, std::span<const glm::dvec2> points, std::span<double> heights,
                     const QueryOptions& options = {});

/// Single-point convenience wrapper of query_surface.
SurfacePoint query_point(const WaterBody& body, double time, glm::dvec2 point);

/// Foam from crests compressing: a smoothstep from 0 to 1 across the body's whitecap
/// Jacobian J* (WaterBody::whitecap_jacobian, tidewater/whitecaps.hpp) over a width of
/// (1 - J*) / 2, so that foam >= 1/2 exactly where J < J* (the water shader uses the
/// same curve).
double crest_foam(double jacobian, double whitecap_jacobian);

/// Name of the SIMD kernel queries use on this machine ("avx2+fma", "sse2", ...).
const char* query_kernel_name();

}  // namespace tidewater
