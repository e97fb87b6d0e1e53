#include "scene_uploads.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "terrain_mesh.hpp"
#include "vk_util.hpp"

namespace tidewater::render::detail {

Status upload_image(const Device& ctx, VkCommandPool pool, GpuImage& image, const void* data, VkDeviceSize bytes,
                    VkImageAspectFlags aspect, VkImageAspectFlags barrier_aspects, std::optional<VkRect2D> region) {
    if (barrier_aspects == 0) barrier_aspects = aspect;
    auto staging = GpuBuffer::create(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    if (!staging) return staging.error();
    std::memcpy(staging->mapped(), data, bytes);
    const VkRect2D rect = region.value_or(VkRect2D{{0, 0}, image.extent()});
    return submit_and_wait(ctx, pool, [&](VkCommandBuffer cmd) {
        // Written in part, the image keeps its texels: it leaves the layout the shaders read.
        if (region)
            transition(ctx.vk(), cmd, image.handle(), barrier_aspects, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
                       VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        else
            transition(ctx.vk(), cmd, image.handle(), barrier_aspects, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {aspect, 0, 0, 1};
        copy.imageOffset = {rect.offset.x, rect.offset.y, 0};
        copy.imageExtent = {rect.extent.width, rect.extent.height, 1};
        ctx.vk().CmdCopyBufferToImage(cmd, staging->handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                                      &copy);
        transition(ctx.vk(), cmd, image.handle(), barrier_aspects, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
}

Result<TerrainUpload> TerrainUpload::create(const Device& ctx, VkCommandPool pool, const Terrain& terrain,
                                            std::uint64_t max_bytes) {
    TerrainUpload t;
    const TerrainPatch patch = build_terrain_patch();
    const VkDeviceSize vbytes = patch.vertices.size() * sizeof(glm::vec2),
                       ibytes = patch.indices.size() * sizeof(std::uint32_t);
    auto vb = GpuBuffer::create(ctx, vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!vb) return vb.error();
    auto ib = GpuBuffer::create(ctx, ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!ib) return ib.error();
    std::memcpy(vb->mapped(), patch.vertices.data(), vbytes);
    std::memcpy(ib->mapped(), patch.indices.data(), ibytes);
    TerrainHeights sampled = sample_terrain_heights(terrain, max_bytes);
    auto heights =
        GpuImage::create(ctx, {sampled.width, sampled.height}, VK_FORMAT_R16_UNORM,
                         VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!heights) return heights.error();
    if (auto st = upload_image(ctx, pool, *heights, sampled.texels.data(), sampled.bytes(), VK_IMAGE_ASPECT_COLOR_BIT);
        !st)
        return st.error();
    t.vertices = std::move(vb).value();
    t.indices = std::move(ib).value();
    t.index_count = static_cast<std::uint32_t>(patch.indices.size());
    t.quadrant_index_count = patch.quadrant_indices;
    t.heights = std::move(heights).value();
    t.resident_bytes = sampled.bytes() + vbytes + ibytes;
    TerrainPlacement& p = t.placement;
    p.height_rect_corner = sampled.corner;
    p.height_rect_size = sampled.texel * glm::dvec2(sampled.width, sampled.height);
    p.texel = sampled.texel;
    p.lowest_ground = sampled.lowest;
    p.highest_ground = sampled.highest;
    p.fade = sampled.fade;
    p.seabed = sampled.seabed;
    t.lod.finest_quad = sampled.texel;
    t.lod.grid_origin = sampled.corner + 0.5 * sampled.texel;
    t.lod.region_min = sampled.region_min;
    t.lod.region_max = sampled.region_max;
    t.lod.lowest = sampled.lowest;
    t.lod.highest = sampled.highest;
    t.water_half_size = std::max(3000.0, terrain.extent_half_size());
    t.written_bytes = sampled.bytes();
    sampled.texels = std::vector<std::uint16_t>();  // uploaded: only how they were sampled is kept
    t.sampling = std::move(sampled);
    return t;
}

Result<bool> TerrainUpload::update(const Device& ctx, VkCommandPool pool, const Terrain& before, const Terrain& after) {
    const auto patch = height_texture_patch(sampling, before, after);
    if (!patch) return false;
    written_bytes = patch->texels.size() * sizeof(std::uint16_t);
    if (patch->texels.empty()) return true;
    const VkRect2D region{{static_cast<std::int32_t>(patch->i0), static_cast<std::int32_t>(patch->j0)},
                          {patch->width, patch->height}};
    if (auto st =
            upload_image(ctx, pool, heights, patch->texels.data(), written_bytes, VK_IMAGE_ASPECT_COLOR_BIT, 0, region);
        !st)
        return st.error();
    return true;
}

}  // namespace tidewater::render::detail
