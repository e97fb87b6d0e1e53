// Over the memory budget the shore fields are drawn from a coarse level, and the
// full-resolution tiles nearest the camera stream in as frames are recorded: the picture
// converges on the one drawn with the whole model resident, without a validation message.
#include <cstdio>
#include <filesystem>
#include <string>

#include "render_fixture.hpp"
#include "saved_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"

namespace tidewater {
namespace {

using test::kept_slots;
using test::save_default_bake;

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

/// The slots of `named`'s saved bake that a CPU query of the camera's submersion reads and
/// keeps (the renderer asks it each frame): all a renderer drawing that bake may keep.
std::size_t camera_query_slots(const Scene& named, const render::FrameInfo& frame) {
    auto probe = bake_scene(named);
    if (!probe.ok()) {
        ADD_FAILURE() << probe.error().message;
        return 0;
    }
    Submersion s;
    const glm::dvec3 eye = frame.camera.position;
    EXPECT_TRUE(
        query_submersion(**probe, frame.time, std::span<const glm::dvec3>(&eye, 1), std::span<Submersion>(&s, 1)).ok());
    return kept_slots(*(*probe)->bake->ocean_shore);
}

// Over the budget a saved bake is not read whole: the coarse level reads each tile once
// without keeping it, and the tiles near the camera stream from the bake folder on the
// renderer's reader thread, drawn a frame or more after they are asked for and kept in
// host memory by nothing (but the tiles under the camera, which its submersion query reads). The picture settles on the
// one streamed from the bake in memory.
TEST_F(RenderTest, ShoreTilesOfASavedBakeStreamFromItsFolder) {
    namespace fs = std::filesystem;
    const auto saved = save_default_bake("tidewater_stream");
    ASSERT_TRUE(saved);
    const Scene* scene = &saved->baked;
    const Scene* named = &saved->named;
    const fs::path& dir = saved->dir;
    auto loaded = bake_scene(*named);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const ShoreWaves& model = *(*loaded)->bake->ocean_shore;
    ASSERT_NE(model.shared().lazy, nullptr) << "a saved bake's tiles are read on demand";

    render::FrameInfo frame = test::scene_camera_frame(*scene, 3.0);
    frame.view = render::DebugView::shore;
    constexpr std::uint64_t kBudget = 16ull << 20, kPerFrame = 512ull << 10;
    const StreamedFrames in_memory = render_streaming(context(), *scene, frame, kBudget, kPerFrame, 8);
    const StreamedFrames coarse = render_streaming(context(), **loaded, frame, kBudget, 0, 1);
    // The camera's submersion query keeps the few tiles under the camera, as any CPU query
    // keeps what it reads; nothing else is kept.
    const std::size_t camera_slots = camera_query_slots(*named, frame);
    EXPECT_LE(camera_slots, 4u * (1u + model.layers().size()));
    EXPECT_EQ(kept_slots(model), camera_slots) << "the coarse level keeps no tile it read";

    auto renderer = test::renderer_within_budget(context(), **loaded, kBudget, kPerFrame);
    ASSERT_NE(renderer, nullptr);
    auto target = render::OffscreenTarget::create(context(), 320, 180);
    ASSERT_TRUE(target.ok());
    render::RgbaImage image;
    render::RendererStats stats;
    int frames = 0, frames_reading = 0;
    for (; frames < 40; ++frames) {
        frame.frame_index = static_cast<std::uint64_t>(frames);
        auto img = (*target)->render(*renderer, frame);
        ASSERT_TRUE(img.ok()) << img.error().message;
        image = std::move(img).value();
        stats = renderer->stats();
        frames_reading += stats.shore_tiles_reading > 0 ? 1 : 0;
        if (frames >= 2 && stats.shore_streamed_bytes == 0 && stats.shore_tiles_reading == 0) break;
    }
    const double coarse_diff = test::mean_difference(in_memory.image, coarse.image);
    const double streamed_diff = test::mean_difference(in_memory.image, image);
    std::printf(
        "from the folder: %llu of %llu tiles streamed in %d frames (%d with reads in flight), %.5f from the bake in "
        "memory streamed alike, %.5f coarse; %zu slots kept\n",
        static_cast<unsigned long long>(stats.shore_streamed_tiles),
        static_cast<unsigned long long>(stats.shore_streamable_tiles), frames + 1, frames_reading, streamed_diff,
        coarse_diff, kept_slots(model));
    EXPECT_GT(frames_reading, 0) << "the tiles were read from the folder";
    EXPECT_EQ(stats.shore_tiles_reading, 0u) << "streaming settles";
    EXPECT_EQ(stats.shore_streamed_tiles, in_memory.stats.shore_streamed_tiles);
    EXPECT_EQ(kept_slots(model), camera_slots) << "no streamed tile is kept in host memory";
    EXPECT_GT(coarse_diff, 0.0);
    EXPECT_LT(streamed_diff, 0.25 * coarse_diff) << "the same tiles as the bake in memory, within its 16-bit encoding";
    renderer.reset();

    // Within the budget every tile is read as it is packed, and not kept either.
    auto whole = bake_scene(*named);
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    const StreamedFrames resident = render_streaming(context(), **whole, frame, 1ull << 30, kPerFrame, 1);
    EXPECT_EQ(resident.stats.shore_stride, 1u);
    EXPECT_LE(kept_slots(*(*whole)->bake->ocean_shore), camera_slots) << "the device's copy is the only one";
    fs::remove_all(dir);
}

// A tile file gone from the folder since the load fails set_scene, within the budget and
// over it, with the file's name, before anything drawn is replaced.
TEST_F(RenderTest, AShoreTileGoneFromItsFolderFailsTheUploadByName) {
    namespace fs = std::filesystem;
    const auto saved = save_default_bake("tidewater_tile_gone");
    ASSERT_TRUE(saved);
    const Scene* scene = &saved->baked;
    const Scene* named = &saved->named;
    const fs::path& dir = saved->dir;
    fs::path tile;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.path().extension() == ".png" && entry.path().parent_path().parent_path().filename() == "tiles")
            tile = entry.path();
    ASSERT_FALSE(tile.empty()) << "a stored tile's file";
    for (const std::uint64_t budget : {1ull << 30, 16ull << 20}) {
        auto loaded = bake_scene(*named);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        fs::rename(tile, tile.string() + ".gone");
        auto renderer = test::renderer_within_budget(context(), *scene, budget);
        ASSERT_NE(renderer, nullptr);
        const Status st = renderer->set_scene(**loaded);
        ASSERT_FALSE(st.ok()) << "budget " << budget;
        EXPECT_NE(st.error().message.find(tile.filename().string()), std::string::npos) << st.error().message;
        fs::rename(tile.string() + ".gone", tile);
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace tidewater
