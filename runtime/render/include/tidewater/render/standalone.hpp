// A headless Vulkan device of Tidewater's own, for the CLI, tools and tests:
// no surface, no window. Hosts with their own device use DeviceContext instead.
//
// Lifetime: owns its instance and device; destroy after every object built on
// context(). Threading: one thread at a time.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tidewater/render/device_context.hpp"
#include "tidewater/result.hpp"

namespace tidewater::render {

struct StandaloneOptions {
    /// Enables VK_LAYER_KHRONOS_validation and a debug messenger that counts
    /// warnings and errors (tests fail on any). Default off.
    bool validation = false;
    /// Receives validation and driver messages; default prints to stderr.
    std::function<void(const std::string&)> log;
    /// Pick the first device whose name contains this; empty = the first suitable one.
    std::string device_name_contains;
    /// The device only builds pipelines (a driver's null device, such as RADV's under
    /// RADV_FORCE_FAMILY, which cannot run work): nothing may be submitted to it, and its
    /// destruction does not wait for it. Default off.
    bool compile_only = false;
};

class StandaloneDevice {
  public:
    static Result<std::unique_ptr<StandaloneDevice>> create(const StandaloneOptions& options = {});
    ~StandaloneDevice();
    StandaloneDevice(const StandaloneDevice&) = delete;
    StandaloneDevice& operator=(const StandaloneDevice&) = delete;

    const DeviceContext& context() const { return context_; }
    const std::string& device_name() const { return device_name_; }
    /// Validation warnings and errors reported so far.
    std::size_t validation_messages() const { return validation_messages_.load(); }

  private:
    StandaloneDevice() = default;
    static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT types,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
    DeviceContext context_{};
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::string device_name_;
    std::function<void(const std::string&)> log_;
    bool compile_only_ = false;
    std::atomic<std::size_t> validation_messages_{0};
};

}  // namespace tidewater::render
