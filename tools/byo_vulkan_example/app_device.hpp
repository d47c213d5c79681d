#pragma once
// The example application's own Vulkan instance and device (nothing from confvis): Vulkan 1.1,
// tessellation and geometry shaders and multiview enabled (the warp stages use gl_ViewIndex),
// one graphics + compute queue, a command pool and one-shot submission.
#include <cstdint>
#include <functional>
#include <string>

#include <vulkan/vulkan.h>

#include "confvis/backends/vulkan/byo_device.hpp"

namespace byo_example {

void vkCheck(VkResult result, const char* call);  // throws confvis::Error(DeviceUnsupported)

class AppVulkan {
 public:
  AppVulkan(const std::string& deviceName, bool validation,
            std::function<void(const std::string&)> onMessage);
  ~AppVulkan();
  AppVulkan(const AppVulkan&) = delete;
  AppVulkan& operator=(const AppVulkan&) = delete;

  // What the confvis helpers take.
  confvis::vulkan::AppDevice appDevice() const {
    return {physicalDevice_, device_, queue_, queueFamily_};
  }
  VkDevice device() const { return device_; }
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const;
  // Records into a fresh command buffer, submits it and waits.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

 private:
  void release() noexcept;

  std::function<void(const std::string&)> onMessage_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace byo_example
