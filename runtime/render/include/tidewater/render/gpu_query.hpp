// GPU surface queries: a compute shader solves the same Eulerian problem as
// tidewater::query_surface, for large batches or to check CPU/GPU parity.
//
// Points are grouped into 64 m phase cells whose per-wave phase is reduced in
// double on the CPU; the shader works in float relative to its cell, so the
// GPU is as accurate at x = 10 km as at the origin.
// Lifetime: borrows the DeviceContext, which must outlive it.
// Threading: one call at a time; each call submits to the context's queue and waits.
#pragma once

#include <glm/vec2.hpp>
#include <memory>
#include <span>

#include "tidewater/query.hpp"
#include "tidewater/render/device_context.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater::render {

class GpuQuery {
  public:
    static Result<std::unique_ptr<GpuQuery>> create(const DeviceContext& context);
    ~GpuQuery();
    GpuQuery(const GpuQuery&) = delete;
    GpuQuery& operator=(const GpuQuery&) = delete;

    /// Same contract as tidewater::query_surface, with `wakes` (null: none) as
    /// QueryOptions::wakes.
    Status query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                         std::span<SurfacePoint> out, const Wakes* wakes = nullptr);

    /// Same contract as tidewater::query_world: points are sorted into bodies on the
    /// host as the CPU does, then each body's water (a river's falling surface, waves and
    /// current included) is solved by the shader; the scene's boats' wakes ride the ocean
    /// and lakes. `detail`, when given (the same size
    /// as `points`), receives the river flow-detail slope at each point (0 elsewhere).
    Status query_world(const Scene& scene, double time, std::span<const glm::dvec2> points, std::span<WorldPoint> out,
                       std::span<glm::dvec2> detail = {});

  private:
    struct Impl;
    explicit GpuQuery(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tidewater::render
