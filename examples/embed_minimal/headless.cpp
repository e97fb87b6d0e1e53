// The smallest complete headless host of Tidewater's renderer: its own instance and
// device with the exact feature chain, two frames in flight over two pairs of target
// images, the layout transitions around record_frame, a readback to PNG, and a CPU
// query that matches the drawn frame (the water's height under the image centre).
//
//   embed_minimal_headless [--frames N] [--out frame.png] [--no-validation]
//
// Exit status 0 when every step worked, the validation layer said nothing and the
// query matched the depth buffer; 1 otherwise.
#include <png.h>
#include <vulkan/vulkan.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>
#include <tidewater/render/renderer.hpp>
#include <tidewater/scene_bake.hpp>
#include <tidewater/tidewater.hpp>
#include <vector>

#include "../common/example_device.hpp"

namespace {

constexpr std::uint32_t kWidth = 640, kHeight = 360, kFramesInFlight = 2;
constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

int g_validation_messages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    ++g_validation_messages;
    return VK_FALSE;
}

bool check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) std::fprintf(stderr, "%s failed: VkResult %d\n", what, static_cast<int>(r));
    return r == VK_SUCCESS;
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

/// The host's device (example_device.hpp: instance, device, queue, the feature chain),
/// a command pool, and its target images.
struct Host : tidewater::examples::ExampleDevice {
    VkCommandPool pool = VK_NULL_HANDLE;

    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const {
        VkPhysicalDeviceMemoryProperties p;
        vkGetPhysicalDeviceMemoryProperties(physical, &p);
        for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
        return 0;
    }

    Image make_image(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect) const {
        Image img;
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {kWidth, kHeight, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.usage = usage;
        vkCreateImage(device, &info, nullptr, &img.image);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, img.image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vkAllocateMemory(device, &alloc, nullptr, &img.memory);
        vkBindImageMemory(device, img.image, img.memory, 0);
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = img.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {aspect, 0, 1, 0, 1};
        vkCreateImageView(device, &view, nullptr, &img.view);
        return img;
    }

    void destroy(Image& img) const {
        vkDestroyImageView(device, img.view, nullptr);
        vkDestroyImage(device, img.image, nullptr);
        vkFreeMemory(device, img.memory, nullptr);
    }

    bool create(bool validation) {
        tidewater::examples::ExampleDeviceOptions options;
        options.application = "embed_minimal";
        options.validation = validation;
        options.on_message = &on_message;
        if (!ExampleDevice::create(options)) {
            std::fprintf(stderr, "%s\n", error().c_str());
            return false;
        }
        VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pi.queueFamilyIndex = family;
        return check(vkCreateCommandPool(device, &pi, nullptr, &pool), "vkCreateCommandPool");
    }

    void destroy() {
        if (device && pool) vkDestroyCommandPool(device, pool, nullptr);
        pool = VK_NULL_HANDLE;
        ExampleDevice::destroy();
    }
};

void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
             VkPipelineStageFlags src_stage, VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
             VkAccessFlags dst_access) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = src_access;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

bool write_png(const std::string& path, const std::vector<std::uint8_t>& rgba) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, kWidth, kHeight, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (std::uint32_t y = 0; y < kHeight; ++y) png_write_row(png, const_cast<png_bytep>(rgba.data() + y * kWidth * 4));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 6;
    std::string out = "frame.png";
    bool validation = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (a == "--no-validation")
            validation = false;
        else {
            std::fprintf(stderr, "usage: embed_minimal_headless [--frames N] [--out frame.png] [--no-validation]\n");
            return 1;
        }
    }
    Host host;
    if (!host.create(validation)) {
        host.destroy();
        return 1;
    }
    bool ok = true;
    {
        // Two frames in flight: a pair of targets, a command buffer and a fence each.
        std::array<Image, kFramesInFlight> color, depth;
        std::array<VkCommandBuffer, kFramesInFlight> cmds{};
        std::array<VkFence, kFramesInFlight> fences{};
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = host.pool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = kFramesInFlight;
        vkAllocateCommandBuffers(host.device, &ai, cmds.data());
        for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
            // TRANSFER_SRC: the renderer copies the opaque scene for refraction.
            color[s] =
                host.make_image(kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                VK_IMAGE_ASPECT_COLOR_BIT);
            depth[s] = host.make_image(kDepthFormat,
                                       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                       VK_IMAGE_ASPECT_DEPTH_BIT);
            VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
            fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;
            vkCreateFence(host.device, &fi, nullptr, &fences[s]);
        }
        // Host-visible buffers for the last frame's colour and depth.
        VkBuffer readback[2]{};
        VkDeviceMemory readback_memory[2]{};
        for (int b = 0; b < 2; ++b) {
            VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
            bi.size = kWidth * kHeight * 4;
            bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
            vkCreateBuffer(host.device, &bi, nullptr, &readback[b]);
            VkMemoryRequirements req;
            vkGetBufferMemoryRequirements(host.device, readback[b], &req);
            VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
            alloc.allocationSize = req.size;
            alloc.memoryTypeIndex = host.memory_type(
                req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
            vkAllocateMemory(host.device, &alloc, nullptr, &readback_memory[b]);
            vkBindBufferMemory(host.device, readback[b], readback_memory[b], 0);
        }

        tidewater::render::RendererInitInfo init;
        init.device = host.context();
        init.color_format = kColorFormat;
        init.depth_format = kDepthFormat;
        init.frames_in_flight = kFramesInFlight;
        init.wireframe = host.enabled.fillModeNonSolid;
        init.log = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
        auto renderer = tidewater::render::Renderer::create(init);
        auto parsed = tidewater::default_scene();
        auto scene = parsed ? tidewater::bake_scene(*parsed)
                            : tidewater::Result<std::shared_ptr<const tidewater::Scene>>(parsed.error());
        if (!renderer || !scene) {
            std::fprintf(stderr, "%s\n", (!renderer ? renderer.error() : scene.error()).message.c_str());
            ok = false;
        }
        if (ok) ok = (*renderer)->set_scene(**scene).ok() && (*renderer)->resize({kWidth, kHeight}).ok();

        // Looking down at open water off the island, so that the image centre is sea.
        tidewater::render::Camera camera;
        camera.position = {1400.0, 40.0, 300.0};
        camera.target = {1300.0, 0.0, 260.0};
        camera.fov_y_deg = 50.0;
        tidewater::Clock clock;
        for (int i = 0; ok && i < frames; ++i) {
            const std::uint32_t s = static_cast<std::uint32_t>(i) % kFramesInFlight;
            vkWaitForFences(host.device, 1, &fences[s], VK_TRUE, UINT64_MAX);  // the slot's last frame is done
            vkResetFences(host.device, 1, &fences[s]);
            VkCommandBuffer cmd = cmds[s];
            vkResetCommandBuffer(cmd, 0);
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            vkBeginCommandBuffer(cmd, &begin);
            // The renderer takes the targets in attachment layouts and gives them back so.
            barrier(cmd, color[s].image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
            barrier(cmd, depth[s].image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
            tidewater::render::FrameInfo frame;
            frame.camera = camera;
            frame.time = clock.now();
            frame.frame_index = static_cast<std::uint64_t>(i);
            const tidewater::render::FrameTargets targets{
                color[s].image, color[s].view, depth[s].image, depth[s].view, {kWidth, kHeight}};
            if (auto st = (*renderer)->record_frame(cmd, frame, targets); !st) {
                std::fprintf(stderr, "record_frame: %s\n", st.error().message.c_str());
                ok = false;
            }
            if (i + 1 == frames) {
                // The last frame: read colour and depth back.
                barrier(cmd, color[s].image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT);
                barrier(cmd, depth[s].image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT);
                VkBufferImageCopy region{};
                region.imageExtent = {kWidth, kHeight, 1};
                region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                vkCmdCopyImageToBuffer(cmd, color[s].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback[0], 1,
                                       &region);
                region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
                vkCmdCopyImageToBuffer(cmd, depth[s].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback[1], 1,
                                       &region);
                VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
                to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
                to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
                vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                                     nullptr, 0, nullptr);
            }
            vkEndCommandBuffer(cmd);
            VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            submit.commandBufferCount = 1;
            submit.pCommandBuffers = &cmd;
            ok = ok && check(vkQueueSubmit(host.queue, 1, &submit, fences[s]), "vkQueueSubmit");
            if (i + 1 < frames) clock.advance(1.0 / 60.0);
        }
        vkDeviceWaitIdle(host.device);

        if (ok) {
            std::vector<std::uint8_t> rgba(kWidth * kHeight * 4);
            std::vector<float> depths(kWidth * kHeight);
            void* mapped = nullptr;
            vkMapMemory(host.device, readback_memory[0], 0, VK_WHOLE_SIZE, 0, &mapped);
            std::memcpy(rgba.data(), mapped, rgba.size());
            vkUnmapMemory(host.device, readback_memory[0]);
            vkMapMemory(host.device, readback_memory[1], 0, VK_WHOLE_SIZE, 0, &mapped);
            std::memcpy(depths.data(), mapped, depths.size() * sizeof(float));
            vkUnmapMemory(host.device, readback_memory[1]);
            if (!write_png(out, rgba)) {
                std::fprintf(stderr, "%s: cannot write the PNG\n", out.c_str());
                ok = false;
            } else {
                std::printf("wrote %s (%ux%u, %d frames, %u in flight)\n", out.c_str(), kWidth, kHeight, frames,
                            kFramesInFlight);
            }
            // The drawn surface under the image centre against the CPU query there. Reversed-Z
            // with an infinite far plane: depth = near / (distance along the view direction).
            const float d = depths[(kHeight / 2) * kWidth + kWidth / 2];
            const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
            const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
            const glm::dvec3 up = glm::cross(right, forward);
            const double tan_half = std::tan(0.5 * camera.fov_y_deg * 3.141592653589793 / 180.0);
            // The centre of pixel (w/2, h/2) sits half a pixel right of and below the image centre.
            const double ndc_x = 1.0 / kWidth, ndc_y = 1.0 / kHeight;
            const glm::dvec3 ray = forward + right * (ndc_x * tan_half * kWidth / kHeight) - up * (ndc_y * tan_half);
            const glm::dvec3 hit = camera.position + ray * (camera.near_plane / static_cast<double>(d));
            const tidewater::WorldPoint water = tidewater::query_world_point(**scene, clock.now(), {hit.x, hit.z});
            const double gap = std::abs(water.surface.height - hit.y);
            std::printf("image centre: drawn surface at y = %.3f m, CPU query %.3f m (%s): %.1f mm apart\n", hit.y,
                        water.surface.height, std::string(tidewater::body_name(**scene, water.body)).c_str(),
                        1000.0 * gap);
            if (!(d > 0.0f) || !(gap < 0.05)) {
                std::fprintf(stderr, "the CPU query does not match the drawn frame\n");
                ok = false;
            } else {
                std::printf("query matches the drawn frame\n");
            }
        }
        renderer = tidewater::Error{};  // the renderer goes before the device
        for (int b = 0; b < 2; ++b) {
            vkDestroyBuffer(host.device, readback[b], nullptr);
            vkFreeMemory(host.device, readback_memory[b], nullptr);
        }
        for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
            host.destroy(color[s]);
            host.destroy(depth[s]);
            vkDestroyFence(host.device, fences[s], nullptr);
        }
    }
    host.destroy();
    if (g_validation_messages > 0) {
        std::fprintf(stderr, "%d validation message(s)\n", g_validation_messages);
        ok = false;
    }
    return ok ? 0 : 1;
}
