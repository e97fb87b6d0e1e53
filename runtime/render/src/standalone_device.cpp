// StandaloneDevice is a host like any other: it creates its instance and device
// through the system loader's exported functions, then lends them as a DeviceContext.
#undef VK_NO_PROTOTYPES
#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

#include "tidewater/render/standalone.hpp"
#include "vk_util.hpp"

namespace tidewater::render {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool layer_available(const char* name) {
    std::uint32_t count = 0;
    if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(count);
    if (vkEnumerateInstanceLayerProperties(&count, layers.data()) < VK_SUCCESS) return false;
    layers.resize(count);
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

struct Candidate {
    VkPhysicalDevice device = VK_NULL_HANDLE;
    std::string name;
    std::uint32_t queue_family = 0;
    std::string why_not;  // empty when usable
};

bool has_device_extension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS) return false;
    std::vector<VkExtensionProperties> extensions(count);
    if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()) != VK_SUCCESS) return false;
    for (const VkExtensionProperties& e : extensions)
        if (std::string_view(e.extensionName) == name) return true;
    return false;
}

Candidate inspect(VkPhysicalDevice device) {
    Candidate c;
    c.device = device;
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    c.name = props.deviceName;
    if (props.apiVersion < VK_API_VERSION_1_3) {
        c.why_not = fmt::format("Vulkan {}.{}, needs 1.3", VK_API_VERSION_MAJOR(props.apiVersion),
                                VK_API_VERSION_MINOR(props.apiVersion));
        return c;
    }
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f13;
    vkGetPhysicalDeviceFeatures2(device, &f2);
    if (!f13.dynamicRendering) {
        c.why_not = "no dynamicRendering";
        return c;
    }
    if (!f2.features.tessellationShader) {
        c.why_not = "no tessellationShader";
        return c;
    }
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need) {
            c.queue_family = i;
            return c;
        }
    }
    c.why_not = "no graphics+compute queue";
    return c;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL StandaloneDevice::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                            VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                            void* user) {
    auto* self = static_cast<StandaloneDevice*>(user);
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        self->validation_messages_.fetch_add(1);
        const std::string text = fmt::format("Vulkan validation: {}", data && data->pMessage ? data->pMessage : "?");
        if (self->log_) {
            self->log_(text);
        } else {
            std::fprintf(stderr, "%s\n", text.c_str());
        }
    }
    return VK_FALSE;
}

Result<std::unique_ptr<StandaloneDevice>> StandaloneDevice::create(const StandaloneOptions& options) {
    std::unique_ptr<StandaloneDevice> self(new StandaloneDevice());
    self->log_ = options.log;
    std::vector<const char*> layers, extensions;
    if (options.validation) {
        if (!layer_available(kValidationLayer)) {
            return Error{ErrorCode::unsupported,
                         "Vulkan: VK_LAYER_KHRONOS_validation is not installed (Debian: vulkan-validationlayers)"};
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "tidewater";
    app.pEngineName = "tidewater";
    app.apiVersion = VK_API_VERSION_1_3;
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &StandaloneDevice::on_message;
    messenger.pUserData = self.get();
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (options.validation) info.pNext = &messenger;  // also covers instance creation itself
    const VkResult created = vkCreateInstance(&info, nullptr, &self->context_.instance);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER) {
        return Error{ErrorCode::no_device,
                     "No Vulkan device: no installed driver could create a Vulkan 1.3 instance "
                     "(VK_ERROR_INCOMPATIBLE_DRIVER; none installed? Debian: mesa-vulkan-drivers)"};
    }
    if (created != VK_SUCCESS) return detail::vk_error(created, "vkCreateInstance");
    if (options.validation) {
        auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(self->context_.instance, "vkCreateDebugUtilsMessengerEXT"));
        if (create_messenger)
            TW_VK_TRY(create_messenger(self->context_.instance, &messenger, nullptr, &self->messenger_));
    }

    std::uint32_t count = 0;
    TW_VK_TRY(vkEnumeratePhysicalDevices(self->context_.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    TW_VK_TRY(vkEnumeratePhysicalDevices(self->context_.instance, &count, devices.data()));
    std::string found;
    const Candidate* chosen = nullptr;
    std::vector<Candidate> candidates;
    for (VkPhysicalDevice d : devices) candidates.push_back(inspect(d));
    for (const Candidate& c : candidates) {
        const bool name_ok =
            options.device_name_contains.empty() || c.name.find(options.device_name_contains) != std::string::npos;
        found += fmt::format("{}\"{}\" ({})", found.empty() ? "" : ", ", c.name,
                             !c.why_not.empty() ? c.why_not : (name_ok ? "usable" : "name does not match"));
        if (!chosen && c.why_not.empty() && name_ok) chosen = &c;
    }
    if (!chosen) {
        return Error{ErrorCode::no_device,
                     fmt::format("No Vulkan device fits (needs Vulkan 1.3, dynamic rendering, tessellation, a "
                                 "graphics+compute queue{}); found: {}",
                                 options.device_name_contains.empty()
                                     ? ""
                                     : fmt::format(", a name containing \"{}\"", options.device_name_contains),
                                 found.empty() ? "none" : found)};
    }
    self->device_name_ = chosen->name;
    self->context_.physical_device = chosen->device;
    self->context_.queue_family = chosen->queue_family;

    VkPhysicalDeviceFeatures supported;
    vkGetPhysicalDeviceFeatures(chosen->device, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.fillModeNonSolid = supported.fillModeNonSolid;                // wireframe debug view
    enabled.tessellationShader = supported.tessellationShader;            // water level of detail
    enabled.sampleRateShading = supported.sampleRateShading;              // water shaded per sample (optional)
    enabled.pipelineStatisticsQuery = supported.pipelineStatisticsQuery;  // invocations per pass (optional)
    enabled.occlusionQueryPrecise = supported.occlusionQueryPrecise;      // samples per pass (optional)
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    // Shader statistics where the driver has them (RADV, most desktop drivers; not lavapipe).
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable_info{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    std::vector<const char*> device_extensions;
    if (has_device_extension(chosen->device, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
        VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        query.pNext = &executable_info;
        vkGetPhysicalDeviceFeatures2(chosen->device, &query);
        executable_info.pNext = nullptr;
        if (executable_info.pipelineExecutableInfo) {
            device_extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
            f13.pNext = &executable_info;
        }
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = chosen->queue_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo dev{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dev.pNext = &f13;
    dev.queueCreateInfoCount = 1;
    dev.pQueueCreateInfos = &queue;
    dev.pEnabledFeatures = &enabled;
    dev.enabledExtensionCount = static_cast<std::uint32_t>(device_extensions.size());
    dev.ppEnabledExtensionNames = device_extensions.data();
    TW_VK_TRY(vkCreateDevice(chosen->device, &dev, nullptr, &self->context_.device));
    self->context_.pipeline_executable_info = !device_extensions.empty();
    self->compile_only_ = options.compile_only;
    self->context_.enabled_features = enabled;
    self->context_.dynamic_rendering = true;
    vkGetDeviceQueue(self->context_.device, chosen->queue_family, 0, &self->context_.queue);
    return self;
}

StandaloneDevice::~StandaloneDevice() {
    if (context_.device) {
        // A lost device has no work left: it is destroyed all the same. A compile-only one
        // never had any (a null device cannot wait).
        if (const VkResult r = compile_only_ ? VK_SUCCESS : vkDeviceWaitIdle(context_.device); r != VK_SUCCESS) {
            const std::string text = detail::vk_error(r, "vkDeviceWaitIdle (destroying the standalone device)").message;
            if (log_)
                log_(text);
            else
                std::fprintf(stderr, "%s\n", text.c_str());
        }
        vkDestroyDevice(context_.device, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(context_.instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(context_.instance, messenger_, nullptr);
    }
    if (context_.instance) vkDestroyInstance(context_.instance, nullptr);
}

}  // namespace tidewater::render
