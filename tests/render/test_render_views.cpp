// Several views a frame (Renderer::add_view, record_views): split screen in one image of
// the host's, each view drawing its own rectangle, gives the pictures single-view frames
// give; resizing one view while frames are in flight leaves the other as it was. Under
// the validation layer (synchronisation validation included): any message fails.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include "../baked_scene.hpp"
#include "test_host.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/tidewater.hpp"

namespace tidewater {
namespace {

using test::TestHost;

constexpr std::uint32_t kHalf = TestHost::kWidth / 2;

render::FrameTargets host_targets(const TestHost& host, VkExtent2D extent, VkOffset2D offset) {
    render::FrameTargets t;
    t.color_image = host.color.image;
    t.color_view = host.color.view;
    t.depth_image = host.depth.image;
    t.depth_view = host.depth.view;
    t.extent = extent;
    t.offset = offset;
    return t;
}

render::FrameInfo looking(glm::dvec3 from, glm::dvec3 at, std::uint64_t index) {
    render::FrameInfo frame;
    frame.camera.position = from;
    frame.camera.target = at;
    frame.camera.fov_y_deg = 50.0;
    frame.time = 2.5;
    frame.frame_index = index;
    return frame;
}

/// How `a`'s columns [ax, ax + width) differ from `b`'s [bx, bx + width): the largest
/// difference of a channel (of 255) and the share of pixels with one over 8.
struct Difference {
    int largest = 0;
    double over_8 = 0.0;
};
Difference compare_columns(const render::RgbaImage& a, int ax, const render::RgbaImage& b, int bx, int width) {
    Difference d;
    int over = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < width; ++x) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int va = a.pixels[(static_cast<std::size_t>(y) * a.width + ax + x) * 4 + c];
                const int vb = b.pixels[(static_cast<std::size_t>(y) * b.width + bx + x) * 4 + c];
                worst = std::max(worst, std::abs(va - vb));
            }
            d.largest = std::max(d.largest, worst);
            over += worst > 8;
        }
    d.over_8 = static_cast<double>(over) / (static_cast<double>(width) * a.height);
    return d;
}

// The two cameras: the default scene's island from the sea, and its beach from the side.
const glm::dvec3 kFromSea{0.0, 30.0, 160.0}, kAtIsland{0.0, 0.0, 0.0};
const glm::dvec3 kFromSide{-160.0, 14.0, -60.0}, kAtBeach{-40.0, 0.0, 0.0};

TEST(Views, TwoViewsInOneFrameDrawWhatTwoSingleViewFramesDraw) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        auto scene = test::baked(default_scene());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        const VkExtent2D half{kHalf, TestHost::kHeight};

        // Two single-view frames, each in the image's left half.
        std::array<render::RgbaImage, 2> single;
        {
            auto renderer = render::Renderer::create(test::renderer_info(host));
            ASSERT_TRUE(renderer.ok()) << renderer.error().message;
            ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
            ASSERT_TRUE((*renderer)->resize(half).ok());
            const std::array<render::FrameInfo, 2> frames = {looking(kFromSea, kAtIsland, 0),
                                                             looking(kFromSide, kAtBeach, 1)};
            for (std::size_t i = 0; i < 2; ++i) {
                VkCommandBuffer cmd = test::begin_commands(host);
                const Status st = (*renderer)->record_frame(cmd, frames[i], host_targets(host, half, {0, 0}));
                ASSERT_TRUE(st.ok()) << st.error().message;
                single[i] = test::finish_and_read(host, cmd);
            }
        }

        // One renderer, two views side by side in one image, recorded into one command buffer.
        render::RendererInitInfo init = test::renderer_info(host);
        init.frames_in_flight = 2;
        auto renderer = render::Renderer::create(init);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        render::Renderer& r = **renderer;
        ASSERT_TRUE(r.set_scene(*scene).ok());
        ASSERT_TRUE(r.resize(half).ok());
        auto side = r.add_view(half);
        ASSERT_TRUE(side.ok()) << side.error().message;
        EXPECT_EQ(r.views().size(), 2u);
        auto split_frame = [&](std::uint64_t index, VkExtent2D side_extent) {
            return std::array<render::ViewFrame, 2>{
                render::ViewFrame{render::kMainView, looking(kFromSea, kAtIsland, index),
                                  host_targets(host, half, {0, 0})},
                render::ViewFrame{*side, looking(kFromSide, kAtBeach, index),
                                  host_targets(host, side_extent, {static_cast<std::int32_t>(kHalf), 0})}};
        };
        VkCommandBuffer cmd = test::begin_commands(host);
        const auto both = split_frame(0, half);
        const Status recorded = r.record_views(cmd, both);
        ASSERT_TRUE(recorded.ok()) << recorded.error().message;
        const render::RgbaImage split = test::finish_and_read(host, cmd);

        const Difference left = compare_columns(split, 0, single[0], 0, kHalf);
        const Difference right = compare_columns(split, kHalf, single[1], 0, kHalf);
        std::printf(
            "split screen against single-view frames: left largest %d (%.4f over 8), right largest %d "
            "(%.4f over 8)\n",
            left.largest, left.over_8, right.largest, right.over_8);
        EXPECT_LT(left.over_8, 0.002) << "the main view's half is its single-view frame";
        EXPECT_LT(right.over_8, 0.002) << "the second view's half is its single-view frame";
        EXPECT_GT(compare_columns(single[0], 0, single[1], 0, kHalf).over_8, 0.2) << "the two cameras differ";
        EXPECT_GT(r.stats(*side).terrain_triangles, 0u);

        // A frame in flight (not waited for), then the second view resized: no wait, and the
        // copies that frame reads live on until it is done (the validation layer watches).
        cmd = test::begin_commands(host);
        ASSERT_TRUE(r.record_views(cmd, split_frame(1, half)).ok());
        vkEndCommandBuffer(cmd);
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        ASSERT_EQ(vkQueueSubmit(host.queue, 1, &submit, VK_NULL_HANDLE), VK_SUCCESS);
        const VkExtent2D narrower{kHalf - 28, TestHost::kHeight};
        ASSERT_TRUE(r.resize(narrower, *side).ok());
        VkCommandBuffer next = test::begin_commands(host);
        const Status resized = r.record_views(next, split_frame(2, narrower));
        ASSERT_TRUE(resized.ok()) << resized.error().message;
        const render::RgbaImage after = test::finish_and_read(host, next);
        vkFreeCommandBuffers(host.device, host.pool, 1, &cmd);
        const Difference untouched = compare_columns(after, 0, split, 0, kHalf);
        EXPECT_EQ(untouched.largest, 0) << "resizing the second view leaves the main view's picture as it was";
        EXPECT_GT(compare_columns(after, kHalf, split, kHalf, kHalf - 28).over_8, 0.05)
            << "the second view is drawn at its new size";

        // A removed view is refused by name; the main view cannot be removed.
        ASSERT_TRUE(r.remove_view(*side).ok());
        EXPECT_EQ(r.views().size(), 1u);
        cmd = test::begin_commands(host);
        const Status gone = r.record_views(cmd, split_frame(3, narrower));
        ASSERT_FALSE(gone.ok());
        EXPECT_NE(gone.error().message.find("not there"), std::string::npos) << gone.error().message;
        EXPECT_FALSE(r.remove_view(render::kMainView).ok());
        // The same view twice, or views of different frame indices, in one frame: refused.
        auto twice = split_frame(3, half);
        twice[1].view = render::kMainView;
        const Status repeated = r.record_views(cmd, twice);
        ASSERT_FALSE(repeated.ok());
        EXPECT_NE(repeated.error().message.find("twice"), std::string::npos) << repeated.error().message;
        // Frames go on with the main view alone (the removed view's buffers go once no frame reads them).
        for (std::uint64_t index = 3; index < 6; ++index) {
            if (index > 3) cmd = test::begin_commands(host);
            ASSERT_TRUE(
                r.record_frame(cmd, looking(kFromSea, kAtIsland, index), host_targets(host, half, {0, 0})).ok());
            const render::RgbaImage alone = test::finish_and_read(host, cmd);
            EXPECT_EQ(compare_columns(alone, 0, split, 0, kHalf).largest, 0);
        }
        renderer->reset();
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

}  // namespace
}  // namespace tidewater
