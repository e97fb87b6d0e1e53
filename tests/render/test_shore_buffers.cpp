// The shore fields on the GPU after an edit: a model that shares all but a few slots with
// the one uploaded is written in place, those slots alone, and the buffers then hold what
// a fresh upload of it would, value for value.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "../baked_scene.hpp"
#include "../tiled_coast.hpp"
#include "scene_uploads.hpp"
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
}

}  // namespace
}  // namespace tidewater
