// VulkanContext on an application's device (bring-your-own Vulkan, byo_device.hpp): the
// instance and device stay the application's; the context makes only the command pool and the
// fence its uploads are submitted with.
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "context.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {

VulkanContext::VulkanContext(const AppDevice& app) {
  if (app.physicalDevice == VK_NULL_HANDLE || app.device == VK_NULL_HANDLE ||
      app.queue == VK_NULL_HANDLE)
    throw Error(ErrorCode::InvalidInput,
                "AppDevice: physicalDevice, device and queue must all be set");
  ownsDevice_ = false;
  physicalDevice_ = app.physicalDevice;
  device_ = app.device;
  queue_ = app.queue;
  queueFamily_ = app.queueFamily;
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);
  capabilities_.name = properties_.deviceName;
  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
  if (queueFamily_ >= familyCount)
    throw Error(ErrorCode::InvalidInput, "AppDevice: queue family " +
                                             std::to_string(queueFamily_) + " does not exist on '" +
                                             capabilities_.name + "'");
  constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if ((families[queueFamily_].queueFlags & kNeeded) != kNeeded)
    throw Error(ErrorCode::DeviceUnsupported,
                "AppDevice: queue family " + std::to_string(queueFamily_) + " of '" +
                    capabilities_.name + "' lacks graphics or compute");
  timestampValidBits_ = families[queueFamily_].timestampValidBits;
  try {
    createCommandPool();
  } catch (...) {
    release();  // leaves the application's device alone (ownsDevice_)
    throw;
  }
}

}  // namespace confvis::vulkan
