// VulkanContext on an application's device: the Vulkan backend rendering there
// (external_device.hpp) and the bring-your-own helpers (byo_device.hpp). The instance and device
// stay the application's; the context makes only the command pool and the fence its submissions
// are waited with.
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "context.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {

VulkanContext::VulkanContext(const VulkanDeviceHandles& handles) : VulkanContext(handles, true) {}

VulkanContext::VulkanContext(const AppDevice& app)
    : VulkanContext(VulkanDeviceHandles{VK_NULL_HANDLE, app.physicalDevice, app.device, app.queue,
                                        app.queueFamily},
                    false) {}

VulkanContext::VulkanContext(const VulkanDeviceHandles& handles, bool forRendering)
    : ownsDevice_(false) {
  const std::string who = forRendering ? "Vulkan backend on an application's device" : "AppDevice";
  if (!handles.physicalDevice || !handles.device || !handles.queue ||
      (forRendering && !handles.instance))
    throw Error(ErrorCode::InvalidInput,
                who + ": " + (forRendering ? "instance, " : "") +
                    "physicalDevice, device and queue must all be set");
  instance_ = handles.instance;
  physicalDevice_ = handles.physicalDevice;
  device_ = handles.device;
  queue_ = handles.queue;
  queueFamily_ = handles.queueFamily;
  capabilities_ = capabilitiesOf(physicalDevice_);
  const std::vector<VkQueueFamilyProperties> families = queueFamilies(physicalDevice_);
  if (queueFamily_ >= families.size())
    throw Error(ErrorCode::InvalidInput, who + ": queue family " + std::to_string(queueFamily_) +
                                             " does not exist on '" + capabilities_.name + "'");
  // Graphics for the walls' passes and blits, compute for the conformal pre-pass.
  constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if ((families[queueFamily_].queueFlags & kNeeded) != kNeeded)
    throw Error(ErrorCode::DeviceUnsupported, who + ": queue family " +
                                                  std::to_string(queueFamily_) + " of '" +
                                                  capabilities_.name + "' lacks graphics or compute");
  if (forRendering) {
    const std::vector<std::string> missing = missingRequirements(capabilities_);
    if (!missing.empty()) {
      std::string list;
      for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
      throw Error(ErrorCode::DeviceUnsupported, "Vulkan device '" + capabilities_.name +
                                                    "' lacks what confvis renders with: " + list);
    }
  }
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);
  timestampValidBits_ = families[queueFamily_].timestampValidBits;
  try {
    createCommandPool();
  } catch (...) {
    release();  // leaves the application's device and instance alone (ownsDevice_)
    throw;
  }
}

}  // namespace confvis::vulkan
