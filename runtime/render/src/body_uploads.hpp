// Lakes and rivers on the GPU (private): their static fields, uploaded once per scene,
// and the per-frame draws that evaluate them (shaders/water_draw.glsl).
//   river fields  each river's query texels (kRiverQueryStride floats) and channel
//                 (s, n, flow x, z) per texel, one river after another;
//   body masks    each river's texel kinds, then each lake's extent (grown by a texel:
//                 the terrain hides what lies above it). Rivers come first, so a river's
//                 texels have the same index in its fields and in the masks;
//   patch list    the patches of each body's grid that hold its water.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "frame_constants.hpp"
#include "gpu_memory.hpp"
#include "host_device.h"
#include "scene_uploads.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/render/device_context.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::render::detail {

/// Where one lake's or river's data sit in the shared buffers.
struct BodyLayout {
    glm::dvec2 corner{0.0};  ///< grid corner, world xz, m
    double texel = 1.0;      ///< m
    int nx = 0, nz = 0;
    std::uint32_t first_texel = 0;  ///< in the body masks (and a river's in its fields)
    double patch = 8.0;             ///< m, a whole number of texels
    std::uint32_t first_patch = 0, patch_count = 0;
    double surface_rise = 0.0;  ///< highest rest surface above the level, m
};

/// The scene's lakes and rivers as the shaders read them; placeholders without any.
struct BodyBuffers {
    GpuBuffer river_texels, river_channel, masks, patches;
    std::vector<BodyLayout> lakes, rivers;  ///< in the scene's order

    static Result<BodyBuffers> create(const Device& ctx, const Scene& scene);
};

/// Appends a river's query texels and channel (s, n, flow x, z) per texel, as the
/// shaders read them (river_water.glsl), to `texels` and `channel`.
void append_river_fields(const tidewater::detail::RiverBake& river, std::vector<float>& texels,
                         std::vector<glm::vec4>& channel);

/// What one frame draws: the ocean (when the scene has one), each lake, each river.
struct BodyDraws {
    std::vector<gpu::GpuBodyDraw> draws;
    std::vector<gpu::GpuWave> waves;             ///< the ocean's, then each lake's
    std::vector<gpu::GpuRiverWave> river_waves;  ///< each river's, in its channel frame
    std::vector<std::uint32_t> patch_counts;     ///< instances of each draw
};

/// The ocean's waves and patch grid come from the frame's `plan`, each lake's waves are
/// drawn one by one as `waves_drawn` says (QualitySettings::waves_drawn), and `shores`
/// places each still body's shore model.
BodyDraws plan_body_draws(const Scene& scene, const BodyBuffers& bodies, double time, const FramePlan& plan,
                          const ShoreBuffers& shores, int waves_drawn);

}  // namespace tidewater::render::detail
