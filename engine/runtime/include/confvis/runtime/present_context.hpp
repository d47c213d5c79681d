#pragma once
// The Vulkan context a live display presents with, independent of the renderer's: an instance
// with the window system's surface extensions, a device whose queue can present to GLFW
// windows and copy images, and, on request, the Khronos validation layer with a debug-utils
// messenger that counts what it reports (confvis view --validate, view.json).
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

struct PresentContextOptions {
  bool validation = false;  // VK_LAYER_KHRONOS_validation + messenger; an error if not installed
};

struct ValidationReport {
  bool enabled = false;
  int errors = 0, warnings = 0;
  std::vector<std::string> messages;  // the first few, for the report
};

// Thread-safety: not thread-safe; one thread uses it and the presenters made with it
// (validation() may be read from any thread: the messenger's count is locked).
class PresentContext {
 public:
  // GLFW must be initialised (GlfwSession). Throws Error(DeviceUnsupported) when no device can
  // present to a window, naming the devices seen.
  explicit PresentContext(const PresentContextOptions& options);
  ~PresentContext();
  PresentContext(const PresentContext&) = delete;
  PresentContext& operator=(const PresentContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  VkCommandPool commandPool() const { return commandPool_; }
  const std::string& deviceName() const { return deviceName_; }
  // A memory type among typeBits with all `required` flags; Error(DeviceUnsupported) if none.
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
  ValidationReport validation() const;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
  void createInstance(const PresentContextOptions& options);
  void pickDevice();
  void release() noexcept;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::string deviceName_;
  std::uint32_t queueFamily_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  mutable std::mutex validationMutex_;
  ValidationReport validation_;
};

}  // namespace confvis
