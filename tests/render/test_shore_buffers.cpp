// The shore fields on the GPU after an edit: a model that shares all but a few slots with
// the one uploaded is written in place, those slots alone, and the buffers then hold what
// a fresh upload of it would, value for value. Over the budget, the tiles near the camera
// stream in at full resolution over a coarse level.
#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "../baked_scene.hpp"
#include "../tiled_coast.hpp"
#include "scene_uploads.hpp"
#include "storage_range_hook.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "vk_device.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

using render::detail::ShoreBuffers;

class ShoreBuffersTest : public test::VulkanTest {
  protected:
    void release() override { buffers_.reset(); }
    /// The device, and the tiled coast's shore model (its waves in runs on coarser grids).
    void load_coast() {
        auto device = render::detail::load_device(context());
        ASSERT_TRUE(device.ok()) << device.error().message;
        device_ = std::move(device).value();
        auto scene = test::baked(test::tiled_coast_scene(/*texels_per_wavelength=*/4.0));
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        model_ = scene->ocean.shore();
        ASSERT_NE(model_, nullptr);
    }
    std::unique_ptr<ShoreBuffers> buffers_;
    std::optional<render::detail::Device> device_;
    std::shared_ptr<const ShoreWaves> model_;
};

bool same_values(std::span<const glm::vec4> a, const std::vector<glm::vec4>& b) {
    return a.size() >= b.size() && std::equal(b.begin(), b.end(), a.begin());
}

/// `model` with depths 1 m shallower over 40 x 40 texels of its first stored tile: the
/// tiles under them change, the rest are shared.
std::shared_ptr<const ShoreWaves> edit_first_stored_tile(const ShoreWaves& model) {
    const ShoreTiles& tiles = model.shared();
    std::size_t stored = 0;
    while (stored < tiles.pages.size() && tiles.pages[stored] < gpu::kShoreFirstStoredSlot) ++stored;
    if (stored == tiles.pages.size()) return nullptr;
    const int i0 = static_cast<int>(stored % static_cast<std::size_t>(tiles.tiles_per_side)) * ShoreTiles::kTile + 8;
    const int j0 = static_cast<int>(stored / static_cast<std::size_t>(tiles.tiles_per_side)) * ShoreTiles::kTile + 8;
    std::vector<float> depths;
    for (int j = j0; j < j0 + 40; ++j)
        for (int i = i0; i < i0 + 40; ++i) depths.push_back(model.texel_values(i, j).depth() - 1.0f);
    return model.with_depths(i0, j0, 40, 40, depths);
}

TEST_F(ShoreBuffersTest, AnEditedModelIsWrittenInPlace) {
    ASSERT_NO_FATAL_FAILURE(load_coast());
    const auto& model = model_;
    const render::detail::Device* device = &*device_;
    buffers_ = std::make_unique<ShoreBuffers>();
    auto first = buffers_->upload(*device, model);
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_TRUE(*first);
    const VkBuffer shared_buffer = buffers_->shared();

    const ShoreTiles& tiles = model->shared();
    const auto edited = edit_first_stored_tile(*model);
    ASSERT_NE(edited, nullptr);
    std::size_t copied = 0;
    for (std::size_t s = 0; s < tiles.slot_count(); ++s) copied += tiles.slot(s) != edited->shared().slot(s);
    ASSERT_GE(copied, 1u);

    auto second = buffers_->upload(*device, edited);
    ASSERT_TRUE(second.ok()) << second.error().message;
    EXPECT_FALSE(*second) << "the buffers are kept";
    EXPECT_EQ(buffers_->shared(), shared_buffer);
    EXPECT_EQ(buffers_->rewritten_bytes(), copied * ShoreTiles::kSlotTexels * sizeof(glm::vec4));
    std::printf("an edit of %zu slots rewrote %llu bytes of %llu\n", copied,
                static_cast<unsigned long long>(buffers_->rewritten_bytes()),
                static_cast<unsigned long long>(buffers_->bytes()));
    std::vector<render::detail::ShorePlacement> placements;
    const render::detail::PackedShore fresh = render::detail::pack_shores({edited.get()}, placements);
    EXPECT_TRUE(same_values(buffers_->shared_values(), fresh.shared));
    EXPECT_TRUE(same_values(buffers_->per_wave_values(), fresh.per_wave));
    EXPECT_FALSE(same_values(buffers_->shared_values(), render::detail::pack_shores({model.get()}, placements).shared));

    // A model laid out otherwise (another scene's) replaces the buffers.
    auto other = test::baked(test::tiled_coast_scene(/*texels_per_wavelength=*/0.0));
    ASSERT_TRUE(other.ok()) << other.error().message;
    auto third = buffers_->upload(*device, other->ocean.shore());
    ASSERT_TRUE(third.ok()) << third.error().message;
    EXPECT_TRUE(*third);
    EXPECT_TRUE(same_values(buffers_->shared_values(),
                            render::detail::pack_shores({other->ocean.shore().get()}, placements).shared));
}

/// Layer `layer`'s pool slot behind page `page` in `values` (the buffer it packs to).
std::span<const glm::vec4> pool_slot(std::span<const glm::vec4> values, const render::detail::StreamedLayer& layer,
                                     std::uint32_t page) {
    const std::size_t per_slot = render::detail::packed_slot_vec4s(*layer.tiles, layer.shared);
    return values.subspan(layer.first_element + page * per_slot, per_slot);
}

/// Whether every resident full-resolution tile holds `model`'s values, layer by layer;
/// counts the resident tiles whose slot `model` does not share with `before`.
::testing::AssertionResult resident_tiles_hold(const ShoreBuffers& buffers, const ShoreWaves& model,
                                               const ShoreWaves* before, std::size_t* changed = nullptr) {
    std::vector<const ShoreTiles*> tiles{&model.shared()}, old_tiles;
    for (const ShoreWaveLayer& l : model.layers()) tiles.push_back(&l.tiles);
    if (before) {
        old_tiles.push_back(&before->shared());
        for (const ShoreWaveLayer& l : before->layers()) old_tiles.push_back(&l.tiles);
    }
    const auto& layers = buffers.streaming().layers();
    if (layers.size() != tiles.size()) return ::testing::AssertionFailure() << "layers differ";
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const ShoreTiles& t = *tiles[l];
        const auto values = layers[l].shared ? buffers.shared_values() : buffers.per_wave_values();
        for (std::size_t tile = 0; tile < t.pages.size(); ++tile) {
            const std::uint32_t page = buffers.pages_now()[layers[l].first_page + tile];
            if (page < gpu::kShoreFirstStoredSlot || page == gpu::kShoreNotResident) continue;
            std::vector<glm::vec4> expected(render::detail::packed_slot_vec4s(t, layers[l].shared));
            render::detail::pack_slot(t, t.pages[tile], layers[l].shared, expected.data());
            const auto slot = pool_slot(values, layers[l], page);
            if (!std::equal(slot.begin(), slot.end(), expected.begin()))
                return ::testing::AssertionFailure() << "layer " << l << " tile " << tile << " differs";
            if (changed && before) *changed += t.slot(t.pages[tile]) != old_tiles[l]->slot(t.pages[tile]);
        }
    }
    return ::testing::AssertionSuccess();
}

TEST_F(ShoreBuffersTest, AnEditOverTheBudgetIsWrittenInPlace) {
    ASSERT_NO_FATAL_FAILURE(load_coast());
    const auto& model = model_;
    const render::detail::Device* device = &*device_;
    // A third of what the model takes: drawn from every k-th texel.
    const std::uint64_t budget = model->device_bytes() / 3;
    buffers_ = std::make_unique<ShoreBuffers>();
    auto first = buffers_->upload(*device, ShoreBuffers::Models{model}, budget);
    ASSERT_TRUE(first.ok()) << first.error().message;
    const int stride = buffers_->stride();
    ASSERT_GT(stride, 1);
    const VkBuffer shared_buffer = buffers_->shared();

    const auto edited = edit_first_stored_tile(*model);
    ASSERT_NE(edited, nullptr);
    // The camera over the edit: its tiles are streamed in at full resolution first.
    const ShoreTiles& tiles = model->shared();
    std::size_t first_stored = 0;
    while (tiles.pages[first_stored] < gpu::kShoreFirstStoredSlot) ++first_stored;
    const double tile_side = ShoreTiles::kTile * model->texel();
    const auto per_side = static_cast<std::size_t>(tiles.tiles_per_side);
    const glm::dvec2 camera =
        model->corner() + tile_side * glm::dvec2(static_cast<double>(first_stored % per_side) + 0.5,
                                                 static_cast<double>(first_stored / per_side) + 0.5);
    for (std::uint64_t frame = 0, quiet = 0; quiet < 3 && frame < 1000; ++frame)
        quiet = buffers_->stream(std::span<const glm::dvec2>(&camera, 1), frame, 2, std::uint64_t{1} << 20) == 0
                    ? quiet + 1
                    : 0;
    ASSERT_GT(buffers_->streamed_tiles(), 0u);
    ASSERT_TRUE(resident_tiles_hold(*buffers_, *model, nullptr));

    auto second = buffers_->upload(*device, ShoreBuffers::Models{edited}, budget);
    ASSERT_TRUE(second.ok()) << second.error().message;
    EXPECT_FALSE(*second) << "the buffers are kept";
    EXPECT_EQ(buffers_->shared(), shared_buffer);
    EXPECT_EQ(buffers_->stride(), stride);
    EXPECT_GT(buffers_->rewritten_bytes(), 0u);
    EXPECT_LT(buffers_->rewritten_bytes(), buffers_->bytes() / 10);
    std::printf("over the budget (every %d texels), an edit rewrote %llu bytes of %llu\n", stride,
                static_cast<unsigned long long>(buffers_->rewritten_bytes()),
                static_cast<unsigned long long>(buffers_->bytes()));
    // What a fresh coarsening of the edited model packs to, value for value.
    std::vector<render::detail::ShorePlacement> placements;
    const auto fresh_coarse = edited->coarsened(stride);
    const render::detail::PackedShore fresh = render::detail::pack_shores({fresh_coarse.get()}, placements);
    EXPECT_TRUE(same_values(buffers_->shared_values(), fresh.shared));
    EXPECT_TRUE(same_values(buffers_->per_wave_values(), fresh.per_wave));
    const auto old_coarse = model->coarsened(stride);
    EXPECT_FALSE(
        same_values(buffers_->shared_values(), render::detail::pack_shores({old_coarse.get()}, placements).shared));
    // The full-resolution tiles streamed in before the edit hold the edited model's values.
    std::size_t changed = 0;
    EXPECT_TRUE(resident_tiles_hold(*buffers_, *edited, model.get(), &changed));
    EXPECT_GT(changed, 0u) << "the edit reaches a streamed tile";
}

// Within the budget but over what one storage buffer may span on the device, the model is
// drawn coarser, as over the budget: no buffer is larger than the device can bind.
TEST_F(ShoreBuffersTest, NoBufferSpansMoreThanTheDeviceBinds) {
    ASSERT_NO_FATAL_FAILURE(load_coast());
    const std::uint64_t budget = 4 * model_->device_bytes();
    buffers_ = std::make_unique<ShoreBuffers>();
    auto fits = buffers_->upload(*device_, ShoreBuffers::Models{model_}, budget);
    ASSERT_TRUE(fits.ok()) << fits.error().message;
    EXPECT_EQ(buffers_->stride(), 1) << "the coast fits this device's storage buffers whole";
    // The same device as a host's loader presents one whose storage buffers span a third
    // of the fields: within the budget, the buffers still stay within that range.
    const auto range = static_cast<std::uint32_t>(model_->device_bytes() / 3);
    auto limited = render::detail::load_device(test::with_storage_range(context(), range));
    ASSERT_TRUE(limited.ok()) << limited.error().message;
    buffers_ = std::make_unique<ShoreBuffers>();
    auto bounded = buffers_->upload(*limited, ShoreBuffers::Models{model_}, budget);
    ASSERT_TRUE(bounded.ok()) << bounded.error().message;
    EXPECT_GT(buffers_->stride(), 1);
    EXPECT_LE(buffers_->bytes(), range);
    buffers_.reset();
}

/// Squared distance from `camera` to the centre of tile `t` of `layer`.
double tile_distance2(const render::detail::StreamedLayer& layer, std::size_t t, glm::dvec2 camera) {
    const double side = ShoreTiles::kTile * layer.grid.texel;
    const auto per_side = static_cast<std::size_t>(layer.tiles->tiles_per_side);
    const glm::dvec2 centre = layer.grid.corner + side * glm::dvec2(static_cast<double>(t % per_side) + 0.5,
                                                                    static_cast<double>(t / per_side) + 0.5);
    return glm::dot(centre - camera, centre - camera);
}

// Over the budget the coarse level is resident and the full-resolution tiles nearest the
// camera stream in, a bounded number of bytes per frame. Checked frame after frame: each
// resident tile's pool slot holds that tile's values exactly; no slot a frame still in
// flight reads is written; once streaming settles, the resident tiles of each layer are
// its nearest; a camera moved elsewhere brings its own tiles in.
TEST_F(ShoreBuffersTest, TilesNearTheCameraStreamInAtFullResolution) {
    ASSERT_NO_FATAL_FAILURE(load_coast());
    const render::detail::Device* device = &*device_;
    buffers_ = std::make_unique<ShoreBuffers>();
    const std::uint64_t budget = model_->device_bytes() / 3;
    auto first = buffers_->upload(*device, ShoreBuffers::Models{model_}, budget);
    ASSERT_TRUE(first.ok()) << first.error().message;
    ASSERT_GT(buffers_->stride(), 1);
    EXPECT_LE(buffers_->bytes(), budget + budget / 20);
    EXPECT_EQ(buffers_->streamed_tiles(), 0u);
    const auto& layers = buffers_->streaming().layers();
    ASSERT_EQ(layers.size(), 1 + model_->layers().size());
    for (const auto& layer : layers)
        for (std::size_t t = 0; t < layer.tiles->pages.size(); ++t)
            ASSERT_EQ(buffers_->pages_now()[layer.first_page + t], layer.tiles->pages[t] < gpu::kShoreFirstStoredSlot
                                                                       ? layer.tiles->pages[t]
                                                                       : gpu::kShoreNotResident);

    // A frame brings at most one slot of the largest layer past the bound.
    std::size_t largest_slot = 0;
    for (const auto& layer : layers)
        largest_slot =
            std::max(largest_slot, render::detail::packed_slot_vec4s(*layer.tiles, layer.shared) * sizeof(glm::vec4));
    const std::uint64_t per_frame = 3 * largest_slot;
    constexpr std::uint32_t kInFlight = 2;
    std::vector<std::uint32_t> pages_before(buffers_->pages_now().begin(), buffers_->pages_now().end());
    std::vector<glm::vec4> shared_before(buffers_->shared_values().begin(), buffers_->shared_values().end());
    std::vector<glm::vec4> waves_before(buffers_->per_wave_values().begin(), buffers_->per_wave_values().end());
    std::uint64_t frame = 0;
    auto stream_until_settled = [&](glm::dvec2 camera) {
        for (int settled = 0; settled < int(kInFlight) + 1; ++frame) {
            ASSERT_LT(frame, 10000u) << "streaming does not settle";
            const std::uint64_t written =
                buffers_->stream(std::span<const glm::dvec2>(&camera, 1), frame, kInFlight, per_frame);
            EXPECT_LE(written, per_frame + largest_slot);
            settled = written == 0 ? settled + 1 : 0;
            const auto pages = buffers_->pages_now();
            for (const auto& layer : layers)
                for (std::size_t t = 0; t < layer.tiles->pages.size(); ++t) {
                    const std::uint32_t before = pages_before[layer.first_page + t], now = pages[layer.first_page + t];
                    // The previous frame, maybe still in flight, reads its slots unchanged.
                    const auto values = layer.shared ? buffers_->shared_values() : buffers_->per_wave_values();
                    if (before >= gpu::kShoreFirstStoredSlot && before != gpu::kShoreNotResident) {
                        const auto then = pool_slot(layer.shared ? shared_before : waves_before, layer, before);
                        const auto slot = pool_slot(values, layer, before);
                        ASSERT_TRUE(std::equal(slot.begin(), slot.end(), then.begin()))
                            << "frame " << frame << " wrote a slot the frame before reads";
                    }
                    // A resident tile's slot holds its full-resolution values.
                    if (now >= gpu::kShoreFirstStoredSlot && now != gpu::kShoreNotResident) {
                        std::vector<glm::vec4> expected(render::detail::packed_slot_vec4s(*layer.tiles, layer.shared));
                        render::detail::pack_slot(*layer.tiles, layer.tiles->pages[t], layer.shared, expected.data());
                        const auto slot = pool_slot(values, layer, now);
                        ASSERT_TRUE(std::equal(slot.begin(), slot.end(), expected.begin()))
                            << "tile " << t << " at frame " << frame;
                    }
                }
            pages_before.assign(pages.begin(), pages.end());
            shared_before.assign(buffers_->shared_values().begin(), buffers_->shared_values().end());
            waves_before.assign(buffers_->per_wave_values().begin(), buffers_->per_wave_values().end());
        }
    };
    // Each layer's resident tiles are its nearest stored ones, as many as its pool holds.
    auto expect_nearest_resident = [&](glm::dvec2 camera) {
        const auto pages = buffers_->pages_now();
        for (const auto& layer : layers) {
            double farthest_resident = 0.0, nearest_missing = std::numeric_limits<double>::infinity();
            std::size_t resident = 0, stored = 0;
            for (std::size_t t = 0; t < layer.tiles->pages.size(); ++t) {
                if (layer.tiles->pages[t] < gpu::kShoreFirstStoredSlot) continue;
                ++stored;
                const double d2 = tile_distance2(layer, t, camera);
                if (pages[layer.first_page + t] == gpu::kShoreNotResident)
                    nearest_missing = std::min(nearest_missing, d2);
                else
                    ++resident, farthest_resident = std::max(farthest_resident, d2);
            }
            EXPECT_EQ(resident, std::min(stored, layer.pool_slots));
            EXPECT_LE(farthest_resident, nearest_missing);
        }
    };
    std::size_t pooled = 0;
    for (const auto& layer : layers) pooled += std::min(layer.pool_slots, layer.tiles->stored_tiles());
    ASSERT_GT(pooled, 0u);
    ASSERT_LT(pooled, buffers_->streamable_tiles()) << "the pools hold part of the model";

    const ShoreGrid& grid = model_->grid();
    const glm::dvec2 west = grid.corner + glm::dvec2(0.1, 0.5) * (grid.texel * grid.resolution);
    const glm::dvec2 east = grid.corner + glm::dvec2(0.9, 0.5) * (grid.texel * grid.resolution);
    ASSERT_NO_FATAL_FAILURE(stream_until_settled(west));
    EXPECT_EQ(buffers_->streamed_tiles(), pooled);
    expect_nearest_resident(west);
    const std::uint64_t frames_west = frame;
    ASSERT_NO_FATAL_FAILURE(stream_until_settled(east));
    EXPECT_EQ(buffers_->streamed_tiles(), pooled);
    expect_nearest_resident(east);
    std::printf(
        "%zu of %zu tiles streamed at full resolution (%d-texel coarse level, %.1f of %.1f MiB); "
        "%llu frames to settle, %llu to move\n",
        pooled, buffers_->streamable_tiles(), buffers_->stride(), buffers_->bytes() / 1048576.0,
        model_->device_bytes() / 1048576.0, static_cast<unsigned long long>(frames_west),
        static_cast<unsigned long long>(frame - frames_west));
}

}  // namespace
}  // namespace tidewater
