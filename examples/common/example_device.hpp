// The Vulkan instance and device the example hosts (and the embedding test) make for
// Tidewater: an instance with the validation layer when asked, the first device with
// Vulkan 1.3, tessellation and a graphics + compute queue (that can present, for a
// windowed host), and the exact feature chain Tidewater's renderer needs. Read this
// file with an example: it is the part of a host that every host writes once.
//
// Lifetime: ExampleDevice owns what it made; destroy() (or the destructor) releases it,
// after everything built on it. Threading: one thread.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <tidewater/render/device_context.hpp>
#include <vector>

namespace tidewater::examples {

struct ExampleDeviceOptions {
    const char* application = "tidewater example";
    /// VK_LAYER_KHRONOS_validation with a messenger that calls on_message (warnings and
    /// errors). Default on.
    bool validation = true;
    PFN_vkDebugUtilsMessengerCallbackEXT on_message = nullptr;
    void* message_user = nullptr;
    std::vector<const char*> instance_extensions;  ///< e.g. GLFW's surface extensions
    std::vector<const char*> device_extensions;    ///< e.g. VK_KHR_swapchain
    /// Called once the instance exists (a windowed host makes its surface here); false
    /// stops the creation.
    std::function<bool(VkInstance)> on_instance;
    /// Whether a queue family can present (a windowed host asks its surface); null: any.
    std::function<bool(VkPhysicalDevice, std::uint32_t family)> can_present;
};

class ExampleDevice {
  public:
    ExampleDevice() = default;
    ExampleDevice(const ExampleDevice&) = delete;
    ExampleDevice& operator=(const ExampleDevice&) = delete;
    ~ExampleDevice() { destroy(); }

    /// Makes the instance and device; on failure `error()` says which step failed.
    bool create(const ExampleDeviceOptions& options);
    void destroy();

    /// What the host lends to Tidewater: these handles and the features it enabled.
    render::DeviceContext context() const;
    const std::string& error() const { return error_; }

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t family = 0;
    VkQueue queue = VK_NULL_HANDLE;
    VkPhysicalDeviceFeatures enabled{};  ///< what vkCreateDevice was given

  private:
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::string error_;
};

}  // namespace tidewater::examples
