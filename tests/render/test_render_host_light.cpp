// The host's own geometry under the water (FrameInfo::light_host_geometry): a plate the
// host draws into its targets before the frame, 6 m under a sea of one 4 m sine wave with
// the sun overhead, seen from just under the surface. Its light is focused by the waves
// over it as the surface's curvature says (the caustics the seabed gets), and without the
// pass it is left exactly as the host drew it. Under the validation layer (synchronisation
// validation included): any message fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "../baked_scene.hpp"
#include "host_device.h"
#include "render_helpers.hpp"
#include "test_host.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/tidewater.hpp"

namespace tidewater {
namespace {

using test::TestHost;

constexpr double kPlateAlongView = 5.5;  // m from the eye along its axis
constexpr double kNear = 0.3;            // the camera's near plane (m)

render::FrameInfo under_the_sea() {
    render::FrameInfo frame;
    frame.camera.position = {0.0, -0.5, 0.0};
    frame.camera.target = {0.0, -6.0, 1.0};
    frame.camera.fov_y_deg = 60.0;
    frame.camera.near_plane = kNear;
    frame.sun_direction = {0.0, 1.0, 0.0};
    frame.time = 1.3;
    return frame;
}

/// The host's frame: its plate (a clear of colour to grey and of depth to the plane
/// kPlateAlongView m down the view's axis, reversed-Z's near / distance), then Tidewater's
/// frame over it.
render::RgbaImage draw(TestHost& host, render::Renderer& renderer, const render::FrameInfo& frame) {
    VkCommandBuffer cmd = test::begin_commands(host);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = host.color.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.5f, 0.5f, 0.5f, 1.0f}};
    VkRenderingAttachmentInfo depth = color;
    depth.imageView = host.depth.view;
    depth.imageLayout = host.depth_layout();
    depth.clearValue.depthStencil = {static_cast<float>(kNear / kPlateAlongView), 0};
    VkRenderingInfo pass{VK_STRUCTURE_TYPE_RENDERING_INFO};
    pass.renderArea = {{0, 0}, {TestHost::kWidth, TestHost::kHeight}};
    pass.layerCount = 1;
    pass.colorAttachmentCount = 1;
    pass.pColorAttachments = &color;
    pass.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &pass);
    vkCmdEndRendering(cmd);
    test::barrier(cmd, host.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    test::barrier(cmd, host.depth.image, host.depth_aspects(), host.depth_layout(), host.depth_layout());
    render::FrameTargets t;
    t.color_image = host.color.image;
    t.color_view = host.color.view;
    t.depth_image = host.depth.image;
    t.depth_view = host.depth.view;
    t.extent = {TestHost::kWidth, TestHost::kHeight};
    t.clear = false;
    t.resolve_image = host.resolved.image;
    t.resolve_view = host.resolved.view;
    const Status st = renderer.record_frame(cmd, frame, t);
    EXPECT_TRUE(st.ok()) << st.error().message;
    return test::finish_and_read(host, cmd);
}

TEST(HostGeometry, CausticsFocusTheSunOnTheHostsPlateAsTheSurfacesCurvatureSays) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        auto scene = test::baked(parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}},
            "ocean": {"waves": [{"direction": 0, "wavelength": 4, "amplitude": 0.08, "steepness": 0}]}})",
                                             "plate.json"));
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        auto renderer_with_caustics = [&](bool caustics) {
            render::RendererInitInfo init = test::renderer_info(host);
            init.quality_overrides.caustics = caustics;
            auto r = render::Renderer::create(init);
            EXPECT_TRUE(r.ok()) << r.error().message;
            EXPECT_TRUE((*r)->set_scene(*scene).ok());
            EXPECT_TRUE((*r)->resize({TestHost::kWidth, TestHost::kHeight}).ok());
            return std::move(r).value();
        };
        render::FrameInfo frame = under_the_sea();
        auto focused = renderer_with_caustics(true);
        auto plain = renderer_with_caustics(false);
        const render::RgbaImage with = draw(host, *focused, frame);
        const render::RgbaImage without = draw(host, *plain, frame);
        frame.light_host_geometry = false;
        const render::RgbaImage unlit_with = draw(host, *focused, frame);
        const render::RgbaImage unlit_without = draw(host, *plain, frame);

        // The plate's point under each pixel: on the plane kPlateAlongView down the axis.
        const glm::dvec3 eye = frame.camera.position;
        const glm::dvec3 axis = glm::normalize(frame.camera.target - eye);
        const WaterOptics optics = optics_of(*scene, BodyRef{BodyKind::ocean, -1});
        const int w = TestHost::kWidth, h = TestHost::kHeight;
        constexpr double kBin = 0.1;
        std::map<int, std::pair<double, int>> bins;
        double unlit_change = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                unlit_change = std::max(unlit_change,
                                        std::abs(test::pixel(unlit_with, x, y).g - test::pixel(unlit_without, x, y).g));
                const glm::dvec3 d = test::pixel_ray(frame.camera, w, h, x, y);
                const glm::dvec3 p = eye + d * (kPlateAlongView / glm::dot(d, axis));
                if (std::abs(p.z) > 0.6) continue;
                const double path = glm::length(p - eye);
                const double change = test::pixel(with, x, y).g - test::pixel(without, x, y).g;
                auto& bin = bins[static_cast<int>(std::floor(p.x / kBin))];
                bin.first += change / std::exp(-optics.extinction.g * path);
                ++bin.second;
            }
        // Against the first-order gain 1 / (1 - D k^2 eta) - 1, D = h (1 - 1/n), one scale.
        const double plate_depth = -(eye + axis * kPlateAlongView / glm::dot(axis, axis)).y;
        const double depth_factor = plate_depth * (1.0 - 1.0 / gpu::kWaterRefractiveIndex);
        const double k = 2.0 * kPi / 4.0;
        std::vector<double> measured, theory;
        for (const auto& [i, sum] : bins) {
            if (sum.second < 3) continue;
            const double x = (i + 0.5) * kBin;
            const double eta = query_world_point(*scene, frame.time, {x, 0.0}).surface.height;
            measured.push_back(sum.first / sum.second);
            theory.push_back(1.0 / (1.0 - depth_factor * k * k * eta) - 1.0);
        }
        ASSERT_GT(measured.size(), 40u);
        const auto [scale, r2] = test::fit_one_scale(measured, theory);
        std::printf(
            "host plate %.2f m down: %zu bins over %.1f m, the gain's swing %.2f to %.2f in theory, fit R^2 %.3f "
            "(scale %.3f); without the pass the caustics change no pixel by more than %.4f\n",
            plate_depth, measured.size(), static_cast<double>(measured.size()) * kBin,
            1.0 + *std::min_element(theory.begin(), theory.end()),
            1.0 + *std::max_element(theory.begin(), theory.end()), r2, scale, unlit_change);
        EXPECT_GT(scale, 0.0);
        EXPECT_GT(r2, 0.9);
        EXPECT_EQ(unlit_change, 0.0) << "left as the host drew it, the plate shows no caustics";
        // Lit under 6 m of water the plate is darker than the host drew it (the light lost on
        // the way down), and seen through the water from the eye in both.
        const glm::ivec2 middle(w / 2, h / 2);
        EXPECT_LT(test::pixel(without, middle.x, middle.y).g, test::pixel(unlit_without, middle.x, middle.y).g);
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

// Multisampled targets (4 samples): the host's depth is resolved for the pass by a pass
// that draws nothing, and the plate is lit under the water as with one sample.
TEST(HostGeometry, AMultisampledHostsPlateIsLitUnderTheWaterToo) {
    TestHost host;
    host.create(VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_4_BIT);
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        auto scene = test::baked(parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -30}},
            "ocean": {"waves": [{"direction": 0, "wavelength": 4, "amplitude": 0.08, "steepness": 0}]}})",
                                             "plate.json"));
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        auto renderer = render::Renderer::create(test::renderer_info(host));
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
        ASSERT_TRUE((*renderer)->resize({TestHost::kWidth, TestHost::kHeight}).ok());
        render::FrameInfo frame = under_the_sea();
        const render::RgbaImage lit = draw(host, **renderer, frame);
        frame.light_host_geometry = false;
        const render::RgbaImage unlit = draw(host, **renderer, frame);
        // Along the middle row: the lit plate's green swings with the caustics, the unlit one's not.
        auto swing = [&](const render::RgbaImage& img) {
            double lo = 1.0, hi = 0.0;
            for (int x = 8; x < static_cast<int>(TestHost::kWidth) - 8; ++x) {
                lo = std::min(lo, test::pixel(img, x, TestHost::kHeight / 2).g);
                hi = std::max(hi, test::pixel(img, x, TestHost::kHeight / 2).g);
            }
            return hi - lo;
        };
        std::printf("4 samples: the plate's green swings %.3f lit under the water, %.3f left as drawn\n", swing(lit),
                    swing(unlit));
        EXPECT_GT(swing(lit), 4.0 * swing(unlit) + 0.01);
        renderer->reset();
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

}  // namespace
}  // namespace tidewater
