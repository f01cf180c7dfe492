// aogen/vulkan/device.hpp — a headless Vulkan 1.1+ instance and device for running AO passes.
//
// WHAT
//   context opens a Vulkan instance without any window or surface, picks one physical
//   device and creates a logical device with one queue: of the first queue family with
//   both graphics and compute where there is one (fragment variants draw), else of the
//   first family with compute (graphics() says which). The device is:
//     1. AOGEN_VULKAN_DEVICE (environment) or device_options::name: the first device whose
//        name contains that substring (case-sensitive); none matching is an aogen::error
//        that lists the devices present;
//     2. otherwise the first discrete GPU;
//     3. otherwise Mesa's lavapipe (a name containing "llvmpipe");
//     4. otherwise the first device with Vulkan 1.1 and a compute queue.
//   Features enabled where the device has them: shaderStorageImageExtendedFormats (r8,
//   r32f and rgba16f storage images) and fragmentStoresAndAtomics (the raw-value images of
//   diagnostic fragment passes; fragment_stores() says whether it is there), and
//   shaderFloat16 of VK_KHR_shader_float16_int8 (the fp16 variant axis; shader_float16()).
//   With device_options::validation and VK_LAYER_KHRONOS_validation installed, the layer is
//   enabled with a debug messenger that records every warning and error
//   message into messages(); tests require it to stay empty. (Info messages are the
//   loader's device list and the layer's cache notes, not findings, and are not recorded.)
//
// USAGE
//     #include <aogen/vulkan/device.hpp>        // CMake: target_link_libraries(... aogen::vulkan)
//     aogen::vulkan::context ctx({/*validation*/ true});
//     ctx.device_name();                          // "llvmpipe (LLVM 15.0.6, 256 bits)"
//     ctx.validation_enabled();                   // true where the layer is installed
//     ctx.messages();                             // every validation message so far
//
// ERRORS
//   aogen::error: no Vulkan loader/driver, no device with Vulkan 1.1 and compute, no device
//   matching the requested name, or a Vulkan call failing (naming the call and VkResult).
//   any_device() says whether a context could be made, without throwing.
#pragma once

#include <aogen/error.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace aogen::vulkan {

// aogen::error naming the call unless `result` is VK_SUCCESS.
inline void check(VkResult result, const char* call)
{
    if (result != VK_SUCCESS) throw error(std::string("vulkan: ") + call + " failed with VkResult " + std::to_string(static_cast<int>(result)));
}

inline constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";
inline constexpr const char* device_environment_variable = "AOGEN_VULKAN_DEVICE";

// Whether an instance layer of that name is installed.
inline bool layer_available(const char* name)
{
    uint32_t n = 0;
    if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(n);
    if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
    for (const VkLayerProperties& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

struct device_options {
    bool validation = false; // enable VK_LAYER_KHRONOS_validation where installed
    std::string name;        // substring of the device name; empty: AOGEN_VULKAN_DEVICE, then the default order
};

class context {
public:
    explicit context(const device_options& o = {})
    {
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.pApplicationName = "aogen";
        app.apiVersion = VK_API_VERSION_1_1;
        VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        ici.pApplicationInfo = &app;
        validation_ = o.validation && layer_available(validation_layer);
        const char* layers[] = {validation_layer};
        const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
        VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
        mci.pfnUserCallback = &context::record;
        mci.pUserData = this;
        if (validation_) {
            ici.enabledLayerCount = 1;
            ici.ppEnabledLayerNames = layers;
            ici.enabledExtensionCount = 1;
            ici.ppEnabledExtensionNames = extensions;
            ici.pNext = &mci; // messages of vkCreateInstance / vkDestroyInstance too
        }
        check(vkCreateInstance(&ici, nullptr, &instance_), "vkCreateInstance");
        try {
            if (validation_) {
                auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                    vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
                if (!create) throw error("vulkan: vkCreateDebugUtilsMessengerEXT not found");
                check(create(instance_, &mci, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
            }
            pick(o.name);
            create_device();
        } catch (...) {
            destroy();
            throw;
        }
    }
    ~context() { destroy(); }
    context(const context&) = delete;
    context& operator=(const context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    // Whether the queue also does graphics (needed by fragment variants).
    bool graphics() const { return graphics_; }
    const std::string& device_name() const { return name_; }
    // A CPU implementation (lavapipe): its timestamps are host time, with quirks of their own.
    bool cpu() const { return cpu_; }
    bool validation_enabled() const { return validation_; }
    // Whether fragment shaders may write storage images (raw diagnostics of fragment passes).
    bool fragment_stores() const { return fragment_stores_; }
    // Whether shaders may do 16-bit float arithmetic (fp16 variants).
    bool shader_float16() const { return float16_; }
    // Nanoseconds per timestamp tick; 0 when the queue has no timestamps.
    double timestamp_period_ns() const { return timestamp_bits_ ? timestamp_period_ : 0.0; }
    uint32_t timestamp_valid_bits() const { return timestamp_bits_; }
    // The alignment a storage buffer's descriptor offset must have (VkPhysicalDeviceLimits).
    VkDeviceSize storage_buffer_alignment() const { return storage_alignment_; }

    std::vector<std::string> messages() const
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return messages_;
    }
    void clear_messages()
    {
        std::lock_guard<std::mutex> lock(mutex_);
        messages_.clear();
    }

    // A memory type index with `flags` among `bits`; aogen::error if none.
    uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const
    {
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical_, &mp);
        for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & flags) == flags) return i;
        throw error("vulkan: no memory type with flags " + std::to_string(flags) + " on " + name_);
    }

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL record(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* self)
    {
        auto* c = static_cast<context*>(self);
        std::lock_guard<std::mutex> lock(c->mutex_);
        c->messages_.push_back(data && data->pMessage ? data->pMessage : "(no message)");
        return VK_FALSE;
    }

    static std::vector<VkQueueFamilyProperties> queue_families(VkPhysicalDevice pd)
    {
        uint32_t n = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
        std::vector<VkQueueFamilyProperties> qf(n);
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, qf.data());
        return qf;
    }

    // The first family with graphics and compute, else the first with compute; UINT32_MAX if none.
    static uint32_t compute_family(VkPhysicalDevice pd)
    {
        const std::vector<VkQueueFamilyProperties> qf = queue_families(pd);
        for (VkQueueFlags want : {VkQueueFlags(VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT), VkQueueFlags(VK_QUEUE_COMPUTE_BIT)})
            for (uint32_t i = 0; i < qf.size(); ++i)
                if ((qf[i].queueFlags & want) == want) return i;
        return UINT32_MAX;
    }

    void pick(std::string wanted)
    {
        if (wanted.empty())
            if (const char* env = std::getenv(device_environment_variable)) wanted = env;
        uint32_t n = 0;
        check(vkEnumeratePhysicalDevices(instance_, &n, nullptr), "vkEnumeratePhysicalDevices");
        std::vector<VkPhysicalDevice> all(n);
        check(vkEnumeratePhysicalDevices(instance_, &n, all.data()), "vkEnumeratePhysicalDevices");
        std::vector<VkPhysicalDevice> usable;
        std::vector<VkPhysicalDeviceProperties> props;
        std::string listed;
        for (VkPhysicalDevice pd : all) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(pd, &p);
            if (p.apiVersion < VK_API_VERSION_1_1 || compute_family(pd) == UINT32_MAX) continue;
            usable.push_back(pd);
            props.push_back(p);
            listed += (listed.empty() ? "" : ", ") + std::string("'") + p.deviceName + "'";
        }
        if (usable.empty()) throw error("vulkan: no device with Vulkan 1.1 and a compute queue (install mesa-vulkan-drivers for lavapipe)");
        size_t chosen = usable.size();
        if (!wanted.empty()) {
            for (size_t i = 0; i < usable.size() && chosen == usable.size(); ++i)
                if (std::string(props[i].deviceName).find(wanted) != std::string::npos) chosen = i;
            if (chosen == usable.size())
                throw error("vulkan: device '" + wanted + "' (" + device_environment_variable + " or options) not found (valid: a substring of " + listed + ")");
        }
        for (size_t i = 0; i < usable.size() && chosen == usable.size(); ++i)
            if (props[i].deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) chosen = i;
        for (size_t i = 0; i < usable.size() && chosen == usable.size(); ++i)
            if (std::string(props[i].deviceName).find("llvmpipe") != std::string::npos) chosen = i;
        if (chosen == usable.size()) chosen = 0;
        physical_ = usable[chosen];
        name_ = props[chosen].deviceName;
        cpu_ = props[chosen].deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        timestamp_period_ = props[chosen].limits.timestampPeriod;
        storage_alignment_ = std::max<VkDeviceSize>(1, props[chosen].limits.minStorageBufferOffsetAlignment);
        queue_family_ = compute_family(physical_);
        const VkQueueFamilyProperties family = queue_families(physical_)[queue_family_];
        timestamp_bits_ = family.timestampValidBits;
        graphics_ = (family.queueFlags & VK_QUEUE_GRAPHICS_BIT) != 0;
    }

    void create_device()
    {
        float priority = 1.0f;
        VkDeviceQueueCreateInfo q{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        q.queueFamilyIndex = queue_family_;
        q.queueCount = 1;
        q.pQueuePriorities = &priority;
        VkPhysicalDeviceFeatures have{};
        vkGetPhysicalDeviceFeatures(physical_, &have);
        VkPhysicalDeviceFeatures want{};
        // r8 / rgba16f / r32f output images are "extended" storage formats.
        want.shaderStorageImageExtendedFormats = have.shaderStorageImageExtendedFormats;
        // Fragment passes in diagnostic mode store their raw values to a storage image.
        want.fragmentStoresAndAtomics = have.fragmentStoresAndAtomics;
        fragment_stores_ = have.fragmentStoresAndAtomics == VK_TRUE;
        // 16-bit float arithmetic (fp16 variants): an extension in Vulkan 1.1.
        VkPhysicalDeviceShaderFloat16Int8FeaturesKHR float16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR};
        const char* float16_extension = VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME;
        if (has_device_extension(float16_extension)) {
            VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
            features.pNext = &float16;
            vkGetPhysicalDeviceFeatures2(physical_, &features);
            float16.shaderInt8 = VK_FALSE; // only what aogen uses
        }
        float16_ = float16.shaderFloat16 == VK_TRUE;
        VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        if (float16_) {
            dci.pNext = &float16;
            dci.enabledExtensionCount = 1;
            dci.ppEnabledExtensionNames = &float16_extension;
        }
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &q;
        dci.pEnabledFeatures = &want;
        check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
        vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
    }

    bool has_device_extension(const char* name) const
    {
        uint32_t n = 0;
        vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n, nullptr);
        std::vector<VkExtensionProperties> all(n);
        vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n, all.data());
        for (const VkExtensionProperties& e : all)
            if (std::string(e.extensionName) == name) return true;
        return false;
    }

    void destroy()
    {
        if (device_) vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
        if (messenger_) {
            auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
            if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
            messenger_ = VK_NULL_HANDLE;
        }
        if (instance_) vkDestroyInstance(instance_, nullptr);
        instance_ = VK_NULL_HANDLE;
    }

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    std::string name_;
    bool validation_ = false;
    bool graphics_ = false;
    bool cpu_ = false;
    bool fragment_stores_ = false;
    bool float16_ = false;
    float timestamp_period_ = 0;
    VkDeviceSize storage_alignment_ = 1;
    uint32_t timestamp_bits_ = 0;
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

// Whether a context can be made here (a loader, a driver, a Vulkan 1.1 compute device).
inline bool any_device()
{
    try {
        context c;
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

} // namespace aogen::vulkan
