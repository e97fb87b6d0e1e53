#include "scene_uploads.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "terrain_mesh.hpp"
#include "vk_util.hpp"

namespace tidewater::render::detail {

namespace {

/// Vec4s a slot packs to: one per texel of the shared layer, one per wave and texel of a run.
std::size_t packed_slot_vec4s(const ShoreTiles& tiles, bool shared) {
    return ShoreTiles::kSlotTexels * (shared ? 1 : tiles.stride / 4);
}

/// One slot as the shaders read it (shore_fields.glsl): a shared slot's texels (depth,
/// breaking, steepness scale, shore distance), or a run's waves one after the other, each
/// wave's texels (phase residual, amplitude factor, wavevector x, z).
void pack_slot(const ShoreTiles& tiles, std::size_t slot, bool shared, glm::vec4* out) {
    const float* texels = tiles.slot(slot);
    const std::size_t stride = tiles.stride;
    if (shared) {
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* t = texels + k * stride;
            *out++ = {t[0], t[1], t[2], t[3]};
        }
        return;
    }
    const std::size_t nw = stride / 4;
    for (std::size_t w = 0; w < nw; ++w)
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* t = texels + k * stride;
            *out++ = {t[w], t[nw + w], t[2 * nw + w], t[3 * nw + w]};
        }
}

/// Packs every slot of `tiles` at the end of `out`.
void pack_slots(const ShoreTiles& tiles, bool shared, std::vector<glm::vec4>& out) {
    const std::size_t per_slot = packed_slot_vec4s(tiles, shared), at = out.size();
    out.resize(at + per_slot * tiles.slot_count());
    for (std::size_t slot = 0; slot < tiles.slot_count(); ++slot)
        pack_slot(tiles, slot, shared, out.data() + at + slot * per_slot);
}

/// Whether `b` packs to the same places as `a`: the same grids, pages and slot counts.
bool same_layout(const ShoreWaves& a, const ShoreWaves& b) {
    auto same_tiles = [](const ShoreTiles& x, const ShoreTiles& y) {
        return x.stride == y.stride && x.slot_count() == y.slot_count() && x.pages == y.pages;
    };
    if (!(a.grid() == b.grid()) || !same_tiles(a.shared(), b.shared()) || a.layers().size() != b.layers().size())
        return false;
    for (std::size_t l = 0; l < a.layers().size(); ++l) {
        const ShoreWaveLayer &x = a.layers()[l], &y = b.layers()[l];
        if (!(x.grid == y.grid) || x.first != y.first || x.count != y.count || !same_tiles(x.tiles, y.tiles))
            return false;
    }
    return true;
}

}  // namespace

PackedShore pack_shores(const std::vector<const ShoreWaves*>& models, std::vector<ShorePlacement>& placements,
                        const std::vector<const ShoreWaves*>& placed_as) {
    PackedShore p;
    placements.assign(models.size(), ShorePlacement{});
    bool any = false;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves* shore = models[m];
        if (!shore) continue;
        if (!any) p.per_wave.clear(), p.shared.clear(), p.pages.clear(), p.layers.clear(), any = true;
        const ShoreTiles& shared = shore->shared();
        ShorePlacement& place = placements[m];
        place = {m < placed_as.size() ? placed_as[m] : shore, static_cast<std::uint32_t>(p.layers.size()),
                 static_cast<std::uint32_t>(p.shared.size()), static_cast<std::uint32_t>(p.pages.size())};
        place.texel = shore->texel();
        place.corner = shore->corner();
        place.resolution = shore->resolution();
        p.pages.insert(p.pages.end(), shared.pages.begin(), shared.pages.end());
        pack_slots(shared, true, p.shared);
        for (const ShoreWaveLayer& layer : shore->layers()) {
            const glm::dvec2 offset = layer.grid.corner - shore->corner();
            gpu::GpuShoreLayer record;
            record.grid = glm::vec4(static_cast<float>(offset.x), static_cast<float>(offset.y),
                                    static_cast<float>(layer.grid.texel), static_cast<float>(layer.grid.resolution));
            record.waves =
                glm::uvec4(static_cast<std::uint32_t>(layer.first), static_cast<std::uint32_t>(layer.count),
                           static_cast<std::uint32_t>(p.pages.size()), static_cast<std::uint32_t>(p.per_wave.size()));
            p.layers.push_back(record);
            const ShoreTiles& tiles = layer.tiles;
            p.pages.insert(p.pages.end(), tiles.pages.begin(), tiles.pages.end());
            pack_slots(tiles, false, p.per_wave);
        }
    }
    if (p.per_wave.empty()) p.per_wave.push_back(glm::vec4(0.0f));  // models without waves
    if (p.layers.empty()) p.layers.push_back(gpu::GpuShoreLayer{});
    return p;
}

std::uint64_t packed_shore_bytes(const std::vector<const ShoreWaves*>& models, int stride) {
    std::uint64_t bytes = 0;
    for (const ShoreWaves* m : models)
        if (m) bytes += m->coarsened_device_bytes(stride);
    return bytes;
}

bool ShoreBuffers::holds(const Models& models) const {
    if (!per_wave_.handle() || models.size() != placements_.size()) return false;
    for (std::size_t m = 0; m < models.size(); ++m)
        if (wanted(models[m]) != placements_[m].model) return false;
    return true;
}

bool ShoreBuffers::rewrite_in_place(const Models& models, const std::vector<const ShoreWaves*>& drawn, int stride) {
    if (!per_wave_.handle() || stride != stride_ || models.size() != uploaded_.size()) return false;
    // What each placement drew: the model uploaded, or its coarsening over the budget.
    auto drawn_before = [&](std::size_t m) { return stride_ > 1 ? coarse_[m].get() : uploaded_[m].get(); };
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves *now = drawn[m], *then = drawn_before(m);
        if ((now == nullptr) != (then == nullptr) || (now && !same_layout(*then, *now))) return false;
    }
    // The slots the new models do not share with the uploaded ones, written where they are.
    std::size_t written = 0;
    auto rewrite = [&](const ShoreTiles& before, const ShoreTiles& after, bool shared, GpuBuffer& buffer,
                       std::size_t first) {
        const std::size_t per_slot = packed_slot_vec4s(after, shared);
        auto* out = static_cast<glm::vec4*>(buffer.mapped()) + first;
        for (std::size_t slot = 0; slot < after.slot_count(); ++slot) {
            if (after.slot(slot) == before.slot(slot)) continue;
            pack_slot(after, slot, shared, out + slot * per_slot);
            written += per_slot * sizeof(glm::vec4);
        }
    };
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ShoreWaves *now = drawn[m], *then = drawn_before(m);
        if (!now) continue;
        const ShorePlacement& place = placements_[m];
        rewrite(then->shared(), now->shared(), true, shared_, place.shared);
        for (std::size_t l = 0; l < now->layers().size(); ++l)
            rewrite(then->layers()[l].tiles, now->layers()[l].tiles, false, per_wave_,
                    layer_records_[place.layers + l].waves.w);
        placements_[m].model = wanted(models[m]);
        uploaded_[m] = models[m];
    }
    rewritten_bytes_ = written;
    return true;
}

Result<bool> ShoreBuffers::upload(const Device& ctx, const Models& models, std::uint64_t max_bytes) {
    if (holds(models) && max_bytes == max_bytes_) {
        rewritten_bytes_ = 0;
        return false;
    }
    // A saved bake's tiles are read on demand: every one now, in parallel; one that cannot
    // be read fails the upload with its file's name.
    for (const auto& m : models)
        if (m)
            if (auto st = m->read_all(); !st) return st.error();
    std::vector<const ShoreWaves*> wanted_models;
    for (const auto& m : models) wanted_models.push_back(wanted(m));
    // Over the budget, every k-th texel of each model (the smallest k that fits, at most
    // 64), sized from the tiles' pages before anything is coarsened. A model re-baked from
    // the one drawn is coarsened sharing the drawn coarsening's tiles away from its edit.
    int stride = 1;
    while (packed_shore_bytes(wanted_models, stride) > max_bytes && stride < 64) ++stride;
    Models coarse;
    std::vector<const ShoreWaves*> drawn = wanted_models;
    if (stride > 1)
        for (std::size_t m = 0; m < drawn.size(); ++m) {
            const bool from_drawn =
                stride == stride_ && m < uploaded_.size() && m < coarse_.size() && uploaded_[m] && coarse_[m];
            coarse.push_back(wanted_models[m]
                                 ? wanted_models[m]->coarsened(stride, from_drawn ? uploaded_[m].get() : nullptr,
                                                               from_drawn ? coarse_[m].get() : nullptr)
                                 : nullptr);
            drawn[m] = coarse.back().get();
        }
    // A model edited in a few slots (ShoreWaves shares the rest): only those are written.
    if (max_bytes == max_bytes_ && rewrite_in_place(models, drawn, stride)) {
        coarse_ = std::move(coarse);
        return false;
    }
    std::vector<ShorePlacement> placements;
    const PackedShore packed = pack_shores(drawn, placements, wanted_models);
    // The offsets are 32-bit element indices in the shaders.
    if (packed.per_wave.size() > std::numeric_limits<std::uint32_t>::max())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: the shore models hold {} texels, more than 2^32", packed.per_wave.size())};
    GpuBuffer fresh[4];
    const std::pair<const void*, std::size_t> data[4] = {
        {packed.per_wave.data(), packed.per_wave.size() * sizeof(glm::vec4)},
        {packed.shared.data(), packed.shared.size() * sizeof(glm::vec4)},
        {packed.pages.data(), packed.pages.size() * sizeof(std::uint32_t)},
        {packed.layers.data(), packed.layers.size() * sizeof(gpu::GpuShoreLayer)}};
    for (int i = 0; i < 4; ++i) {
        auto made = GpuBuffer::storage_with(ctx, data[i].first, data[i].second);
        if (!made) return made.error();
        fresh[i] = std::move(made).value();
    }
    per_wave_ = std::move(fresh[0]);
    shared_ = std::move(fresh[1]);
    pages_ = std::move(fresh[2]);
    layers_ = std::move(fresh[3]);
    placements_ = std::move(placements);
    stride_ = stride;
    max_bytes_ = max_bytes;
    coarse_ = std::move(coarse);
    layer_records_ = packed.layers;
    rewritten_bytes_ = bytes();
    uploaded_.clear();
    for (std::size_t m = 0; m < models.size(); ++m) uploaded_.push_back(placements_[m].model ? models[m] : nullptr);
    return true;
}

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
