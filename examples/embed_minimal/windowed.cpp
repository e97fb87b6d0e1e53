// The smallest windowed host of Tidewater's renderer: a GLFW window, a swapchain whose
// images have TRANSFER_SRC usage (the renderer copies the opaque scene for refraction),
// two frames in flight, and Renderer::resize whenever the swapchain is rebuilt.
//
//   embed_minimal_windowed [--frames N] [--resize-at N]
//
// With --frames it closes itself after N frames (CI runs it under xvfb-run); with
// --resize-at it resizes its window at that frame, so the swapchain is rebuilt.
// Exit status 0 when every frame recorded and presented and the validation layer said
// nothing.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tidewater/render/renderer.hpp>
#include <tidewater/scene_bake.hpp>
#include <tidewater/tidewater.hpp>
#include <vector>

#include "../common/example_window.hpp"

namespace {

constexpr std::uint32_t kFramesInFlight = 2;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
int g_validation_messages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    ++g_validation_messages;
    return VK_FALSE;
}

struct Depth {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

/// The host's device (example_device.hpp: instance, device, queue, the feature chain)
/// with its window, surface, swapchain and frames in flight.
struct App : tidewater::examples::ExampleDevice {
    GLFWwindow* window = nullptr;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format{};
    VkExtent2D extent{};
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<Depth> depths;  // one per swapchain image
    VkCommandBuffer cmds[kFramesInFlight]{};
    VkFence fences[kFramesInFlight]{};
    VkSemaphore acquired[kFramesInFlight]{};
    std::vector<VkSemaphore> rendered;  // one per swapchain image

    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const {
        VkPhysicalDeviceMemoryProperties p;
        vkGetPhysicalDeviceMemoryProperties(physical, &p);
        for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
        return 0;
    }

    bool create_device() {
        tidewater::examples::ExampleDeviceOptions options = tidewater::examples::window_device_options(window, surface);
        options.application = "embed_minimal_windowed";
        options.on_message = &on_message;
        if (!create(options)) {
            std::fprintf(stderr, "%s\n", error().c_str());
            return false;
        }
        VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pi.queueFamilyIndex = family;
        vkCreateCommandPool(device, &pi, nullptr, &pool);
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = pool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = kFramesInFlight;
        vkAllocateCommandBuffers(device, &ai, cmds);
        for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
            VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
            fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;
            vkCreateFence(device, &fi, nullptr, &fences[s]);
            VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
            vkCreateSemaphore(device, &si, nullptr, &acquired[s]);
        }
        return true;
    }

    void destroy_swapchain() {
        for (Depth& d : depths) {
            vkDestroyImageView(device, d.view, nullptr);
            vkDestroyImage(device, d.image, nullptr);
            vkFreeMemory(device, d.memory, nullptr);
        }
        for (VkImageView v : views) vkDestroyImageView(device, v, nullptr);
        for (VkSemaphore s : rendered) vkDestroySemaphore(device, s, nullptr);
        depths.clear();
        views.clear();
        rendered.clear();
        if (swapchain) vkDestroySwapchainKHR(device, swapchain, nullptr);
        swapchain = VK_NULL_HANDLE;
    }

    /// (Re)creates the swapchain at the window's size: its images need TRANSFER_SRC.
    bool create_swapchain() {
        vkDeviceWaitIdle(device);
        destroy_swapchain();
        VkSurfaceCapabilitiesKHR caps;
        vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps);
        if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT)) {
            std::fprintf(stderr, "the surface's images cannot be TRANSFER_SRC, which the renderer needs\n");
            return false;
        }
        std::uint32_t count = 0;
        vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr);
        std::vector<VkSurfaceFormatKHR> formats(count);
        vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data());
        format = formats[0];
        for (const VkSurfaceFormatKHR& f : formats)  // a UNORM format: the renderer writes display values
            if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) format = f;
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        extent = caps.currentExtent.width != 0xFFFFFFFFu
                     ? caps.currentExtent
                     : VkExtent2D{static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)};
        VkSwapchainCreateInfoKHR sc{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
        sc.surface = surface;
        sc.minImageCount = std::max(caps.minImageCount, 2u);
        if (caps.maxImageCount) sc.minImageCount = std::min(sc.minImageCount, caps.maxImageCount);
        sc.imageFormat = format.format;
        sc.imageColorSpace = format.colorSpace;
        sc.imageExtent = extent;
        sc.imageArrayLayers = 1;
        sc.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        sc.preTransform = caps.currentTransform;
        sc.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
        sc.presentMode = VK_PRESENT_MODE_FIFO_KHR;
        sc.clipped = VK_TRUE;
        if (vkCreateSwapchainKHR(device, &sc, nullptr, &swapchain) != VK_SUCCESS) return false;
        vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr);
        images.resize(count);
        vkGetSwapchainImagesKHR(device, swapchain, &count, images.data());
        for (VkImage image : images) {
            VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            vi.image = image;
            vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
            vi.format = format.format;
            vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            views.emplace_back();
            vkCreateImageView(device, &vi, nullptr, &views.back());
            Depth d;
            VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
            info.imageType = VK_IMAGE_TYPE_2D;
            info.format = kDepthFormat;
            info.extent = {extent.width, extent.height, 1};
            info.mipLevels = info.arrayLayers = 1;
            info.samples = VK_SAMPLE_COUNT_1_BIT;
            info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
            vkCreateImage(device, &info, nullptr, &d.image);
            VkMemoryRequirements req;
            vkGetImageMemoryRequirements(device, d.image, &req);
            VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
            alloc.allocationSize = req.size;
            alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
            vkAllocateMemory(device, &alloc, nullptr, &d.memory);
            vkBindImageMemory(device, d.image, d.memory, 0);
            vi.image = d.image;
            vi.format = kDepthFormat;
            vi.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
            vkCreateImageView(device, &vi, nullptr, &d.view);
            depths.push_back(d);
            VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
            rendered.emplace_back();
            vkCreateSemaphore(device, &si, nullptr, &rendered.back());
        }
        return true;
    }

    void destroy() {
        if (device) {
            vkDeviceWaitIdle(device);  // the host's last frames: nothing to report on the way out
            destroy_swapchain();
            for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
                vkDestroyFence(device, fences[s], nullptr);
                vkDestroySemaphore(device, acquired[s], nullptr);
            }
            vkDestroyCommandPool(device, pool, nullptr);
        }
        if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
        surface = VK_NULL_HANDLE;
        ExampleDevice::destroy();
        if (window) glfwDestroyWindow(window);
        window = nullptr;
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

}  // namespace

int main(int argc, char** argv) {
    long frames = -1, resize_at = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc)
            frames = std::atol(argv[++i]);
        else if (a == "--resize-at" && i + 1 < argc)
            resize_at = std::atol(argv[++i]);
        else {
            std::fprintf(stderr, "usage: embed_minimal_windowed [--frames N] [--resize-at N]\n");
            return 1;
        }
    }
    if (!glfwInit()) {
        std::fprintf(stderr, "glfwInit failed (no display? run under xvfb-run)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    App app;
    app.window = glfwCreateWindow(640, 360, "Tidewater embed_minimal", nullptr, nullptr);
    bool ok = app.window && app.create_device() && app.create_swapchain();
    int resizes = 0;
    long drawn = 0;
    if (ok) {
        tidewater::render::RendererInitInfo init;
        init.device = app.context();
        init.color_format = app.format.format;
        init.depth_format = kDepthFormat;
        init.frames_in_flight = kFramesInFlight;
        init.wireframe = app.enabled.fillModeNonSolid;
        auto renderer = tidewater::render::Renderer::create(init);
        auto parsed = tidewater::default_scene();
        auto scene = parsed ? tidewater::bake_scene(*parsed)
                            : tidewater::Result<std::shared_ptr<const tidewater::Scene>>(parsed.error());
        ok = renderer && scene && (*renderer)->set_scene(**scene).ok() && (*renderer)->resize(app.extent).ok();
        if (!ok)
            std::fprintf(stderr, "%s\n",
                         !renderer ? renderer.error().message.c_str()
                         : !scene  ? scene.error().message.c_str()
                                   : "set_scene failed");
        tidewater::Clock clock;
        std::vector<bool> seen(app.images.size(), false);  // images that have been presented once
        bool rebuild = false;
        for (std::uint64_t i = 0;
             ok && !glfwWindowShouldClose(app.window) && (frames < 0 || static_cast<long>(i) < frames); ++i) {
            glfwPollEvents();
            if (static_cast<long>(i) == resize_at) glfwSetWindowSize(app.window, 480, 300);
            const std::uint32_t s = static_cast<std::uint32_t>(i % kFramesInFlight);
            vkWaitForFences(app.device, 1, &app.fences[s], VK_TRUE, UINT64_MAX);
            std::uint32_t index = 0;
            VkResult acquired = rebuild ? VK_ERROR_OUT_OF_DATE_KHR
                                        : vkAcquireNextImageKHR(app.device, app.swapchain, UINT64_MAX, app.acquired[s],
                                                                VK_NULL_HANDLE, &index);
            if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
                // Rebuild the swapchain, then tell the renderer the new size.
                ok = app.create_swapchain() && (*renderer)->resize(app.extent).ok();
                seen.assign(app.images.size(), false);
                rebuild = false;
                ++resizes;
                std::printf("swapchain rebuilt at %ux%u; renderer resized\n", app.extent.width, app.extent.height);
                continue;
            }
            if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR) {
                ok = false;
                break;
            }
            vkResetFences(app.device, 1, &app.fences[s]);
            VkCommandBuffer cmd = app.cmds[s];
            vkResetCommandBuffer(cmd, 0);
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            vkBeginCommandBuffer(cmd, &begin);
            barrier(cmd, app.images[index], VK_IMAGE_ASPECT_COLOR_BIT,
                    seen[index] ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
            barrier(cmd, app.depths[index].image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
                    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
            tidewater::render::FrameInfo frame;
            frame.camera.position = (*scene)->camera->position;
            frame.camera.target = (*scene)->camera->target;
            frame.camera.fov_y_deg = (*scene)->camera->fov_y_deg;
            frame.time = clock.now();
            frame.frame_index = i;
            const tidewater::render::FrameTargets targets{app.images[index], app.views[index], app.depths[index].image,
                                                          app.depths[index].view, app.extent};
            if (auto st = (*renderer)->record_frame(cmd, frame, targets); !st) {
                std::fprintf(stderr, "record_frame: %s\n", st.error().message.c_str());
                ok = false;
            }
            barrier(cmd, app.images[index], VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
            vkEndCommandBuffer(cmd);
            const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
            VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            submit.waitSemaphoreCount = 1;
            submit.pWaitSemaphores = &app.acquired[s];
            submit.pWaitDstStageMask = &wait_stage;
            submit.commandBufferCount = 1;
            submit.pCommandBuffers = &cmd;
            submit.signalSemaphoreCount = 1;
            submit.pSignalSemaphores = &app.rendered[index];
            ok = ok && vkQueueSubmit(app.queue, 1, &submit, app.fences[s]) == VK_SUCCESS;
            seen[index] = true;
            VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
            present.waitSemaphoreCount = 1;
            present.pWaitSemaphores = &app.rendered[index];
            present.swapchainCount = 1;
            present.pSwapchains = &app.swapchain;
            present.pImageIndices = &index;
            const VkResult presented = vkQueuePresentKHR(app.queue, &present);
            int w = 0, h = 0;
            glfwGetFramebufferSize(app.window, &w, &h);
            const bool size_changed =
                static_cast<std::uint32_t>(w) != app.extent.width || static_cast<std::uint32_t>(h) != app.extent.height;
            if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || size_changed)
                rebuild = true;
            else if (presented != VK_SUCCESS)
                ok = false;
            ++drawn;
            clock.advance(1.0 / 60.0);
        }
        vkDeviceWaitIdle(app.device);
        renderer = tidewater::Error{};  // the renderer goes before the device
    }
    app.destroy();
    glfwTerminate();
    std::printf("presented %ld frame(s), %d swapchain rebuild(s), %d validation message(s)\n", drawn, resizes,
                g_validation_messages);
    return ok && g_validation_messages == 0 && (resize_at < 0 || resizes > 0) ? 0 : 1;
}
