// The frame's clip volumes: the scene's, the host's and the floats', gathered in the world
// frame and packed into the frame's constants (GpuFrame.clip_volumes).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "host_device.h"
#include "tidewater/render/renderer.hpp"

namespace tidewater::render::detail {

struct FrameClips {
    std::vector<ClipVolume> host_and_floats;  ///< world: the host's, then the floats' kept
    std::uint32_t total = 0;                  ///< with the scene's
    std::uint32_t left_out = 0;               ///< floats' for want of room
    /// The distance textures of every volume kept, each once, in the order their samples
    /// lie in the frame's eFrameClipTextures buffer.
    std::vector<std::shared_ptr<const DistanceTexture>> textures;
};

/// The host's volumes (all: fails past kMaxClipVolumes with the scene's, past the frame's
/// planes or texture samples, or on a bad one) and the floats' (their body-frame clip at
/// their pose), nearest `camera` first, as many as fit.
Result<FrameClips> gather_clip_volumes(const Scene& scene, std::span<const ClipVolume> host,
                                       std::span<const FloatDraw> floats, glm::dvec3 camera);

/// Writes the scene's then `clips`' volumes into `frame`, relative to `origin` (x, z); a
/// distance texture's first sample is its place in `clips.textures`.
void pack_clip_volumes(const Scene& scene, const FrameClips& clips, glm::dvec2 origin, gpu::GpuFrame& frame);

/// The samples of `textures`, texture after texture: what eFrameClipTextures holds.
std::size_t texture_samples(std::span<const std::shared_ptr<const DistanceTexture>> textures);
void write_texture_samples(std::span<const std::shared_ptr<const DistanceTexture>> textures, float* out);

}  // namespace tidewater::render::detail
