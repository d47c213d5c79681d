#pragma once
// The Vulkan context a live display presents with: the Vulkan backend's own context
// (backends/vulkan/src/context.hpp) made with the window system's surface extensions and
// VK_KHR_swapchain, on a device whose graphics queue can present to GLFW windows, and, on
// request, the Khronos validation layer whose messages are counted (confvis view --validate,
// view.json). The Vulkan backend renders on this same device (handles()), so its frames reach
// the windows without leaving the GPU.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

namespace vulkan {
class VulkanContext;
}

struct PresentContextOptions {
  bool validation = false;  // VK_LAYER_KHRONOS_validation + messenger; an error if not installed
  // The device also renders with the Vulkan backend: chosen as VulkanOptions::device says among
  // those that can present, with every rendering feature required and enabled.
  bool forRendering = false;
  std::string device{};  // see VulkanOptions::device; only with forRendering
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

  VkInstance instance() const;
  VkPhysicalDevice physicalDevice() const;
  VkDevice device() const;
  VkQueue queue() const;
  std::uint32_t queueFamily() const;
  VkCommandPool commandPool() const;
  VulkanDeviceHandles handles() const;
  const std::string& deviceName() const;
  // A memory type among typeBits with all `required` flags; Error(DeviceUnsupported) if none.
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
  ValidationReport validation() const;

 private:
  void count(const std::string& message);

  mutable std::mutex validationMutex_;
  ValidationReport validation_;
  std::unique_ptr<vulkan::VulkanContext> context_;
};

}  // namespace confvis
