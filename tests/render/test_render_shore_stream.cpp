// Over the memory budget the shore fields are drawn from a coarse level, and the
// full-resolution tiles nearest the camera stream in as frames are recorded: the picture
// converges on the one drawn with the whole model resident, without a validation message.
#include <cstdio>

#include "render_fixture.hpp"

namespace tidewater {
namespace {

/// Frames 0 .. frames - 1 of `frame` through a renderer of its own whose memory budget is
/// `budget` bytes and that streams at most `per_frame` bytes of shore tiles a frame; the last.
struct StreamedFrames {
    render::RgbaImage image;
    render::RendererStats stats;
    std::uint64_t frames_streaming = 0;  ///< frames that brought tiles in
};
StreamedFrames render_streaming(const render::DeviceContext& device, const Scene& scene, render::FrameInfo frame,
                                std::uint64_t budget, std::uint64_t per_frame, int frames) {
    StreamedFrames out;
    auto renderer = test::renderer_within_budget(device, scene, budget, per_frame);
    if (!renderer) return out;
    auto target = render::OffscreenTarget::create(device, 320, 180);
    EXPECT_TRUE(target.ok());
    if (!target.ok()) return out;
    for (int f = 0; f < frames; ++f) {
        frame.frame_index = static_cast<std::uint64_t>(f);
        auto img = (*target)->render(*renderer, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        if (!img.ok()) return out;
        out.image = std::move(img).value();
        out.stats = renderer->stats();
        out.frames_streaming += out.stats.shore_streamed_bytes > 0 ? 1 : 0;
    }
    return out;
}

// The default island's shore fields (24 waves at 256², and its tarn's) take about 31 MiB;
// under a 16 MiB budget they are drawn from every k-th texel, with a pool of about 4 MiB
// for full-resolution tiles. Streaming 512 KiB a frame, the pool fills over several frames,
// nearest tiles first.
TEST_F(RenderTest, ShoreTilesNearTheCameraStreamInOverFrames) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    render::FrameInfo frame = test::scene_camera_frame(*scene, 3.0);
    for (const render::DebugView view : {render::DebugView::shore, render::DebugView::shaded}) {
        frame.view = view;
        const render::RgbaImage full = render(*scene, frame, 320, 180);
        const render::RendererStats full_stats = renderer_->stats();
        EXPECT_EQ(full_stats.shore_stride, 1u);
        EXPECT_EQ(full_stats.shore_streamed_tiles, 0u);

        constexpr std::uint64_t kBudget = 16ull << 20;
        const StreamedFrames coarse = render_streaming(context(), *scene, frame, kBudget, 0, 1);
        const StreamedFrames streamed = render_streaming(context(), *scene, frame, kBudget, 512ull << 10, 8);
        ASSERT_EQ(streamed.image.width, 320);
        ASSERT_EQ(coarse.image.width, 320);
        EXPECT_GE(coarse.stats.shore_stride, 2u);
        EXPECT_EQ(coarse.stats.shore_streamed_tiles, 0u);
        EXPECT_EQ(streamed.stats.shore_stride, coarse.stats.shore_stride);
        EXPECT_GT(streamed.stats.shore_streamed_tiles, 0u);
        EXPECT_LT(streamed.stats.shore_streamed_tiles, streamed.stats.shore_streamable_tiles);
        EXPECT_GT(streamed.frames_streaming, 2u) << "the pool fills over several frames";
        EXPECT_EQ(streamed.stats.shore_streamed_bytes, 0u) << "streaming settles";
        EXPECT_LE(streamed.stats.shore_bytes, kBudget / 2 + (kBudget >> 5));
        const double coarse_diff = test::mean_difference(full, coarse.image);
        const double streamed_diff = test::mean_difference(full, streamed.image);
        std::printf(
            "%s view: coarse level every %u texels, %.4f from the full model; %llu of %llu tiles streamed "
            "over %llu frames, %.4f\n",
            view == render::DebugView::shore ? "shore" : "shaded", coarse.stats.shore_stride, coarse_diff,
            static_cast<unsigned long long>(streamed.stats.shore_streamed_tiles),
            static_cast<unsigned long long>(streamed.stats.shore_streamable_tiles),
            static_cast<unsigned long long>(streamed.frames_streaming), streamed_diff);
        EXPECT_GT(coarse_diff, 0.0);
        EXPECT_LT(streamed_diff, 0.75 * coarse_diff) << "the tiles near the camera are drawn at full resolution";
    }
}

}  // namespace
}  // namespace tidewater
