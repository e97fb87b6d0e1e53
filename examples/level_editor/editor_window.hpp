// The editor's window and Vulkan objects: a GLFW window, its own instance and device
// with Tidewater's feature chain, a swapchain whose images have TRANSFER_SRC usage (the
// renderer copies the opaque scene; screenshots read it back), a depth image per
// swapchain image, two frames in flight, and a render pass that loads what Tidewater
// drew so that Dear ImGui draws over it.
// Lifetime: owns everything it creates; destroy it after the renderer and ImGui.
// Threading: the main thread only.
#pragma once

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdint>
#include <functional>
#include <string>
#include <tidewater/render/device_context.hpp>
#include <tidewater/result.hpp>
#include <vector>

#include "../common/example_window.hpp"

namespace tidewater::editor {

class EditorWindow {
  public:
    static constexpr std::uint32_t kFramesInFlight = 2;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    Status create(int width, int height, bool validation);
    void destroy();
    ~EditorWindow() { destroy(); }

    GLFWwindow* window() const { return window_; }
    render::DeviceContext context() const;
    VkFormat color_format() const { return format_.format; }
    VkExtent2D extent() const { return extent_; }
    VkRenderPass ui_pass() const { return ui_pass_; }
    std::uint32_t image_count() const { return static_cast<std::uint32_t>(images_.size()); }
    int validation_messages() const { return validation_messages_; }

    /// What a frame records into: the command buffer (begun), the swapchain image (in
    /// COLOR_ATTACHMENT_OPTIMAL) and its depth (DEPTH_ATTACHMENT_OPTIMAL), and the UI
    /// pass's framebuffer.
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkImage color = VK_NULL_HANDLE, depth = VK_NULL_HANDLE;
        VkImageView color_view = VK_NULL_HANDLE, depth_view = VK_NULL_HANDLE;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        std::uint64_t index = 0;  ///< frames since the start
    };
    /// Waits for the slot, acquires an image and begins its commands; false when the
    /// swapchain was rebuilt instead (`resized` is called with the new extent).
    Result<bool> begin_frame(Frame& frame, const std::function<Status(VkExtent2D)>& resized);
    /// Ends, submits and presents; with `screenshot` non-empty, the presented image is
    /// also written there (waits for the device).
    Status end_frame(Frame& frame, const std::string& screenshot = {});

  private:
    Status create_swapchain();
    void destroy_swapchain();
    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const;
    static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    GLFWwindow* window_ = nullptr;
    examples::ExampleDevice gpu_;  // instance, device and queue (../common/example_device.hpp)
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format_{};
    VkExtent2D extent_{};
    VkRenderPass ui_pass_ = VK_NULL_HANDLE;
    struct Target {
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkImage depth = VK_NULL_HANDLE;
        VkDeviceMemory depth_memory = VK_NULL_HANDLE;
        VkImageView depth_view = VK_NULL_HANDLE;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        VkSemaphore rendered = VK_NULL_HANDLE;
        bool presented = false;
    };
    std::vector<Target> images_;
    VkCommandBuffer cmds_[kFramesInFlight]{};
    VkFence fences_[kFramesInFlight]{};
    VkSemaphore acquired_[kFramesInFlight]{};
    std::uint32_t current_image_ = 0;
    std::uint64_t frame_counter_ = 0;
    int validation_messages_ = 0;
};

}  // namespace tidewater::editor
