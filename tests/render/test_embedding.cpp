// Embedding: a host with its own instance, device, command buffer and render
// target draws something of its own, and Tidewater records into the same pass.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "../../examples/common/example_device.hpp"
#include "../baked_scene.hpp"
#include "../core/test_helpers.hpp"
#include "render_helpers.hpp"
#include "tidewater/render/renderer.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

/// A Vulkan host written the way an engine would, independent of Tidewater's helpers: its
/// device as the examples make theirs (examples/common/example_device.hpp), under the
/// validation layer, with its own targets and command pool.
class TestHost : public examples::ExampleDevice {
  public:
    std::vector<std::string> messages;
    VkCommandPool pool = VK_NULL_HANDLE;
    struct Image {
        VkImage image = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
    } color, depth;
    VkBuffer readback = VK_NULL_HANDLE;
    VkDeviceMemory readback_memory = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM, depth_format = VK_FORMAT_D32_SFLOAT;
    static constexpr std::uint32_t kWidth = 256, kHeight = 144;

    bool has_stencil() const { return depth_format == VK_FORMAT_D32_SFLOAT_S8_UINT; }
    VkImageAspectFlags depth_aspects() const {
        return has_stencil() ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT;
    }
    VkImageLayout depth_layout() const {
        return has_stencil() ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                             : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    }

    static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
        if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
            static_cast<TestHost*>(user)->messages.push_back(data->pMessage ? data->pMessage : "?");
        return VK_FALSE;
    }

    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) {
        VkPhysicalDeviceMemoryProperties p;
        vkGetPhysicalDeviceMemoryProperties(physical, &p);
        for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
        return 0;
    }

    Image make_image(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect) {
        Image img;
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {kWidth, kHeight, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.usage = usage;
        EXPECT_EQ(vkCreateImage(device, &info, nullptr, &img.image), VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, img.image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        EXPECT_EQ(vkAllocateMemory(device, &alloc, nullptr, &img.memory), VK_SUCCESS);
        vkBindImageMemory(device, img.image, img.memory, 0);
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = img.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {aspect, 0, 1, 0, 1};
        EXPECT_EQ(vkCreateImageView(device, &view, nullptr, &img.view), VK_SUCCESS);
        return img;
    }

    void create(VkFormat color_fmt = VK_FORMAT_R8G8B8A8_UNORM, VkFormat depth_fmt = VK_FORMAT_D32_SFLOAT) {
        color_format = color_fmt;
        depth_format = depth_fmt;
        examples::ExampleDeviceOptions options;
        options.application = "tidewater embedding test";
        options.on_message = &on_message;
        options.message_user = this;
        ASSERT_TRUE(ExampleDevice::create(options)) << error();
        VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pi.queueFamilyIndex = family;
        vkCreateCommandPool(device, &pi, nullptr, &pool);
        color = make_image(color_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           VK_IMAGE_ASPECT_COLOR_BIT);
        depth = make_image(depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           depth_aspects());
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = kWidth * kHeight * 8;  // up to 8-byte texels (R16G16B16A16_SFLOAT)
        bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        vkCreateBuffer(device, &bi, nullptr, &readback);
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, readback, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        vkAllocateMemory(device, &alloc, nullptr, &readback_memory);
        vkBindBufferMemory(device, readback, readback_memory, 0);
    }

    void destroy() {
        if (!device) return;
        vkDeviceWaitIdle(device);
        vkDestroyBuffer(device, readback, nullptr);
        vkFreeMemory(device, readback_memory, nullptr);
        for (Image* img : {&color, &depth}) {
            vkDestroyImageView(device, img->view, nullptr);
            vkDestroyImage(device, img->image, nullptr);
            vkFreeMemory(device, img->memory, nullptr);
        }
        vkDestroyCommandPool(device, pool, nullptr);
        ExampleDevice::destroy();
    }
};

void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &b);
}

/// Begins `cmd` and moves the host's images to attachment layouts.
void begin_attachments(TestHost& host, VkCommandBuffer cmd) {
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &bi);
    barrier(cmd, host.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    barrier(cmd, host.depth.image, host.depth_aspects(), VK_IMAGE_LAYOUT_UNDEFINED, host.depth_layout());
}

/// A fresh primary command buffer, begun, with the host's images moved to attachment layouts.
VkCommandBuffer begin_commands(TestHost& host) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = host.pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(host.device, &ai, &cmd) != VK_SUCCESS) return VK_NULL_HANDLE;
    begin_attachments(host, cmd);
    return cmd;
}

bool submit_and_wait(TestHost& host, VkCommandBuffer cmd) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    return vkQueueSubmit(host.queue, 1, &si, VK_NULL_HANDLE) == VK_SUCCESS && vkQueueWaitIdle(host.queue) == VK_SUCCESS;
}

/// The renderer for the host's images: their formats, one frame in flight.
render::RendererInitInfo renderer_info(const TestHost& host) {
    render::RendererInitInfo init;
    init.device = host.context();
    init.color_format = host.color_format;
    init.depth_format = host.depth_format;
    init.frames_in_flight = 1;
    return init;
}

/// IEEE half to float (the float target's texels).
float half_to_float(std::uint16_t h) {
    const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
}

/// A linear value as an 8-bit sRGB code (what an sRGB target stores for it).
std::uint8_t srgb_code(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(e * 255.0f));
}

/// Ends `cmd` after copying the host's colour image out, submits, waits, frees it and
/// returns the picture as display RGBA8, whatever the target's format.
render::RgbaImage finish_and_read(TestHost& host, VkCommandBuffer cmd) {
    barrier(cmd, host.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {TestHost::kWidth, TestHost::kHeight, 1};
    vkCmdCopyImageToBuffer(cmd, host.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.readback, 1, &region);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                         nullptr);
    vkEndCommandBuffer(cmd);
    EXPECT_TRUE(submit_and_wait(host, cmd));
    vkFreeCommandBuffers(host.device, host.pool, 1, &cmd);

    render::RgbaImage img;
    img.width = TestHost::kWidth;
    img.height = TestHost::kHeight;
    img.pixels.resize(TestHost::kWidth * TestHost::kHeight * 4);
    void* mapped = nullptr;
    vkMapMemory(host.device, host.readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped);
    const bool bgra = host.color_format == VK_FORMAT_B8G8R8A8_UNORM || host.color_format == VK_FORMAT_B8G8R8A8_SRGB;
    for (std::size_t k = 0; k < TestHost::kWidth * TestHost::kHeight; ++k) {
        std::uint8_t* out = &img.pixels[k * 4];
        if (host.color_format == VK_FORMAT_R16G16B16A16_SFLOAT) {
            const auto* h = static_cast<const std::uint16_t*>(mapped) + k * 4;
            for (int c = 0; c < 3; ++c) out[c] = srgb_code(half_to_float(h[c]));
            out[3] = 255;
        } else {
            const auto* p = static_cast<const std::uint8_t*>(mapped) + k * 4;
            out[0] = p[bgra ? 2 : 0], out[1] = p[1], out[2] = p[bgra ? 0 : 2], out[3] = p[3];
        }
    }
    vkUnmapMemory(host.device, host.readback_memory);
    return img;
}

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
