#include "confvis/runtime/present_context.hpp"

#include <cstring>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "confvis/base/error.hpp"
#include "vk_check.hpp"

namespace confvis {

using vulkan::check;

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::size_t kKeptMessages = 20;

bool layerInstalled(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

// Discrete GPUs first, lavapipe (a CPU device) last: the order `confvis render --device auto`
// picks its renderer in.
int preference(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

}  // namespace

PresentContext::PresentContext(const PresentContextOptions& options) {
  try {
    createInstance(options);
    pickDevice();
  } catch (...) {
    release();
    throw;
  }
}

PresentContext::~PresentContext() { release(); }

void PresentContext::createInstance(const PresentContextOptions& options) {
  std::uint32_t glfwCount = 0;
  const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
  if (!glfwExtensions)
    throw Error(ErrorCode::DeviceUnsupported,
                "the Vulkan loader offers no window-system surface extension (is a Vulkan "
                "driver installed and a display reachable?)");
  std::vector<const char*> extensions(glfwExtensions, glfwExtensions + glfwCount);
  std::vector<const char*> layers;
  if (options.validation) {
    if (!layerInstalled(kValidationLayer))
      throw Error(ErrorCode::DeviceUnsupported,
                  std::string("--validate needs ") + kValidationLayer +
                      " (Debian: vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    validation_.enabled = true;
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "confvis view";
  app.apiVersion = VK_API_VERSION_1_1;
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &PresentContext::onMessage;
  messenger.pUserData = this;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  if (options.validation) info.pNext = &messenger;  // also covers instance creation itself
  const VkResult created = vkCreateInstance(&info, nullptr, &instance_);
  if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error(ErrorCode::DeviceUnsupported,
                "no Vulkan driver (Debian: mesa-vulkan-drivers gives lavapipe)");
  check(created, "vkCreateInstance (presenting)");
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw Error(ErrorCode::DeviceUnsupported, "no vkCreateDebugUtilsMessengerEXT");
    check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }
}

void PresentContext::pickDevice() {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
  int best = 99;
  std::string seen;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(candidate, &properties);
    seen += (seen.empty() ? "" : ", ") + std::string(properties.deviceName);
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
    for (std::uint32_t f = 0; f < familyCount; ++f) {
      // Graphics queues can blit; presentation support is asked of the window system.
      if (!(families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
      if (glfwGetPhysicalDevicePresentationSupport(instance_, candidate, f) != GLFW_TRUE) continue;
      if (preference(properties.deviceType) < best) {
        best = preference(properties.deviceType);
        physicalDevice_ = candidate;
        queueFamily_ = f;
        deviceName_ = properties.deviceName;
      }
      break;
    }
  }
  if (!physicalDevice_)
    throw Error(ErrorCode::DeviceUnsupported,
                "no Vulkan device can present to a window on this display (devices: " +
                    (seen.empty() ? std::string("none") : seen) + ")");
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = queueFamily_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = &swapchainExtension;
  check(vkCreateDevice(physicalDevice_, &info, nullptr, &device_), "vkCreateDevice (presenting)");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = queueFamily_;
  check(vkCreateCommandPool(device_, &pool, nullptr, &commandPool_), "vkCreateCommandPool");
}

std::uint32_t PresentContext::memoryType(std::uint32_t typeBits,
                                         VkMemoryPropertyFlags required) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required)
      return i;
  throw Error(ErrorCode::DeviceUnsupported,
              deviceName_ + " has no memory type for a presenting buffer or image");
}

ValidationReport PresentContext::validation() const {
  const std::lock_guard lock(validationMutex_);
  return validation_;
}

VKAPI_ATTR VkBool32 VKAPI_CALL PresentContext::onMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  auto* context = static_cast<PresentContext*>(self);
  const std::lock_guard lock(context->validationMutex_);
  ValidationReport& report = context->validation_;
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ++report.errors;
  else ++report.warnings;
  if (report.messages.size() < kKeptMessages && data && data->pMessage)
    report.messages.emplace_back(data->pMessage);
  return VK_FALSE;
}

void PresentContext::release() noexcept {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  device_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
}

}  // namespace confvis
