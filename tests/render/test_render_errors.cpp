// The renderer's refusals on lavapipe under the validation layer: shaders that are not
// SPIR-V, unsupported formats, a missing device, bad frame input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "render_fixture.hpp"
#include "tidewater/render/standalone.hpp"

namespace tidewater {
namespace {

// Hot reload refuses what is not SPIR-V, naming the shader, and the frame still draws.
TEST_F(RenderTest, ReloadingShadersRefusesWhatIsNotSpirv) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene);
    render::FrameInfo frame;
    frame.camera.position = {900.0, 300.0, 500.0};
    frame.camera.target = {120.0, 0.0, 20.0};
    const auto before = render(*scene, frame);
    auto refused = renderer_->reload_shaders({{"water.frag", {1u, 2u, 3u}}});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("water.frag is not SPIR-V"), std::string::npos) << refused.error().message;
    const auto after = render(*scene, frame);
    EXPECT_LT(test::mean_difference(before, after), 1e-9) << "the built-in pipelines keep drawing";
}

TEST_F(RenderTest, UnsupportedFormatAndMissingDeviceAreNamed) {
    render::RendererInitInfo init;
    init.device = context();
    init.color_format = VK_FORMAT_R64G64B64A64_SFLOAT;
    auto r = render::Renderer::create(init);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::unsupported);
    EXPECT_NE(r.error().message.find("colour format"), std::string::npos) << r.error().message;
    render::StandaloneOptions options;
    options.device_name_contains = "NoSuchGPU";
    auto none = render::StandaloneDevice::create(options);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::no_device);
    EXPECT_NE(none.error().message.find(device_->device_name()), std::string::npos)
        << "lists what was found (" << device_->device_name() << "): " << none.error().message;
    EXPECT_NE(none.error().message.find("NoSuchGPU"), std::string::npos);
}

TEST_F(RenderTest, BadFrameInputIsAnError) {
    const Scene scene =
        scene_from(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}}, "ocean": "pool_calm"})");
    ASSERT_TRUE(renderer_->set_scene(scene).ok());
    auto t = render::OffscreenTarget::create(context(), 64, 64);
    ASSERT_TRUE(t.ok());
    target_ = std::move(t).value();
    render::FrameInfo frame;
    frame.time = std::nan("");
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    frame.time = 0.0;
    frame.camera.target = frame.camera.position;
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    frame.camera = render::Camera{};
    frame.camera.fov_y_deg = 0.0;
    EXPECT_FALSE(target_->render(*renderer_, frame).ok());
    EXPECT_FALSE(render::OffscreenTarget::create(context(), 0, 64).ok());
    EXPECT_FALSE(render::OffscreenTarget::create(context(), 100000, 64).ok());
}

}  // namespace
}  // namespace tidewater
