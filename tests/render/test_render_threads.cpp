// The renderer beside other threads, as its API allows them (renderer.hpp, gpu_query.hpp,
// device_context.hpp): a re-bake on a worker swapped in between frames; CPU queries on
// another thread of the very scene whose saved bake the renderer streams from its folder
// on its reader thread; GPU queries on one thread while another records frames on a
// host's own device, the queue used by one at a time. Each answer is the one given alone.
// Built also under ThreadSanitizer (TIDEWATER_SANITIZE=thread, ctest -L threads).
#include <atomic>
#include <cstdio>
#include <cstring>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

#include "render_fixture.hpp"
#include "saved_bake.hpp"
#include "test_host.hpp"
#include "tidewater/render/gpu_query.hpp"

namespace tidewater {
namespace {

class RenderThreads : public RenderTest {};

/// Points over the default island's coast and the sea around it, 75 m apart.
std::vector<glm::dvec2> coast_points() {
    std::vector<glm::dvec2> points;
    for (double x = -900.0; x <= 900.0; x += 75.0)
        for (double z = -900.0; z <= 900.0; z += 75.0) points.push_back({x, z});
    return points;
}

/// Whether two answers are the same bit for bit.
bool same(const WorldPoint& a, const WorldPoint& b) {
    const SurfacePoint &s = a.surface, &t = b.surface;
    const auto eq = [](const auto& u, const auto& v) { return std::memcmp(&u, &v, sizeof(u)) == 0; };
    return eq(s.height, t.height) && eq(s.normal, t.normal) && eq(s.displacement, t.displacement) &&
           eq(s.velocity, t.velocity) && eq(s.jacobian, t.jacobian) && eq(s.depth, t.depth) &&
           eq(s.shore_distance, t.shore_distance) && s.wet == t.wet && eq(s.foam, t.foam) && a.body == b.body &&
           eq(a.flow, b.flow);
}

/// Ends the other thread's loop when the test leaves its scope, by an assertion too: it is
/// declared after the future that waits for that thread, so it is destroyed first.
struct StopWhenLeaving {
    std::atomic<bool>& running;
    ~StopWhenLeaving() { running = false; }
};

std::size_t differing(const std::vector<WorldPoint>& a, const std::vector<WorldPoint>& b) {
    std::size_t n = a.size() == b.size() ? 0 : std::max(a.size(), b.size());
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += same(a[i], b[i]) ? 0 : 1;
    return n;
}

// An editor's terrain edit: a worker thread re-bakes while the last good scene keeps
// drawing, and the new one is swapped in between frames.
TEST_F(RenderThreads, AReBakeOnAWorkerThreadIsSwappedInBetweenFrames) {
    auto first = test::baked(default_scene());
    ASSERT_TRUE(first);
    auto current = std::make_shared<const Scene>(*first);
    ASSERT_TRUE(renderer_->set_scene(*current).ok());
    // The edit: a knoll 30 m high raised in the open sea in front of the camera.
    Scene edited = *current;
    auto island = std::get<IslandTerrain>(edited.terrain.shape());
    island.knolls.push_back({{640.0, 330.0}, 120.0, 30.0});
    edited.terrain = Terrain(island);
    render::FrameInfo frame;
    frame.camera.position = {900.0, 300.0, 500.0};
    frame.camera.target = {120.0, 0.0, 20.0};
    const auto before = render(*current, frame);
    SceneBakeOptions options;
    options.previous = current;
    std::atomic<bool> finished{false};
    auto job = std::async(std::launch::async, [&] {
        auto baked = bake_scene(edited, options);
        finished = true;
        return baked;
    });
    int frames_while_baking = 0;
    while (!finished) {  // the last good scene keeps drawing
        auto img = target_->render(*renderer_, frame);
        ASSERT_TRUE(img.ok()) << img.error().message;
        ++frames_while_baking;
    }
    auto rebaked = job.get();
    ASSERT_TRUE(rebaked) << rebaked.error().message;
    EXPECT_EQ((*rebaked)->bake->reused.rivers, current->rivers.size()) << "the brook and rill are not in the edit";
    ASSERT_TRUE(renderer_->set_scene(**rebaked).ok());  // between frames
    const auto after = render(**rebaked, frame);
    std::printf("%d frame(s) drawn while the worker re-baked in %.2f s\n", frames_while_baking,
                (*rebaked)->bake->seconds);
    EXPECT_GT(test::mean_difference(before, after), 0.01) << "the new knoll is drawn";
}

// A saved bake loads lazily: its tiles are read when first asked for, by whoever asks.
// Here the renderer's reader thread streams them for the frames (over a 16 MiB budget)
// while another thread queries the same scene over the coast at three times, again and
// again. The queries answer as they do alone, on a scene loaded afresh.
TEST_F(RenderThreads, CpuQueriesOfTheSceneWhoseSavedBakeTheRendererStreams) {
    const auto saved = test::save_default_bake("tidewater_threads_stream");
    ASSERT_TRUE(saved);
    auto drawn = bake_scene(saved->named);
    ASSERT_TRUE(drawn.ok()) << drawn.error().message;
    ASSERT_NE((*drawn)->bake->ocean_shore->shared().lazy, nullptr) << "a saved bake's tiles are read on demand";
    auto renderer = test::renderer_within_budget(context(), **drawn, 16ull << 20, 512ull << 10);
    ASSERT_NE(renderer, nullptr);
    auto target = render::OffscreenTarget::create(context(), 320, 180);
    ASSERT_TRUE(target.ok()) << target.error().message;

    const std::vector<glm::dvec2> points = coast_points();
    const double times[3] = {1.0, 2.5, 4.0};
    std::vector<std::vector<WorldPoint>> asked(3, std::vector<WorldPoint>(points.size()));
    std::atomic<bool> drawing{true};
    auto asking = std::async(std::launch::async, [&] {
        int rounds = 0;
        do {
            for (int k = 0; k < 3; ++k)
                if (!query_world(**drawn, times[k], points, asked[static_cast<std::size_t>(k)]).ok()) return -1;
            ++rounds;
        } while (drawing);
        return rounds;
    });
    const StopWhenLeaving stop{drawing};
    render::FrameInfo frame = test::scene_camera_frame(**drawn, 3.0);
    int frames = 0, frames_reading = 0;
    for (; frames < 24; ++frames) {
        frame.frame_index = static_cast<std::uint64_t>(frames);
        frame.time = 3.0 + frames / 60.0;
        auto img = (*target)->render(*renderer, frame);
        ASSERT_TRUE(img.ok()) << img.error().message;
        frames_reading += renderer->stats().shore_tiles_reading > 0 ? 1 : 0;
    }
    drawing = false;
    const int rounds = asking.get();
    const render::RendererStats stats = renderer->stats();
    renderer.reset();

    auto alone = bake_scene(saved->named);
    ASSERT_TRUE(alone.ok()) << alone.error().message;
    std::size_t differ = 0;
    for (int k = 0; k < 3; ++k) {
        std::vector<WorldPoint> answer(points.size());
        ASSERT_TRUE(query_world(**alone, times[k], points, answer).ok());
        differ += differing(asked[static_cast<std::size_t>(k)], answer);
    }
    std::printf("%d rounds of %zu queries beside %d frames (%d reading tiles, %llu tiles streamed)\n", rounds,
                3 * points.size(), frames, frames_reading, static_cast<unsigned long long>(stats.shore_streamed_tiles));
    EXPECT_GT(rounds, 0) << "the queries ran";
    EXPECT_GT(frames_reading, 0) << "the reader thread read tiles while the queries ran";
    EXPECT_EQ(differ, 0u) << "answers beside the renderer differ from those alone";
    std::filesystem::remove_all(saved->dir);
}

// GPU queries on one thread while another records frames, on a host's own device: a
// recording never submits or waits (device_context.hpp), so it overlaps the queries; the
// frame's submission and each query take the host's lock of the queue. Tidewater shares no
// other state between them: the queries and the frames are those given alone.
TEST(RenderThreadsOnAHost, GpuQueriesOnOneThreadWhileAnotherRecordsFrames) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    test::TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        auto renderer = render::Renderer::create(test::renderer_info(host));
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
        render::FrameTargets targets;
        targets.color_image = host.color.image;
        targets.color_view = host.color.view;
        targets.depth_image = host.depth.image;
        targets.depth_view = host.depth.view;
        targets.extent = {test::TestHost::kWidth, test::TestHost::kHeight};
        ASSERT_TRUE((*renderer)->resize(targets.extent).ok());
        auto query = render::GpuQuery::create(host.context());
        ASSERT_TRUE(query.ok()) << query.error().message;
        const std::vector<glm::dvec2> points = coast_points();
        const render::FrameInfo frame = test::scene_camera_frame(*scene, 3.0);

        std::vector<WorldPoint> alone(points.size());
        ASSERT_TRUE((*query)->query_world(*scene, 2.0, points, alone).ok());
        VkCommandBuffer cmd = test::begin_commands(host);
        ASSERT_TRUE((*renderer)->record_frame(cmd, frame, targets).ok());
        const render::RgbaImage alone_frame = test::finish_and_read(host, cmd);

        std::mutex queue;  // the host's: one user of the queue at a time
        std::atomic<bool> drawing{true};
        std::atomic<int> rounds_done{0};
        auto asking = std::async(std::launch::async, [&] {
            std::size_t differ = 0;
            std::vector<WorldPoint> answer(points.size());
            do {
                {
                    const std::lock_guard<std::mutex> hold(queue);
                    if (!(*query)->query_world(*scene, 2.0, points, answer).ok()) return std::size_t{1} << 40;
                }
                differ += differing(answer, alone);
                ++rounds_done;
                std::this_thread::yield();
            } while (drawing);
            return differ;
        });
        const StopWhenLeaving stop{drawing};
        render::RgbaImage last;
        int frames = 0;
        // At least 12 frames, and on until the queries have run beside them three times.
        for (; frames < 12 || (rounds_done < 3 && frames < 200); ++frames) {
            cmd = test::begin_commands(host);
            ASSERT_NE(cmd, VK_NULL_HANDLE);
            ASSERT_TRUE((*renderer)->record_frame(cmd, frame, targets).ok());  // beside a query
            const std::lock_guard<std::mutex> hold(queue);
            last = test::finish_and_read(host, cmd);
        }
        drawing = false;
        const std::size_t differ = asking.get();
        std::printf("%d rounds of %zu GPU queries beside %d frames recorded\n", rounds_done.load(), points.size(),
                    frames);
        EXPECT_GE(rounds_done, 3) << "the queries ran beside the frames";
        EXPECT_EQ(differ, 0u) << "GPU answers beside the frames differ from those alone";
        EXPECT_EQ(last.pixels, alone_frame.pixels) << "the frame beside the queries differs from the one alone";
        query->reset();
        renderer->reset();
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

}  // namespace
}  // namespace tidewater

#ifdef TIDEWATER_THREAD_SANITIZER
// ThreadSanitizer's suppressions for this executable. Lavapipe and the validation layer
// are not instrumented: their threads order the lifetimes of their own objects by futexes
// and atomics it cannot see, so it reports their mutexes and blocks destroyed "in a race"
// and a lock order of the layer's. Each names a library: a report is left out when a frame
// of that library is in it, and every race between Tidewater's own accesses is still
// reported.
extern "C" const char* __tsan_default_suppressions() {
    return "race:libvulkan_lvp.so\n"
           "race:libVkLayer_khronos_validation.so\n"
           "deadlock:libVkLayer_khronos_validation.so\n";
}
#endif
