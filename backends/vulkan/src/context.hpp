#pragma once
// The Vulkan instance and device confvis renders with: device selection (device_requirements),
// optional validation with a debug messenger, one graphics queue, one command pool, and
// one-shot command submission for uploads and frames.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/backends/vulkan/byo_device.hpp"
#include "confvis/backends/vulkan/device_requirements.hpp"

namespace confvis::vulkan {

struct ContextOptions {
  std::string device;  // see VulkanOptions::device
  bool validation = false;
  std::function<void(const std::string&)> onValidationMessage;
};

// The capabilities of every device the instance reports, in its order.
std::vector<DeviceCapabilities> queryDevices(VkInstance instance,
                                             std::vector<VkPhysicalDevice>* handles = nullptr);

// An instance without layers, for listing devices. Throws Error(DeviceUnsupported) when no
// Vulkan driver is installed.
VkInstance createPlainInstance();

class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options);
  // On an application's device and queue (context_adopted.cpp): owns only its command pool and
  // fence; the device stays the application's.
  explicit VulkanContext(const AppDevice& app);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkQueue queue() const { return queue_; }
  const DeviceCapabilities& capabilities() const { return capabilities_; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  // Valid bits of the queue's timestamps (0: it writes none).
  std::uint32_t timestampValidBits() const { return timestampValidBits_; }

  // A memory type among typeBits with all `required` flags. Throws Error(DeviceUnsupported).
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
  // The same, nullopt where the device has none.
  std::optional<std::uint32_t> findMemoryType(std::uint32_t typeBits,
                                              VkMemoryPropertyFlags required) const;

  // Records into a fresh primary command buffer, submits it and waits for it to finish.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

 private:
  void createInstance(const ContextOptions& options);
  void createDevice();
  void release() noexcept;
  void createCommandPool();  // and the fence: for submitAndWait

  bool ownsDevice_ = true;  // false on an application's device

  std::function<void(const std::string&)> onMessage_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  DeviceCapabilities capabilities_;
  std::uint32_t queueFamily_ = 0;
  std::uint32_t timestampValidBits_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace confvis::vulkan
