// Faults from the device: each public call of the renderer, its offscreen target and the
// GPU query is run once per Vulkan call it makes, that call failing (out of host or
// device memory, or the device lost). Each run returns an Error carrying the VkResult,
// nothing crashes, the validation layer stays silent, and after an out-of-memory fault
// the same call succeeds (nothing was left half-made). The sanitizer build runs these
// too, failing every third call (fault_stride, for time): nothing leaks.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "../baked_scene.hpp"
#include "render_helpers.hpp"
#include "tidewater/render/gpu_query.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/scene.hpp"
#include "vk_util.hpp"
#include "vulkan_faults.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

using test::FaultKind;
using test::vulkan_faults;

/// Every how many calls a sweep fails one: TIDEWATER_FAULT_STRIDE, else 3 under
/// AddressSanitizer (lavapipe's runs are slow there) and 1 otherwise.
int fault_stride() {
    if (const char* stride = std::getenv("TIDEWATER_FAULT_STRIDE"); stride && std::atoi(stride) >= 1)
        return std::atoi(stride);
#if defined(__SANITIZE_ADDRESS__)
    return 3;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return 3;
#else
    return 1;
#endif
#else
    return 1;
#endif
}

const std::vector<glm::dvec2>& query_points() {
    static const std::vector<glm::dvec2> points = {{10.0, 20.0}, {-30.0, 5.0}, {300.0, -120.0}};
    return points;
}

class VulkanFaultTest : public test::VulkanTest {
  protected:
    void SetUp() override {
        test::VulkanTest::SetUp();
        auto scene = test::baked(default_scene());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        scene_ = std::move(scene).value();
    }
    void TearDown() override {
        vulkan_faults().disarm();
        test::VulkanTest::TearDown();
    }
    void release() override {
        query_.reset();
        target_.reset();
        renderer_.reset();
    }
    render::DeviceContext faulty_context() const { return test::VulkanFaults::hooked(context()); }

    /// A renderer, an offscreen target and a GPU query, all through the faulty loader,
    /// with the scene set.
    void make_all() {
        release();
        render::RendererInitInfo init;
        init.device = faulty_context();
        init.color_format = render::OffscreenTarget::kColorFormat;
        init.depth_format = render::OffscreenTarget::kDepthFormat;
        init.log = [this](const std::string& m) { log_.push_back(m); };
        auto renderer = render::Renderer::create(init);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        renderer_ = std::move(renderer).value();
        ASSERT_TRUE(renderer_->set_scene(scene_).ok());
        auto target = render::OffscreenTarget::create(faulty_context(), 64, 48);
        ASSERT_TRUE(target.ok()) << target.error().message;
        target_ = std::move(target).value();
        auto query = render::GpuQuery::create(faulty_context());
        ASSERT_TRUE(query.ok()) << query.error().message;
        query_ = std::move(query).value();
    }

    Status render_frame() {
        auto image = target_->render(*renderer_, test::island_frame());
        if (!image) return image.error();
        return {};
    }
    Status query_surface() {
        std::vector<SurfacePoint> out(query_points().size());
        return query_->query_surface(scene_.ocean, 2.0, query_points(), out);
    }
    Status query_world() {
        std::vector<WorldPoint> out(query_points().size());
        return query_->query_world(scene_, 2.0, query_points(), out);
    }

    /// Fails each out-of-memory fault point of `call` in turn. `before` (not failed) puts
    /// the objects in the state each run starts from; `call` runs once without a fault
    /// first, so that the same state is counted and failed. Returns the calls failed.
    int sweep_out_of_memory(
        const char* what, const std::function<Status()>& call, const std::function<void()>& before = [] {}) {
        before();
        EXPECT_TRUE(call().ok()) << what << " without a fault";
        before();
        vulkan_faults().arm(FaultKind::out_of_memory, 0);
        const Status counted = call();
        const int calls = vulkan_faults().calls();
        vulkan_faults().disarm();
        EXPECT_TRUE(counted.ok()) << what << " while counting: " << counted.error().message;
        EXPECT_GT(calls, 0) << what << " makes no Vulkan call that returns a VkResult";
        int failed = 0;
        for (int n = 1; n <= calls; n += fault_stride()) {
            before();
            vulkan_faults().arm(FaultKind::out_of_memory, n);
            const Status st = call();
            const bool tripped = vulkan_faults().tripped();
            const std::string where = vulkan_faults().tripped_in();
            const VkResult fault = vulkan_faults().fault();
            vulkan_faults().disarm();
            if (!tripped) continue;  // this run made fewer calls
            ++failed;
            expect_failed_with(st, fault, what, n, where);
            expect_no_new_messages(what, n, where);
            const Status again = call();
            EXPECT_TRUE(again.ok()) << what << " after call " << n << " (" << where
                                    << ") failed: " << again.error().message;
            expect_no_new_messages(what, n, where);
        }
        EXPECT_GT(failed, calls / (2 * fault_stride())) << what;
        std::printf("[ faults   ] %s: %d of %d calls failed in turn\n", what, failed, calls);
        return failed;
    }

    /// Loses the device at each submission, wait and query read of `call` in turn, on
    /// objects made afresh each time; destroys them with the device still lost.
    int sweep_device_lost(const char* what, const std::function<Status()>& call) {
        make_all();
        EXPECT_TRUE(call().ok()) << what << " without a fault";
        vulkan_faults().arm(FaultKind::device_lost, 0);
        EXPECT_TRUE(call().ok()) << what << " while counting";
        const int calls = vulkan_faults().calls();
        vulkan_faults().disarm();
        int failed = 0;
        for (int n = 1; n <= calls; n += fault_stride()) {
            make_all();
            EXPECT_TRUE(call().ok()) << what << " without a fault";
            vulkan_faults().arm(FaultKind::device_lost, n);
            const Status st = call();
            const std::string where = vulkan_faults().tripped_in();
            if (vulkan_faults().tripped()) {
                ++failed;
                expect_failed_with(st, VK_ERROR_DEVICE_LOST, what, n, where);
            }
            release();  // destroyed on the lost device
            vulkan_faults().disarm();
            expect_no_new_messages(what, n, where);
        }
        std::printf("[ faults   ] %s: the device lost at %d of %d submissions, waits and reads\n", what, failed, calls);
        return failed;
    }

    void expect_failed_with(const Status& st, VkResult fault, const char* what, int n, const std::string& where) {
        ASSERT_FALSE(st.ok()) << what << " succeeded though its call " << n << " (" << where << ") failed";
        EXPECT_EQ(st.error().code, ErrorCode::device_error) << what << ", call " << n << ": " << st.error().message;
        EXPECT_EQ(st.error().vk_result, fault)
            << what << ", call " << n << " (" << where << "): " << st.error().message;
    }
    void expect_no_new_messages(const char* what, int n, const std::string& where) {
        for (const std::string& m : messages_)
            ADD_FAILURE() << what << ", call " << n << " (" << where << ") failed, then: " << m;
        messages_.clear();
    }

    Scene scene_;
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<render::OffscreenTarget> target_;
    std::unique_ptr<render::GpuQuery> query_;
    std::vector<std::string> log_;
};

// Each run starts from the open sea alone, so set_scene uploads the island whole.
TEST_F(VulkanFaultTest, SetSceneFailsCleanlyAtEveryCall) {
    make_all();
    Scene open_sea;
    open_sea.ocean = default_scene().value().ocean;
    open_sea.shore.enabled = false;
    sweep_out_of_memory(
        "set_scene", [&] { return renderer_->set_scene(scene_); },
        [&] {
            const Status st = renderer_->set_scene(open_sea);
            ASSERT_TRUE(st.ok()) << st.error().message;
        });
    EXPECT_TRUE(render_frame().ok()) << "a frame after the faults";
}

TEST_F(VulkanFaultTest, ResizeFailsCleanlyAtEveryCall) {
    make_all();
    int turn = 0;
    sweep_out_of_memory("resize", [&] { return renderer_->resize({++turn % 2 ? 80u : 64u, 48u}); });
}

// A frame in a target of a size the view has not had (the view is resized first, its
// resources made), and a frame like the one before.
TEST_F(VulkanFaultTest, RecordingAndDrawingAFrameFailsCleanlyAtEveryCall) {
    make_all();
    int turn = 0;
    const auto fresh_target = [&] {
        target_.reset();
        auto target = render::OffscreenTarget::create(faulty_context(), ++turn % 2 ? 72u : 64u, 40u);
        ASSERT_TRUE(target.ok()) << target.error().message;
        target_ = std::move(target).value();
    };
    sweep_out_of_memory(
        "OffscreenTarget::render, a new size", [&] { return render_frame(); }, fresh_target);
    sweep_out_of_memory("record_frame (through OffscreenTarget::render)", [&] { return render_frame(); });
}

TEST_F(VulkanFaultTest, ReloadingShadersFailsCleanlyAtEveryCall) {
    make_all();
    sweep_out_of_memory("reload_shaders", [&] { return renderer_->reload_shaders({}); });
    EXPECT_TRUE(render_frame().ok()) << "a frame after the faults";
}

// On a query made afresh each run (its first call makes its buffers), and on one in use.
TEST_F(VulkanFaultTest, GpuQueriesFailCleanlyAtEveryCall) {
    make_all();
    const auto fresh_query = [&] {
        query_.reset();
        auto query = render::GpuQuery::create(faulty_context());
        ASSERT_TRUE(query.ok()) << query.error().message;
        query_ = std::move(query).value();
    };
    sweep_out_of_memory(
        "GpuQuery::query_surface, first", [&] { return query_surface(); }, fresh_query);
    sweep_out_of_memory(
        "GpuQuery::query_world, first", [&] { return query_world(); }, fresh_query);
    sweep_out_of_memory("GpuQuery::query_surface", [&] { return query_surface(); });
    sweep_out_of_memory("GpuQuery::query_world", [&] { return query_world(); });
}

TEST_F(VulkanFaultTest, ALostDeviceAtEverySubmissionWaitAndReadIsReported) {
    EXPECT_GT(sweep_device_lost("set_scene", [&] { return renderer_->set_scene(scene_); }), 0);
    EXPECT_GT(sweep_device_lost("OffscreenTarget::render", [&] { return render_frame(); }), 0);
    EXPECT_GT(sweep_device_lost("GpuQuery::query_surface", [&] { return query_surface(); }), 0);
    EXPECT_GT(sweep_device_lost("GpuQuery::query_world", [&] { return query_world(); }), 0);
}

// Destruction waits for the device; a wait that fails is told to the host's log, and
// every handle is still destroyed (the validation layer reports any left at the
// device's destruction).
TEST_F(VulkanFaultTest, DestructionAfterAFailedWaitReleasesEverything) {
    for (const FaultKind kind : {FaultKind::out_of_memory, FaultKind::device_lost}) {
        make_all();
        ASSERT_TRUE(render_frame().ok());
        log_.clear();
        vulkan_faults().arm(kind, 1);
        renderer_.reset();
        const bool tripped = vulkan_faults().tripped();
        const VkResult fault = vulkan_faults().fault();
        vulkan_faults().disarm();
        ASSERT_TRUE(tripped) << "the renderer's destruction waits for the device";
        bool told = false;
        for (const std::string& m : log_)
            told = told || m.find(render::detail::vk_result_name(fault)) != std::string::npos;
        EXPECT_TRUE(told) << "the failed wait (" << render::detail::vk_result_name(fault) << ") reaches the host's log";
        expect_no_new_messages("~Renderer", 1, "the wait");
    }
}

}  // namespace
}  // namespace tidewater
