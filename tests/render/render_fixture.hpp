// The render tests' fixture: a validated standalone device (vulkan_fixture.hpp), a
// renderer and an offscreen target, and what a pixel is (sky, water, land).
// TIDEWATER_TEST_IMAGE_DIR keeps every frame a test renders, for looking at failures.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "../baked_scene.hpp"
#include "render_helpers.hpp"
#include "tidewater/detail/image_write.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/tidewater.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater::test {

class RenderTest : public test::VulkanTest {
  protected:
    void SetUp() override {
        VulkanTest::SetUp();
        if (HasFatalFailure()) return;  // no device: the test body is skipped, not run on null
        render::RendererInitInfo init;
        init.device = context();
        init.color_format = render::OffscreenTarget::kColorFormat;
        init.depth_format = render::OffscreenTarget::kDepthFormat;
        init.wireframe = init.device.enabled_features.fillModeNonSolid;
        auto r = render::Renderer::create(init);
        ASSERT_TRUE(r.ok()) << r.error().message;
        renderer_ = std::move(r).value();
    }
    void release() override {
        target_.reset();
        renderer_.reset();
    }
    render::RgbaImage render(const Scene& scene, const render::FrameInfo& frame, std::uint32_t w = 320,
                             std::uint32_t h = 180) {
        EXPECT_TRUE(renderer_->set_scene(scene).ok());
        if (!target_ || width_ != w || height_ != h) {
            auto t = render::OffscreenTarget::create(context(), w, h);
            EXPECT_TRUE(t.ok()) << t.error().message;
            target_ = std::move(t).value();
            width_ = w;
            height_ = h;
        }
        auto img = target_->render(*renderer_, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        // TIDEWATER_TEST_IMAGE_DIR keeps every frame a test renders, for looking at failures.
        if (const char* dir = std::getenv("TIDEWATER_TEST_IMAGE_DIR"); dir && img.ok()) {
            const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
            const auto path =
                std::filesystem::path(dir) / (std::string(info->name()) + "_" + std::to_string(dumped_++) + ".png");
            EXPECT_TRUE(detail::write_png_rgba8(path, img->width, img->height, img->pixels).ok());
        }
        return img.ok() ? std::move(img).value() : render::RgbaImage{};
    }
    static Scene scene_from(const std::string& json) {
        auto s = test::baked(parse_scene(json, "test scene"));
        EXPECT_TRUE(s.ok()) << s.error().message;
        return s.ok() ? std::move(s).value() : Scene{};
    }
    /// A frame through a renderer and target of their own at `samples` per pixel, the
    /// water shaded at every sample when `water_per_sample`.
    render::RgbaImage render_multisampled(const Scene& scene, const render::FrameInfo& frame, std::uint32_t w,
                                          std::uint32_t h, VkSampleCountFlagBits samples,
                                          bool water_per_sample = false) {
        render::RendererInitInfo init;
        init.device = context();
        init.samples = samples;
        init.shade_water_per_sample = water_per_sample;
        init.wireframe = false;
        auto r = render::Renderer::create(init);
        EXPECT_TRUE(r.ok()) << r.error().message;
        if (!r.ok()) return {};
        EXPECT_TRUE((*r)->set_scene(scene).ok());
        auto t = render::OffscreenTarget::create(context(), w, h, samples);
        EXPECT_TRUE(t.ok()) << t.error().message;
        if (!t.ok()) return {};
        auto img = (*t)->render(**r, frame);
        EXPECT_TRUE(img.ok()) << img.error().message;
        if (const char* dir = std::getenv("TIDEWATER_TEST_IMAGE_DIR"); dir && img.ok()) {
            const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
            const auto path = std::filesystem::path(dir) /
                              (std::string(info->name()) + "_" + std::to_string(dumped_++) + "_msaa.png");
            EXPECT_TRUE(detail::write_png_rgba8(path, img->width, img->height, img->pixels).ok());
        }
        return img.ok() ? std::move(img).value() : render::RgbaImage{};
    }
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<render::OffscreenTarget> target_;
    std::uint32_t width_ = 0, height_ = 0;
    int dumped_ = 0;
};

/// A frame seen from `scene`'s own camera at `time`.
inline render::FrameInfo scene_camera_frame(const Scene& scene, double time = 0.0) {
    render::FrameInfo frame;
    if (scene.camera) {
        frame.camera.position = scene.camera->position;
        frame.camera.target = scene.camera->target;
        frame.camera.fov_y_deg = scene.camera->fov_y_deg;
    }
    frame.time = time;
    return frame;
}

/// A renderer of its own on `device` for the offscreen target's formats, made from the
/// init info `adjust` changes, with `scene` set; null (and the test failed) when it cannot
/// be made.
template <class Adjust>
std::unique_ptr<render::Renderer> renderer_with(const render::DeviceContext& device, const Scene& scene,
                                                Adjust&& adjust) {
    render::RendererInitInfo init;
    init.device = device;
    init.color_format = render::OffscreenTarget::kColorFormat;
    init.depth_format = render::OffscreenTarget::kDepthFormat;
    init.wireframe = false;
    adjust(init);
    auto renderer = render::Renderer::create(init);
    EXPECT_TRUE(renderer.ok()) << renderer.error().message;
    if (!renderer.ok()) return nullptr;
    const Status set = (*renderer)->set_scene(scene);
    EXPECT_TRUE(set.ok()) << set.error().message;
    return set.ok() ? std::move(renderer).value() : nullptr;
}

/// A renderer of its own whose memory budget is `budget` bytes and that streams at most
/// `stream_per_frame` bytes of shore tiles a frame (renderer_with).
inline std::unique_ptr<render::Renderer> renderer_within_budget(
    const render::DeviceContext& device, const Scene& scene, std::uint64_t budget,
    std::uint64_t stream_per_frame = render::RendererInitInfo{}.shore_stream_bytes_per_frame) {
    return renderer_with(device, scene, [&](render::RendererInitInfo& init) {
        init.gpu_memory_budget = budget;
        init.shore_stream_bytes_per_frame = stream_per_frame;
    });
}

inline bool is_sky(Rgb c) {
    return c.b > c.r + 0.1 && c.b > 0.45;
}
inline bool is_water(Rgb c) {
    return c.b > c.r && c.g > c.r;
}
inline bool is_land(Rgb c) {
    return c.g > c.b && c.r > 0.08;
}  // grass, sand and rock have more green than blue

}  // namespace tidewater::test

namespace tidewater {
// The render tests name these unqualified.
using test::is_land;
using test::is_sky;
using test::is_water;
using test::RenderTest;
using test::Rgb;
}  // namespace tidewater
