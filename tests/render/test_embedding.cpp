// Embedding: a host with its own instance, device, command buffer and render
// target draws something of its own, and Tidewater records into the same pass.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "../baked_scene.hpp"
#include "../core/test_helpers.hpp"
#include "render_helpers.hpp"
#include "test_host.hpp"
#include "tidewater/render/renderer.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

using test::begin_attachments;
using test::begin_commands;
using test::finish_and_read;
using test::renderer_info;
using test::submit_and_wait;
using test::TestHost;

TEST(Embedding, RecordsIntoTheHostsOwnPass) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        render::RendererInitInfo init = renderer_info(host);
        std::vector<std::string> log;
        init.log = [&](const std::string& m) { log.push_back(m); };
        auto renderer = render::Renderer::create(init);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        auto scene = test::baked(default_scene());
        ASSERT_TRUE(scene.ok());
        ASSERT_TRUE((*renderer)->set_scene(*scene).ok());

        VkCommandBuffer cmd = begin_commands(host);
        ASSERT_NE(cmd, VK_NULL_HANDLE);
        render::FrameInfo frame;
        frame.camera.position = scene->camera->position;
        frame.camera.target = scene->camera->target;
        frame.camera.fov_y_deg = scene->camera->fov_y_deg;
        frame.time = 2.0;
        // The sky the water reflects is drawn outside the host's pass, before it.
        const Status unprepared = (*renderer)->record_in_pass(cmd, frame, {TestHost::kWidth, TestHost::kHeight});
        ASSERT_FALSE(unprepared.ok());
        EXPECT_NE(unprepared.error().message.find("record_sky"), std::string::npos) << unprepared.error().message;
        ASSERT_TRUE((*renderer)->record_sky(cmd, frame).ok());
        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = host.color.view;
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.clearValue.color = {{1.0f, 0.0f, 1.0f, 1.0f}};  // magenta: must not survive
        VkRenderingAttachmentInfo depth = color;
        depth.imageView = host.depth.view;
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.clearValue.depthStencil = {0.0f, 0};  // reversed-Z far
        VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
        ri.renderArea = {{0, 0}, {TestHost::kWidth, TestHost::kHeight}};
        ri.layerCount = 1;
        ri.colorAttachmentCount = 1;
        ri.pColorAttachments = &color;
        ri.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &ri);
        // The host's own drawing: a red panel at the nearest depth, top-left.
        VkClearAttachment clears[2] = {{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}}, {VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}}};
        clears[0].clearValue.color = {{1.0f, 0.0f, 0.0f, 1.0f}};
        clears[1].clearValue.depthStencil = {1.0f, 0};
        VkClearRect rect{{{8, 8}, {48, 32}}, 0, 1};
        vkCmdClearAttachments(cmd, 2, clears, 1, &rect);
        ASSERT_TRUE((*renderer)->record_in_pass(cmd, frame, {TestHost::kWidth, TestHost::kHeight}).ok());
        vkCmdEndRendering(cmd);
        const render::RgbaImage img = finish_and_read(host, cmd);

        const test::Rgb panel = test::pixel(img, 20, 20);
        EXPECT_GT(panel.r, 0.99);
        EXPECT_LT(panel.g + panel.b, 0.01) << "the host's panel is kept";
        int magenta = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const test::Rgb c = test::pixel(img, x, y);
                magenta += c.r > 0.95 && c.b > 0.95 && c.g < 0.05;
            }
        EXPECT_EQ(magenta, 0) << "Tidewater covered every pixel the host did not draw";
        const test::Rgb sky = test::block(img, 200, 3, 2);
        EXPECT_GT(sky.b, sky.r) << "sky at the top";
        EXPECT_FALSE(log.empty()) << "the host's log callback hears from the renderer";
        renderer->reset();
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

// The host's explicit calls do the waiting: record_frame refuses targets of a size the
// renderer was not given with resize(), and an unbaked scene with a shore is refused
// rather than drawn as open sea.
TEST(Embedding, FramesNeedAResizeAndScenesABake) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        render::RendererInitInfo init = renderer_info(host);
        auto renderer = render::Renderer::create(init);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        auto parsed = default_scene();
        ASSERT_TRUE(parsed.ok());
        auto unbaked = (*renderer)->set_scene(*parsed);
        ASSERT_FALSE(unbaked.ok());
        EXPECT_NE(unbaked.error().message.find("bake_scene"), std::string::npos) << unbaked.error().message;
        auto scene = test::baked(parsed);
        ASSERT_TRUE(scene.ok());
        ASSERT_TRUE((*renderer)->set_scene(*scene).ok());

        VkCommandBuffer cmd = begin_commands(host);
        ASSERT_NE(cmd, VK_NULL_HANDLE);
        render::FrameTargets targets;
        targets.color_image = host.color.image;
        targets.color_view = host.color.view;
        targets.depth_image = host.depth.image;
        targets.depth_view = host.depth.view;
        targets.extent = {TestHost::kWidth, TestHost::kHeight};
        render::FrameInfo frame;
        frame.camera.position = scene->camera->position;
        frame.camera.target = scene->camera->target;
        frame.time = 1.0;

        // Not sized yet, then sized for another extent: both refused, naming resize().
        auto first = (*renderer)->record_frame(cmd, frame, targets);
        ASSERT_FALSE(first.ok());
        EXPECT_NE(first.error().message.find("resize()"), std::string::npos) << first.error().message;
        vkEndCommandBuffer(cmd);
        ASSERT_TRUE((*renderer)->resize({TestHost::kWidth * 2, TestHost::kHeight}).ok());
        vkResetCommandPool(host.device, host.pool, 0);  // the refused recording is thrown away
        begin_attachments(host, cmd);
        auto other = (*renderer)->record_frame(cmd, frame, targets);
        ASSERT_FALSE(other.ok());
        EXPECT_NE(other.error().message.find("512x144"), std::string::npos) << other.error().message;
        // Sized right, the frame records and the host submits it.
        ASSERT_TRUE((*renderer)->resize(targets.extent).ok());
        auto recorded = (*renderer)->record_frame(cmd, frame, targets);
        ASSERT_TRUE(recorded.ok()) << recorded.error().message;
        vkEndCommandBuffer(cmd);
        ASSERT_TRUE(submit_and_wait(host, cmd));
        vkFreeCommandBuffers(host.device, host.pool, 1, &cmd);
        renderer->reset();
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

/// Records one frame of `scene` with record_frame into the host's targets and reads the
/// colour back as display RGBA8, whatever the target's format.
render::RgbaImage draw_and_read(TestHost& host, render::Renderer& renderer, const Scene& scene) {
    VkCommandBuffer cmd = begin_commands(host);
    render::FrameTargets targets;
    targets.color_image = host.color.image;
    targets.color_view = host.color.view;
    targets.depth_image = host.depth.image;
    targets.depth_view = host.depth.view;
    targets.extent = {TestHost::kWidth, TestHost::kHeight};
    render::FrameInfo frame;
    frame.camera.position = scene.camera->position;
    frame.camera.target = scene.camera->target;
    frame.camera.fov_y_deg = scene.camera->fov_y_deg;
    frame.time = 2.0;
    EXPECT_TRUE(renderer.resize(targets.extent).ok());
    auto recorded = renderer.record_frame(cmd, frame, targets);
    EXPECT_TRUE(recorded.ok()) << recorded.error().message;
    return finish_and_read(host, cmd);
}

// Every format of the table draws the same picture under validation: UNORM targets
// hold the display values, sRGB ones encode the linear values the shaders write for
// them, the float target holds linear values; the depth formats' aspects and layouts
// (D32S8's stencil included) are right.
TEST(Embedding, EveryTargetFormatInTheTableDrawsTheSamePicture) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    render::RgbaImage reference;
    const std::pair<VkFormat, VkFormat> formats[] = {
        {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT},        {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_D32_SFLOAT},
        {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_D32_SFLOAT},         {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_D32_SFLOAT},
        {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT},   {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D16_UNORM},
        {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT_S8_UINT}};
    for (const auto& [color, depth] : formats) {
        TestHost host;
        host.create(color, depth);
        ASSERT_NE(host.device, VK_NULL_HANDLE);
        {
            auto renderer = render::Renderer::create(renderer_info(host));
            ASSERT_TRUE(renderer.ok()) << renderer.error().message;
            ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
            const render::RgbaImage img = draw_and_read(host, **renderer, *scene);
            if (reference.pixels.empty()) {
                reference = img;
            } else {
                const double diff = test::mean_difference(img, reference);
                std::printf("colour %d, depth %d: mean difference %.5f\n", static_cast<int>(color),
                            static_cast<int>(depth), diff);
                EXPECT_LT(diff, 0.01) << "colour format " << color << ", depth format " << depth;
            }
        }
        host.destroy();
        for (const auto& m : host.messages) ADD_FAILURE() << "colour " << color << ", depth " << depth << ": " << m;
    }
}

// The features the host enabled, as DeviceContext says: each missing one is named.
TEST(Embedding, MissingDeviceFeaturesAreNamed) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    const std::pair<const char*, void (*)(render::RendererInitInfo&)> cases[] = {
        {"tessellationShader",
         [](render::RendererInitInfo& i) { i.device.enabled_features.tessellationShader = VK_FALSE; }},
        {"fillModeNonSolid",
         [](render::RendererInitInfo& i) { i.device.enabled_features.fillModeNonSolid = VK_FALSE; }},
        {"dynamicRendering", [](render::RendererInitInfo& i) { i.device.dynamic_rendering = false; }},
    };
    for (const auto& [feature, drop] : cases) {
        render::RendererInitInfo init = renderer_info(host);
        drop(init);
        auto r = render::Renderer::create(init);
        ASSERT_FALSE(r.ok()) << feature;
        EXPECT_EQ(r.error().code, ErrorCode::unsupported);
        EXPECT_NE(r.error().message.find(feature), std::string::npos) << r.error().message;
    }
    // Without fillModeNonSolid the host may leave the wireframe view out.
    render::RendererInitInfo init = renderer_info(host);
    init.device.enabled_features.fillModeNonSolid = VK_FALSE;
    init.wireframe = false;
    auto r = render::Renderer::create(init);
    EXPECT_TRUE(r.ok()) << r.error().message;
    r = Error{};
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

// A volk-style host hands in its own loader: every Vulkan function Tidewater calls comes
// from it. The hook here counts the lookups and wraps vkCmdDrawIndexed (the terrain
// draw) to count the calls that reach it.
PFN_vkCmdDrawIndexed g_real_draw_indexed = nullptr;
int g_hooked_draws = 0, g_device_lookups = 0, g_instance_lookups = 0;
bool g_hide_queue_submit = false;

VKAPI_ATTR void VKAPI_CALL counting_draw_indexed(VkCommandBuffer cmd, std::uint32_t indices, std::uint32_t instances,
                                                 std::uint32_t first, std::int32_t offset,
                                                 std::uint32_t first_instance) {
    ++g_hooked_draws;
    g_real_draw_indexed(cmd, indices, instances, first, offset, first_instance);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL host_device_proc(VkDevice device, const char* name) {
    ++g_device_lookups;
    if (g_hide_queue_submit && std::strcmp(name, "vkQueueSubmit") == 0) return nullptr;
    PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
    if (std::strcmp(name, "vkCmdDrawIndexed") == 0) {
        g_real_draw_indexed = reinterpret_cast<PFN_vkCmdDrawIndexed>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(&counting_draw_indexed);
    }
    return real;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL host_instance_proc(VkInstance instance, const char* name) {
    ++g_instance_lookups;
    return vkGetInstanceProcAddr(instance, name);
}

TEST(Embedding, AHostsOwnLoaderServesEveryVulkanCall) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    {
        render::RendererInitInfo init = renderer_info(host);
        init.device.get_instance_proc_addr = &host_instance_proc;
        init.device.get_device_proc_addr = &host_device_proc;
        g_hide_queue_submit = true;  // a loader without a function Tidewater needs: named
        auto refused = render::Renderer::create(init);
        g_hide_queue_submit = false;
        ASSERT_FALSE(refused.ok());
        EXPECT_NE(refused.error().message.find("vkQueueSubmit"), std::string::npos) << refused.error().message;

        g_hooked_draws = g_device_lookups = g_instance_lookups = 0;
        auto renderer = render::Renderer::create(init);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        EXPECT_GT(g_device_lookups, 50);
        EXPECT_GE(g_instance_lookups, 5);  // the physical-device queries the renderer makes
        ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
        const render::RgbaImage img = draw_and_read(host, **renderer, *scene);
        EXPECT_GE(g_hooked_draws, 1) << "the terrain draw went through the host's loader";
        EXPECT_GT(test::block(img, 200, 3, 2).b, 0.3) << "and the frame was drawn";
        // Half a hook is refused.
        init.device.get_device_proc_addr = nullptr;
        auto half = render::Renderer::create(init);
        ASSERT_FALSE(half.ok());
        EXPECT_NE(half.error().message.find("get_device_proc_addr"), std::string::npos) << half.error().message;
    }
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

TEST(Embedding, FormatsOutsideTheTableAreRefusedByName) {
    TestHost host;
    host.create();
    ASSERT_NE(host.device, VK_NULL_HANDLE);
    render::RendererInitInfo init = renderer_info(host);
    init.color_format = VK_FORMAT_R8G8B8A8_SNORM;
    auto colour = render::Renderer::create(init);
    ASSERT_FALSE(colour.ok());
    EXPECT_EQ(colour.error().code, ErrorCode::unsupported);
    EXPECT_NE(colour.error().message.find("colour format VK_FORMAT_R8G8B8A8_SNORM is not supported"), std::string::npos)
        << colour.error().message;
    EXPECT_NE(colour.error().message.find("VK_FORMAT_R16G16B16A16_SFLOAT"), std::string::npos)
        << "lists the accepted formats";
    init = renderer_info(host);
    init.depth_format = VK_FORMAT_D24_UNORM_S8_UINT;
    auto depth = render::Renderer::create(init);
    ASSERT_FALSE(depth.ok());
    EXPECT_NE(depth.error().message.find("depth format VK_FORMAT_D24_UNORM_S8_UINT is not supported"),
              std::string::npos)
        << depth.error().message;
    host.destroy();
    for (const auto& m : host.messages) ADD_FAILURE() << m;
}

}  // namespace
}  // namespace tidewater
