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
#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/base/export.hpp"

// Exported in shared builds: the runtime's PresentContext is this context (as vk_check.hpp).
namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

struct ContextOptions {
  std::string device;  // see VulkanOptions::device
  bool validation = false;
  std::function<void(const std::string&)> onValidationMessage;
  // For a device that also presents to windows (confvis view): the window system's instance
  // extensions, the device extensions (VK_KHR_swapchain), and which queue families can present;
  // only devices with a graphics family that can are chosen, and that family is the queue's.
  std::vector<const char*> instanceExtensions{}, deviceExtensions{};
  std::function<bool(VkInstance, VkPhysicalDevice, std::uint32_t family)> canPresent{};
  // False: any device with a graphics queue will do (best by kind, `device` ignored), the
  // rendering features enabled where it has them (a presenter of Embree's frames needs none).
  bool requireRendering = true;
};

// One device's capabilities and queue families.
DeviceCapabilities capabilitiesOf(VkPhysicalDevice device);
std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice device);

// The capabilities of every device the instance reports, in its order.
std::vector<DeviceCapabilities> queryDevices(VkInstance instance,
                                             std::vector<VkPhysicalDevice>* handles = nullptr);

// An instance without layers, for listing devices. Throws Error(DeviceUnsupported) when no
// Vulkan driver is installed.
VkInstance createPlainInstance();

class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options);
  // On an application's device and queue (context_adopted.cpp): owns neither the device nor
  // the instance, makes only its command pool and fence, and waits for nothing when destroyed
  // (its own submissions were waited for; the application's other queues may be busy). The
  // backend rendering on the device (external_device.hpp): the instance too, and every
  // rendering requirement of the device.
  explicit VulkanContext(const VulkanDeviceHandles& handles);
  // The same for the byo_* helpers (byo_device.hpp): no instance, no rendering requirement.
  explicit VulkanContext(const AppDevice& app);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkDevice device() const { return device_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  // Resettable command buffers may be allocated from it; one thread at a time.
  VkCommandPool commandPool() const { return commandPool_; }
  VulkanDeviceHandles handles() const {
    return {instance_, physicalDevice_, device_, queue_, queueFamily_};
  }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkQueue queue() const { return queue_; }
  const DeviceCapabilities& capabilities() const { return capabilities_; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  // VK_EXT_transform_feedback with its queries is enabled on the device (only on a device this
  // context created, where the device has it): the once-a-frame warp capture (warp_capture.hpp).
  bool transformFeedback() const { return transformFeedback_; }
  // Valid bits of the queue's timestamps (0: it writes none).
  std::uint32_t timestampValidBits() const { return timestampValidBits_; }

  // A memory type among typeBits with all `required` flags. Throws Error(DeviceUnsupported).
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
  // The same, nullopt where the device has none.
  std::optional<std::uint32_t> findMemoryType(std::uint32_t typeBits,
                                              VkMemoryPropertyFlags required) const;

  // Records into a fresh primary command buffer, submits it and waits for it to finish.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);
  // The same, waiting for `wait` (at the transfer stage) before it runs and signalling `signal`.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record,
                     const std::vector<VkSemaphore>& wait, const std::vector<VkSemaphore>& signal);

 private:
  void createInstance(const ContextOptions& options);
  void pickDevice(const ContextOptions& options);
  void createDevice(const ContextOptions& options);
  // Both adopting constructors: `forRendering` as the VulkanDeviceHandles one.
  VulkanContext(const VulkanDeviceHandles& handles, bool forRendering);
  void createCommandPool();  // and the fence: for submitAndWait
  void release() noexcept;

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
  bool transformFeedback_ = false;
  bool ownsDevice_ = true;  // false on an application's device: instance and device are its
};

}  // namespace vulkan
}  // namespace confvis
