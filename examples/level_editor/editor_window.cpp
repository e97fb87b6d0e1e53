#include "editor_window.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/image_write.hpp"

namespace tidewater::editor {

namespace {

Error vk_failed(const char* call, VkResult r) {
    Error e{ErrorCode::device_error, fmt::format("editor: {} failed with VkResult {}", call, static_cast<int>(r))};
    e.vk_result = static_cast<std::int32_t>(r);
    return e;
}

#define EDITOR_VK(call)                                                  \
    do {                                                                 \
        const VkResult editor_r_ = (call);                               \
        if (editor_r_ != VK_SUCCESS) return vk_failed(#call, editor_r_); \
    } while (0)

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

VKAPI_ATTR VkBool32 VKAPI_CALL EditorWindow::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    ++static_cast<EditorWindow*>(user)->validation_messages_;
    return VK_FALSE;
}

std::uint32_t EditorWindow::memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties p;
    vkGetPhysicalDeviceMemoryProperties(gpu_.physical, &p);
    for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
    return 0;
}

Status EditorWindow::create(int width, int height, bool validation) {
    if (!glfwInit()) return Error{ErrorCode::no_device, "editor: glfwInit failed (no display? run under xvfb-run)"};
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(width, height, "Tidewater editor", nullptr, nullptr);
    if (!window_) return Error{ErrorCode::no_device, "editor: cannot create the window"};

    examples::ExampleDeviceOptions options = examples::window_device_options(window_, surface_);
    options.application = "tidewater-editor";
    options.validation = validation;
    options.on_message = &EditorWindow::on_message;
    options.message_user = this;
    if (!gpu_.create(options)) return Error{ErrorCode::no_device, "editor: " + gpu_.error()};
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = gpu_.family;
    EDITOR_VK(vkCreateCommandPool(gpu_.device, &pi, nullptr, &pool_));
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = kFramesInFlight;
    EDITOR_VK(vkAllocateCommandBuffers(gpu_.device, &ai, cmds_));
    for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
        VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        EDITOR_VK(vkCreateFence(gpu_.device, &fi, nullptr, &fences_[s]));
        VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        EDITOR_VK(vkCreateSemaphore(gpu_.device, &si, nullptr, &acquired_[s]));
    }
    return create_swapchain();
}

Status EditorWindow::create_swapchain() {
    vkDeviceWaitIdle(gpu_.device);
    destroy_swapchain();
    VkSurfaceCapabilitiesKHR caps;
    EDITOR_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu_.physical, surface_, &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
        return Error{ErrorCode::unsupported,
                     "editor: the window's images cannot be TRANSFER_SRC, which the renderer needs"};
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu_.physical, surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu_.physical, surface_, &count, formats.data());
    format_ = formats.at(0);
    for (const VkSurfaceFormatKHR& f : formats)  // UNORM: the renderer and ImGui write display values
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) format_ = f;
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    extent_ = caps.currentExtent.width != 0xFFFFFFFFu
                  ? caps.currentExtent
                  : VkExtent2D{static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)};
    VkSwapchainCreateInfoKHR sc{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    sc.surface = surface_;
    sc.minImageCount = std::max(caps.minImageCount, 2u);
    if (caps.maxImageCount) sc.minImageCount = std::min(sc.minImageCount, caps.maxImageCount);
    sc.imageFormat = format_.format;
    sc.imageColorSpace = format_.colorSpace;
    sc.imageExtent = extent_;
    sc.imageArrayLayers = 1;
    sc.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    sc.preTransform = caps.currentTransform;
    sc.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    sc.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    sc.clipped = VK_TRUE;
    EDITOR_VK(vkCreateSwapchainKHR(gpu_.device, &sc, nullptr, &swapchain_));
    if (!ui_pass_) {
        // The UI pass keeps what Tidewater drew and leaves the image ready to present.
        VkAttachmentDescription color{};
        color.format = format_.format;
        color.samples = VK_SAMPLE_COUNT_1_BIT;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkSubpassDescription sub{};
        sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        sub.colorAttachmentCount = 1;
        sub.pColorAttachments = &ref;
        VkSubpassDependency dep{};
        dep.srcSubpass = VK_SUBPASS_EXTERNAL;
        dep.dstSubpass = 0;
        dep.srcStageMask = dep.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        rp.attachmentCount = 1;
        rp.pAttachments = &color;
        rp.subpassCount = 1;
        rp.pSubpasses = &sub;
        rp.dependencyCount = 1;
        rp.pDependencies = &dep;
        EDITOR_VK(vkCreateRenderPass(gpu_.device, &rp, nullptr, &ui_pass_));
    }
    vkGetSwapchainImagesKHR(gpu_.device, swapchain_, &count, nullptr);
    std::vector<VkImage> images(count);
    vkGetSwapchainImagesKHR(gpu_.device, swapchain_, &count, images.data());
    for (VkImage image : images) {
        Target t;
        t.image = image;
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_.format;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        EDITOR_VK(vkCreateImageView(gpu_.device, &vi, nullptr, &t.view));
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = kDepthFormat;
        info.extent = {extent_.width, extent_.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        EDITOR_VK(vkCreateImage(gpu_.device, &info, nullptr, &t.depth));
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(gpu_.device, t.depth, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        EDITOR_VK(vkAllocateMemory(gpu_.device, &alloc, nullptr, &t.depth_memory));
        EDITOR_VK(vkBindImageMemory(gpu_.device, t.depth, t.depth_memory, 0));
        vi.image = t.depth;
        vi.format = kDepthFormat;
        vi.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        EDITOR_VK(vkCreateImageView(gpu_.device, &vi, nullptr, &t.depth_view));
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = ui_pass_;
        fb.attachmentCount = 1;
        fb.pAttachments = &t.view;
        fb.width = extent_.width;
        fb.height = extent_.height;
        fb.layers = 1;
        EDITOR_VK(vkCreateFramebuffer(gpu_.device, &fb, nullptr, &t.framebuffer));
        VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        EDITOR_VK(vkCreateSemaphore(gpu_.device, &si, nullptr, &t.rendered));
        images_.push_back(t);
    }
    return {};
}

void EditorWindow::destroy_swapchain() {
    for (Target& t : images_) {
        vkDestroyFramebuffer(gpu_.device, t.framebuffer, nullptr);
        vkDestroyImageView(gpu_.device, t.depth_view, nullptr);
        vkDestroyImage(gpu_.device, t.depth, nullptr);
        vkFreeMemory(gpu_.device, t.depth_memory, nullptr);
        vkDestroyImageView(gpu_.device, t.view, nullptr);
        vkDestroySemaphore(gpu_.device, t.rendered, nullptr);
    }
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(gpu_.device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

render::DeviceContext EditorWindow::context() const {
    return gpu_.context();
}

Result<bool> EditorWindow::begin_frame(Frame& frame, const std::function<Status(VkExtent2D)>& resized) {
    const std::uint32_t s = static_cast<std::uint32_t>(frame_counter_ % kFramesInFlight);
    vkWaitForFences(gpu_.device, 1, &fences_[s], VK_TRUE, UINT64_MAX);
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    VkResult r = VK_ERROR_OUT_OF_DATE_KHR;
    if (static_cast<std::uint32_t>(w) == extent_.width && static_cast<std::uint32_t>(h) == extent_.height)
        r = vkAcquireNextImageKHR(gpu_.device, swapchain_, UINT64_MAX, acquired_[s], VK_NULL_HANDLE, &current_image_);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        if (w == 0 || h == 0) return false;  // minimised
        if (auto st = create_swapchain(); !st) return st.error();
        if (auto st = resized(extent_); !st) return st.error();
        return false;
    }
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) return vk_failed("vkAcquireNextImageKHR", r);
    vkResetFences(gpu_.device, 1, &fences_[s]);
    Target& t = images_[current_image_];
    frame.cmd = cmds_[s];
    frame.color = t.image;
    frame.color_view = t.view;
    frame.depth = t.depth;
    frame.depth_view = t.depth_view;
    frame.framebuffer = t.framebuffer;
    frame.index = frame_counter_;
    vkResetCommandBuffer(frame.cmd, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    EDITOR_VK(vkBeginCommandBuffer(frame.cmd, &begin));
    barrier(frame.cmd, t.image, VK_IMAGE_ASPECT_COLOR_BIT,
            t.presented ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0,
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    barrier(frame.cmd, t.depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    return true;
}

Status EditorWindow::end_frame(Frame& frame, const std::string& screenshot) {
    const std::uint32_t s = static_cast<std::uint32_t>(frame_counter_ % kFramesInFlight);
    Target& t = images_[current_image_];
    VkBuffer readback = VK_NULL_HANDLE;
    VkDeviceMemory readback_memory = VK_NULL_HANDLE;
    const VkDeviceSize bytes = static_cast<VkDeviceSize>(extent_.width) * extent_.height * 4;
    if (!screenshot.empty()) {
        // The presented picture, UI included, read back before it goes to the screen.
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = bytes;
        bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        EDITOR_VK(vkCreateBuffer(gpu_.device, &bi, nullptr, &readback));
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(gpu_.device, readback, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        EDITOR_VK(vkAllocateMemory(gpu_.device, &alloc, nullptr, &readback_memory));
        EDITOR_VK(vkBindBufferMemory(gpu_.device, readback, readback_memory, 0));
        barrier(frame.cmd, t.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(frame.cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
        barrier(frame.cmd, t.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    }
    EDITOR_VK(vkEndCommandBuffer(frame.cmd));
    const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &acquired_[s];
    submit.pWaitDstStageMask = &wait_stage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.cmd;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &t.rendered;
    EDITOR_VK(vkQueueSubmit(gpu_.queue, 1, &submit, fences_[s]));
    t.presented = true;
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &t.rendered;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &current_image_;
    const VkResult presented = vkQueuePresentKHR(gpu_.queue, &present);
    ++frame_counter_;
    Status result;
    if (presented != VK_SUCCESS && presented != VK_SUBOPTIMAL_KHR && presented != VK_ERROR_OUT_OF_DATE_KHR)
        result = vk_failed("vkQueuePresentKHR", presented);
    if (readback) {
        vkWaitForFences(gpu_.device, 1, &fences_[s], VK_TRUE, UINT64_MAX);
        void* mapped = nullptr;
        vkMapMemory(gpu_.device, readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped);
        std::vector<std::uint8_t> rgba(bytes);
        std::memcpy(rgba.data(), mapped, bytes);
        vkUnmapMemory(gpu_.device, readback_memory);
        if (format_.format == VK_FORMAT_B8G8R8A8_UNORM || format_.format == VK_FORMAT_B8G8R8A8_SRGB)
            for (std::size_t k = 0; k < rgba.size(); k += 4) std::swap(rgba[k], rgba[k + 2]);
        for (std::size_t k = 3; k < rgba.size(); k += 4) rgba[k] = 255;
        vkDestroyBuffer(gpu_.device, readback, nullptr);
        vkFreeMemory(gpu_.device, readback_memory, nullptr);
        if (auto st = detail::write_png_rgba8(screenshot, static_cast<int>(extent_.width),
                                              static_cast<int>(extent_.height), rgba);
            !st)
            return st;
    }
    return result;
}

void EditorWindow::destroy() {
    if (gpu_.device) {
        vkDeviceWaitIdle(gpu_.device);
        destroy_swapchain();
        if (ui_pass_) vkDestroyRenderPass(gpu_.device, ui_pass_, nullptr);
        for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
            vkDestroyFence(gpu_.device, fences_[s], nullptr);
            vkDestroySemaphore(gpu_.device, acquired_[s], nullptr);
        }
        vkDestroyCommandPool(gpu_.device, pool_, nullptr);
    }
    if (surface_) vkDestroySurfaceKHR(gpu_.instance, surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
    gpu_.destroy();  // the device, the validation messenger and the instance
    if (window_) {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    window_ = nullptr;
}

}  // namespace tidewater::editor
