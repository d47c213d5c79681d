#include "context.hpp"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <optional>

#include "confvis/base/error.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  const std::string text = std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT
                                           ? "validation error: "
                                           : "validation warning: ") +
                           (data && data->pMessage ? data->pMessage : "(no message)");
  const auto* sink = static_cast<const std::function<void(const std::string&)>*>(user);
  if (sink && *sink)
    (*sink)(text);
  else
    std::cerr << "confvis vulkan: " << text << "\n";
  return VK_FALSE;  // never abort the call: the test or the user decides what a message means
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(void* user) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = debugCallback;
  info.pUserData = user;
  return info;
}

bool layerAvailable(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

VkApplicationInfo applicationInfo() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "confvis";
  app.pEngineName = "confvis";
  app.apiVersion = VK_API_VERSION_1_1;
  return app;
}

VkInstance createInstanceChecked(const VkInstanceCreateInfo& info) {
  VkInstance instance = VK_NULL_HANDLE;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
    throw Error(ErrorCode::DeviceUnsupported,
                std::string("no Vulkan driver found (vkCreateInstance: ") + toString(result) +
                    "); install a GPU driver or mesa-vulkan-drivers (lavapipe)");
  check(result, "vkCreateInstance");
  return instance;
}

DeviceKind kindOf(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceKind::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceKind::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceKind::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceKind::Cpu;
    default: return DeviceKind::Other;
  }
}

std::optional<std::uint32_t> graphicsQueueFamily(VkPhysicalDevice device) {
  const std::vector<VkQueueFamilyProperties> families = queueFamilies(device);
  for (std::uint32_t i = 0; i < families.size(); ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return i;
  return std::nullopt;
}

// Whether `device` offers VK_EXT_transform_feedback with what the once-a-frame capture uses
// (transform feedback and its queries, for the overflow check).
bool hasTransformFeedback(VkPhysicalDevice device, std::uint32_t apiVersion) {
  if (apiVersion < VK_API_VERSION_1_1) return false;
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  const bool listed = std::any_of(extensions.begin(), extensions.end(), [](const auto& e) {
    return std::strcmp(e.extensionName, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME) == 0;
  });
  if (!listed) return false;
  VkPhysicalDeviceTransformFeedbackFeaturesEXT features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
  VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features2.pNext = &features;
  vkGetPhysicalDeviceFeatures2(device, &features2);
  VkPhysicalDeviceTransformFeedbackPropertiesEXT properties{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT};
  VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties2.pNext = &properties;
  vkGetPhysicalDeviceProperties2(device, &properties2);
  return features.transformFeedback && properties.transformFeedbackQueries &&
         properties.maxTransformFeedbackBuffers >= 1;
}

}  // namespace

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  return families;
}

DeviceCapabilities capabilitiesOf(VkPhysicalDevice device) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);
  DeviceCapabilities caps;
  caps.name = properties.deviceName;
  caps.kind = kindOf(properties.deviceType);
  caps.apiVersion = properties.apiVersion;
  caps.graphicsQueue = graphicsQueueFamily(device).has_value();
  caps.maxTessellationGenerationLevel = properties.limits.maxTessellationGenerationLevel;
  VkPhysicalDeviceFeatures features;
  vkGetPhysicalDeviceFeatures(device, &features);
  caps.tessellationShader = features.tessellationShader;
  caps.geometryShader = features.geometryShader;
  if (properties.apiVersion >= VK_API_VERSION_1_1) {
    VkPhysicalDeviceMultiviewFeatures multiview{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
    VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features2.pNext = &multiview;
    vkGetPhysicalDeviceFeatures2(device, &features2);
    caps.multiview = multiview.multiview;
    caps.multiviewTessellationShader = multiview.multiviewTessellationShader;
    caps.multiviewGeometryShader = multiview.multiviewGeometryShader;
    VkPhysicalDeviceMultiviewProperties multiviewProps{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &multiviewProps;
    vkGetPhysicalDeviceProperties2(device, &properties2);
    caps.maxMultiviewViewCount = multiviewProps.maxMultiviewViewCount;
  }
  VkFormatProperties format;
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_R32G32B32A32_SFLOAT, &format);
  caps.float32CubeSampling =
      (format.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) &&
      (format.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
  caps.float32ColorAttachment =
      format.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_D32_SFLOAT, &format);
  caps.depth32Attachment =
      format.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
  return caps;
}

std::vector<DeviceCapabilities> queryDevices(VkInstance instance,
                                             std::vector<VkPhysicalDevice>* handles) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
        "vkEnumeratePhysicalDevices");
  std::vector<DeviceCapabilities> caps;
  for (VkPhysicalDevice device : devices) caps.push_back(capabilitiesOf(device));
  if (handles) *handles = devices;
  return caps;
}

VkInstance createPlainInstance() {
  const VkApplicationInfo app = applicationInfo();
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  return createInstanceChecked(info);
}

VulkanContext::VulkanContext(const ContextOptions& options)
    : onMessage_(options.onValidationMessage) {
  try {
    createInstance(options);
    pickDevice(options);
    createDevice(options);
  } catch (...) {
    release();  // the destructor does not run for a half-built object
    throw;
  }
}

void VulkanContext::createInstance(const ContextOptions& options) {
  const VkApplicationInfo app = applicationInfo();
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  std::vector<const char*> extensions = options.instanceExtensions;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (!options.validation) {
    instance_ = createInstanceChecked(info);
    return;
  }
  if (!layerAvailable(kValidationLayer))
    throw Error(ErrorCode::DeviceUnsupported,
                std::string("Vulkan validation requested but ") + kValidationLayer +
                    " is not installed (Debian package vulkan-validationlayers)");
  const char* layers[] = {kValidationLayer};
  extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  info.enabledLayerCount = 1;
  info.ppEnabledLayerNames = layers;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  // Synchronization validation catches missing barriers, the errors a CPU driver hides.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  // Chained into instance creation too, so messages of vkCreate/DestroyInstance are caught.
  VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo(&onMessage_);
  messenger.pNext = &features;
  info.pNext = &messenger;
  instance_ = createInstanceChecked(info);
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) throw Error(ErrorCode::DeviceUnsupported, "VK_EXT_debug_utils is not available");
  messenger.pNext = nullptr;
  check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

void VulkanContext::pickDevice(const ContextOptions& options) {
  std::vector<VkPhysicalDevice> handles;
  std::vector<DeviceCapabilities> devices = queryDevices(instance_, &handles);
  std::vector<std::optional<std::uint32_t>> families(devices.size());
  std::string seen;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    seen += (seen.empty() ? "" : ", ") + devices[i].name;
    const std::vector<VkQueueFamilyProperties> all = queueFamilies(handles[i]);
    for (std::uint32_t f = 0; f < all.size() && !families[i]; ++f)
      if ((all[f].queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
          (!options.canPresent || options.canPresent(instance_, handles[i], f)))
        families[i] = f;
    // A device whose graphics queues cannot present is, for a presenter, one without any.
    devices[i].graphicsQueue = families[i].has_value();
  }
  std::size_t chosen = devices.size();
  if (options.requireRendering) {
    chosen = chooseDevice(devices, options.device);
  } else {
    for (std::size_t i = 0; i < devices.size(); ++i)
      if (families[i] && (chosen == devices.size() || devices[i].kind < devices[chosen].kind))
        chosen = i;  // DeviceKind lists discrete GPUs first, CPU devices last
    if (chosen == devices.size())
      throw Error(ErrorCode::DeviceUnsupported,
                  "no Vulkan device can present to a window on this display (devices: " +
                      (seen.empty() ? std::string("none") : seen) + ")");
  }
  physicalDevice_ = handles[chosen];
  capabilities_ = devices[chosen];
  queueFamily_ = *families[chosen];
}

void VulkanContext::createDevice(const ContextOptions& options) {
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);
  timestampValidBits_ = queueFamilies(physicalDevice_)[queueFamily_].timestampValidBits;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VulkanRequiredFeatures required;
  // A presenter that need not render enables only what the device has.
  const DeviceCapabilities& caps = capabilities_;
  required.features.features.tessellationShader = caps.tessellationShader;
  required.features.features.geometryShader = caps.geometryShader;
  required.multiview.multiview = caps.multiview;
  required.multiview.multiviewTessellationShader = caps.multiviewTessellationShader;
  required.multiview.multiviewGeometryShader = caps.multiviewGeometryShader;
  // Optional: the once-a-frame warp capture (warp_capture.hpp); without it each wall's draw
  // tessellates and warps the bent triangles itself.
  std::vector<const char*> extensions = options.deviceExtensions;
  VkPhysicalDeviceTransformFeedbackFeaturesEXT transformFeedback{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
  transformFeedback_ = options.requireRendering && hasTransformFeedback(physicalDevice_, caps.apiVersion);
  if (transformFeedback_) {
    extensions.push_back(VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);
    transformFeedback.transformFeedback = VK_TRUE;
    transformFeedback.pNext = required.features.pNext;
    required.features.pNext = &transformFeedback;
  }
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  // Vulkan 1.0 devices know no VkPhysicalDeviceFeatures2 chain; they never render (chooseDevice).
  if (caps.apiVersion >= VK_API_VERSION_1_1) info.pNext = &required.features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physicalDevice_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  createCommandPool();
}

void VulkanContext::createCommandPool() {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags =
      VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  check(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(vkCreateFence(device_, &fenceInfo, nullptr, &fence_), "vkCreateFence");
}

VulkanContext::~VulkanContext() { release(); }

void VulkanContext::release() noexcept {
  if (device_) {
    // An application's device: its other queues may be busy on other threads (vkDeviceWaitIdle
    // needs them all); this context's own submissions were waited for.
    if (ownsDevice_) vkDeviceWaitIdle(device_);
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
    if (ownsDevice_) vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_ && ownsDevice_) vkDestroyInstance(instance_, nullptr);  // else the application's
  fence_ = VK_NULL_HANDLE;
  commandPool_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
}

std::optional<std::uint32_t> VulkanContext::findMemoryType(
    std::uint32_t typeBits, VkMemoryPropertyFlags required) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required)
      return i;
  return std::nullopt;
}

std::uint32_t VulkanContext::memoryType(std::uint32_t typeBits,
                                        VkMemoryPropertyFlags required) const {
  if (const auto found = findMemoryType(typeBits, required)) return *found;
  throw Error(ErrorCode::DeviceUnsupported, "Vulkan device '" + capabilities_.name +
                                                "' has no memory type with flags " +
                                                std::to_string(required));
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  submitAndWait(record, {}, {});
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record,
                                  const std::vector<VkSemaphore>& wait,
                                  const std::vector<VkSemaphore>& signal) {
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = commandPool_;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &allocInfo, &cmd), "vkAllocateCommandBuffers");
  struct Free {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Free() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } freeOnExit{device_, commandPool_, cmd};
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  const std::vector<VkPipelineStageFlags> waitStages(wait.size(), VK_PIPELINE_STAGE_TRANSFER_BIT);
  submit.waitSemaphoreCount = static_cast<std::uint32_t>(wait.size());
  submit.pWaitSemaphores = wait.data();
  submit.pWaitDstStageMask = waitStages.data();
  submit.signalSemaphoreCount = static_cast<std::uint32_t>(signal.size());
  submit.pSignalSemaphores = signal.data();
  check(vkResetFences(device_, 1, &fence_), "vkResetFences");
  check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit");
  check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace confvis::vulkan

namespace confvis {

VulkanRequiredFeatures::VulkanRequiredFeatures() {
  multiview.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES;
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  multiview.multiview = VK_TRUE;
  multiview.multiviewTessellationShader = VK_TRUE;
  multiview.multiviewGeometryShader = VK_TRUE;
  features.pNext = &multiview;
  features.features.tessellationShader = VK_TRUE;
  features.features.geometryShader = VK_TRUE;
}

}  // namespace confvis
