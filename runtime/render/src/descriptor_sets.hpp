// The descriptor sets of Tidewater's pipelines (private), each described by one table
// of its bindings in host_device.h's order. A set's layout, its pool sizes and its
// descriptor writes are all made from that table, so a new binding is one row here.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "host_device.h"
#include "vk_handle.hpp"

namespace tidewater::render::detail {

struct BindingRow {
    std::uint32_t binding;
    VkDescriptorType type;
};

namespace binding_types {
inline constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
inline constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
inline constexpr VkDescriptorType kTexture = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
}  // namespace binding_types

/// Set gpu::kFrameSet of the render pipelines (frame.glsl, water_draw.glsl).
inline constexpr std::array<BindingRow, gpu::eFrameBindingCount> kFrameSetRows = {{
    {gpu::eFrameConstants, binding_types::kUniform},     {gpu::eFrameWaves, binding_types::kStorage},
    {gpu::eFrameTerrainHeight, binding_types::kTexture}, {gpu::eFrameSceneColor, binding_types::kTexture},
    {gpu::eFrameSceneDepth, binding_types::kTexture},    {gpu::eFrameShoreWaves, binding_types::kStorage},
    {gpu::eFrameShoreShared, binding_types::kStorage},   {gpu::eFrameBodyDraws, binding_types::kStorage},
    {gpu::eFrameRiverTexels, binding_types::kStorage},   {gpu::eFrameRiverChannel, binding_types::kStorage},
    {gpu::eFrameBodyMasks, binding_types::kStorage},     {gpu::eFrameRiverWaves, binding_types::kStorage},
    {gpu::eFramePatchList, binding_types::kStorage},     {gpu::eFrameWakePoints, binding_types::kStorage},
    {gpu::eFrameShorePages, binding_types::kStorage},    {gpu::eFrameShoreLayers, binding_types::kStorage},
    {gpu::eFrameSkyTable, binding_types::kTexture},      {gpu::eFrameFoamNoise, binding_types::kTexture},
    {gpu::eFrameClipTextures, binding_types::kStorage},
}};

/// Set gpu::kQuerySet of the GPU query pipeline (query.comp).
inline constexpr std::array<BindingRow, gpu::eQueryBindingCount> kQuerySetRows = {{
    {gpu::eQueryWaves, binding_types::kStorage},
    {gpu::eQueryBasePhases, binding_types::kStorage},
    {gpu::eQueryPoints, binding_types::kStorage},
    {gpu::eQueryResults, binding_types::kStorage},
    {gpu::eQueryShoreWaves, binding_types::kStorage},
    {gpu::eQueryShoreShared, binding_types::kStorage},
    {gpu::eQueryCellOrigins, binding_types::kStorage},
    {gpu::eQueryRiverTexels, binding_types::kStorage},
    {gpu::eQueryRiverChannel, binding_types::kStorage},
    {gpu::eQueryRiverWaves, binding_types::kStorage},
    {gpu::eQueryWakePoints, binding_types::kStorage},
    {gpu::eQueryShorePages, binding_types::kStorage},
    {gpu::eQueryShoreLayers, binding_types::kStorage},
}};

/// The most bindings a set has (write_set writes a set without allocating).
inline constexpr std::size_t kMaxSetBindings = 19;
static_assert(gpu::eFrameBindingCount <= kMaxSetBindings && gpu::eQueryBindingCount <= kMaxSetBindings);

/// Row i describes binding i: what a set's writes index by.
template <std::size_t N>
constexpr bool rows_in_binding_order(const std::array<BindingRow, N>& rows) {
    for (std::size_t i = 0; i < N; ++i)
        if (rows[i].binding != i) return false;
    return true;
}
static_assert(rows_in_binding_order(kFrameSetRows), "kFrameSetRows must list host_device.h's FrameBinding in order");
static_assert(rows_in_binding_order(kQuerySetRows), "kQuerySetRows must list host_device.h's QueryBinding in order");

/// The set layout of `rows`, visible to `stages`.
VkResult make_set_layout(const Device& device, std::span<const BindingRow> rows, VkShaderStageFlags stages,
                         OwnedSetLayout& out);

/// A pool for `sets` sets of `rows`.
VkResult make_descriptor_pool(const Device& device, std::span<const BindingRow> rows, std::uint32_t sets,
                              OwnedDescriptorPool& out);

/// What one binding holds: its buffer, or its sampled image (by the row's type).
struct BoundResource {
    VkDescriptorBufferInfo buffer{};
    VkDescriptorImageInfo image{};
};
inline BoundResource bound_buffer(VkBuffer buffer) {
    return {{buffer, 0, VK_WHOLE_SIZE}, {}};
}
inline BoundResource bound_texture(VkSampler sampler, VkImageView view) {
    return {{}, {sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
}

/// Writes every binding of `set`: resources[i] into binding rows[i].
void write_set(const Device& device, VkDescriptorSet set, std::span<const BindingRow> rows,
               std::span<const BoundResource> resources);

}  // namespace tidewater::render::detail
