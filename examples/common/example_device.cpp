#include "example_device.hpp"

#include <string>

namespace tidewater::examples {

namespace {

bool failed(std::string& error, const char* call, VkResult r) {
    error = std::string(call) + " failed: VkResult " + std::to_string(static_cast<int>(r));
    return false;
}

}  // namespace

bool ExampleDevice::create(const ExampleDeviceOptions& options) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = options.application;
    app.apiVersion = VK_API_VERSION_1_3;
    std::vector<const char*> extensions = options.instance_extensions;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    if (options.validation) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    VkInstanceCreateInfo ii{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ii.pApplicationInfo = &app;
    ii.enabledLayerCount = options.validation ? 1u : 0u;
    ii.ppEnabledLayerNames = &layer;
    ii.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    ii.ppEnabledExtensionNames = extensions.data();
    if (VkResult r = vkCreateInstance(&ii, nullptr, &instance); r != VK_SUCCESS)
        return failed(error_, "vkCreateInstance", r);
    if (options.validation) {
        VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        mi.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
        mi.pfnUserCallback = options.on_message;
        mi.pUserData = options.message_user;
        auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create_messenger || !options.on_message)
            return failed(error_, "vkCreateDebugUtilsMessengerEXT (no callback)", VK_ERROR_EXTENSION_NOT_PRESENT);
        if (VkResult r = create_messenger(instance, &mi, nullptr, &messenger_); r != VK_SUCCESS)
            return failed(error_, "vkCreateDebugUtilsMessengerEXT", r);
    }
    if (options.on_instance && !options.on_instance(instance)) {
        error_ = "the host's set-up after vkCreateInstance failed";
        return false;
    }

    // The first device with Vulkan 1.3, tessellation and a graphics + compute queue.
    std::uint32_t count = 0;
    if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, nullptr); r != VK_SUCCESS)
        return failed(error_, "vkEnumeratePhysicalDevices", r);
    std::vector<VkPhysicalDevice> devices(count);
    if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, devices.data()); r < VK_SUCCESS)
        return failed(error_, "vkEnumeratePhysicalDevices", r);
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(d, &props);
        VkPhysicalDeviceFeatures features;
        vkGetPhysicalDeviceFeatures(d, &features);
        if (props.apiVersion < VK_API_VERSION_1_3 || !features.tessellationShader) continue;
        std::uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
        std::vector<VkQueueFamilyProperties> fp(families);
        vkGetPhysicalDeviceQueueFamilyProperties(d, &families, fp.data());
        for (std::uint32_t f = 0; f < families && !physical; ++f) {
            const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
            if ((fp[f].queueFlags & need) != need || (options.can_present && !options.can_present(d, f))) continue;
            physical = d;
            family = f;
            enabled.fillModeNonSolid = features.fillModeNonSolid;  // the wireframe view, where there is one
        }
        if (physical) break;
    }
    if (!physical) {
        error_ = "no Vulkan 1.3 device with tessellation and a graphics + compute queue";
        return false;
    }

    // The feature chain: dynamic rendering (Vulkan 1.3) and tessellation, and
    // fillModeNonSolid where the device has it. DeviceContext says the same.
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    enabled.tessellationShader = VK_TRUE;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qi.queueFamilyIndex = family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    di.pNext = &f13;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    di.enabledExtensionCount = static_cast<std::uint32_t>(options.device_extensions.size());
    di.ppEnabledExtensionNames = options.device_extensions.data();
    di.pEnabledFeatures = &enabled;
    if (VkResult r = vkCreateDevice(physical, &di, nullptr, &device); r != VK_SUCCESS)
        return failed(error_, "vkCreateDevice", r);
    vkGetDeviceQueue(device, family, 0, &queue);
    return true;
}

void ExampleDevice::destroy() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy_messenger) destroy_messenger(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
    device = VK_NULL_HANDLE;
    messenger_ = VK_NULL_HANDLE;
    instance = VK_NULL_HANDLE;
    physical = VK_NULL_HANDLE;
}

render::DeviceContext ExampleDevice::context() const {
    render::DeviceContext c;
    c.instance = instance;
    c.physical_device = physical;
    c.device = device;
    c.queue_family = family;
    c.queue = queue;
    c.enabled_features = enabled;
    c.dynamic_rendering = true;
    return c;
}

}  // namespace tidewater::examples
