// Lakes and rivers on the GPU (private): their static fields, uploaded once per scene,
// and the per-frame draws that evaluate them (shaders/water_draw.glsl).
//   river fields  each river's query texels (kRiverQueryStride floats) and channel
//                 (s, n, flow x, z) per texel, one after another;
//   body masks    each river's texel kinds, then each lake's extent (grown by a texel:
//                 the terrain hides what lies above it);
//   patch list    the patches of each body's grid that hold its water.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gpu_memory.hpp"
#include "host_device.h"
#include "tidewater/render/device_context.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::render::detail {

/// Where one lake's or river's data sit in the shared buffers.
struct BodyLayout {
    glm::dvec2 corner{0.0};  ///< grid corner, world xz, m
    double texel = 1.0;      ///< m
    int nx = 0, nz = 0;
    std::uint32_t first_texel = 0;  ///< river fields (rivers) or body masks (both)
    std::uint32_t first_mask = 0;
    double patch = 8.0;             ///< m
    std::uint32_t first_patch = 0, patch_count = 0;
    double surface_rise = 0.0;      ///< highest rest surface above the level, m
};

/// The scene's lakes and rivers as the shaders read them; placeholders without any.
struct BodyBuffers {
    GpuBuffer river_texels, river_channel, masks, patches;
    std::vector<BodyLayout> lakes, rivers;  ///< in the scene's order

    static Result<BodyBuffers> create(const DeviceContext& ctx, const Scene& scene);
};

/// What one frame draws: the ocean (when the scene has one), each lake, each river.
struct BodyDraws {
    std::vector<gpu::GpuBodyDraw> draws;
    std::vector<gpu::GpuWave> waves;             ///< the ocean's, then each lake's
    std::vector<gpu::GpuRiverWave> river_waves;  ///< each river's, in its channel frame
    std::vector<std::uint32_t> patch_counts;     ///< instances of each draw
};

/// `ocean_waves` and `ocean_patch` are the frame plan's (phases at the render origin).
BodyDraws plan_body_draws(const Scene& scene, const BodyBuffers& bodies, double time, glm::dvec2 origin,
                          const std::vector<gpu::GpuWave>& ocean_waves, const glm::vec4& ocean_patch,
                          std::uint32_t ocean_patches, bool ocean_shore);

}  // namespace tidewater::render::detail
