// What a windowed host adds to ExampleDeviceOptions: GLFW's instance extensions, the
// swapchain extension, the window's surface made once the instance exists, and a queue
// that can present to it. Header-only, so that headless hosts need no GLFW.
#pragma once

#include <GLFW/glfw3.h>
#include <vulkan/vulkan.h>

#include "example_device.hpp"

namespace tidewater::examples {

/// Options for a device that presents to `window`; `surface` (owned by the caller, who
/// destroys it before the instance) is set when the instance is made.
inline ExampleDeviceOptions window_device_options(GLFWwindow* window, VkSurfaceKHR& surface) {
    ExampleDeviceOptions options;
    std::uint32_t count = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&count);
    options.instance_extensions.assign(extensions, extensions + count);
    options.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    options.on_instance = [window, &surface](VkInstance made) {
        return glfwCreateWindowSurface(made, window, nullptr, &surface) == VK_SUCCESS;
    };
    options.can_present = [&surface](VkPhysicalDevice d, std::uint32_t family) {
        VkBool32 present = VK_FALSE;
        return vkGetPhysicalDeviceSurfaceSupportKHR(d, family, surface, &present) == VK_SUCCESS && present;
    };
    return options;
}

}  // namespace tidewater::examples
