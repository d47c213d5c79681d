#pragma once
// For the tests of the Vulkan backend on an application's device: the instance, device and queue
// an application would make (validation layer on, every message collected), and its own images
// to render into and read back.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/backends/vulkan/external_device.hpp"
#include "vulkan_test_support.hpp"

namespace confvis::test {

inline void vkOk(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed");
}

class AppDevice {
 public:
  std::shared_ptr<std::vector<std::string>> messages = std::make_shared<std::vector<std::string>>();

  AppDevice() {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.apiVersion = VK_API_VERSION_1_1;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger{};
    messenger.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    messenger.pfnUserCallback = &AppDevice::onMessage;
    messenger.pUserData = messages.get();
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    info.pNext = &messenger;
    vkOk(vkCreateInstance(&info, nullptr, &handles.instance), "vkCreateInstance");
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(handles.instance, "vkCreateDebugUtilsMessengerEXT"));
    vkOk(create(handles.instance, &messenger, nullptr, &messenger_), "messenger");

    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(handles.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(handles.instance, &count, devices.data());
    std::string wanted = testDevice();  // lavapipe, as every Vulkan test renders on
    std::transform(wanted.begin(), wanted.end(), wanted.begin(), ::tolower);
    for (VkPhysicalDevice device : devices) {
      VkPhysicalDeviceProperties properties;
      vkGetPhysicalDeviceProperties(device, &properties);
      std::string name = properties.deviceName;
      std::transform(name.begin(), name.end(), name.begin(), ::tolower);
      const bool any = wanted.empty() || wanted == "auto";
      if (!handles.physicalDevice && (any || name.find(wanted) != std::string::npos))
        handles.physicalDevice = device;
    }
    if (!handles.physicalDevice)
      throw std::runtime_error("no Vulkan device named like '" + wanted + "'");
    std::vector<VkQueueFamilyProperties> families(8);
    count = 8;
    vkGetPhysicalDeviceQueueFamilyProperties(handles.physicalDevice, &count, families.data());
    while (!(families[handles.queueFamily].queueFlags & VK_QUEUE_GRAPHICS_BIT)) ++handles.queueFamily;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{};
    queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue.queueFamilyIndex = handles.queueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VulkanRequiredFeatures required;  // what external_device.hpp asks for
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.pNext = &required.features;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queue;
    vkOk(vkCreateDevice(handles.physicalDevice, &deviceInfo, nullptr, &handles.device),
         "vkCreateDevice");
    vkGetDeviceQueue(handles.device, handles.queueFamily, 0, &handles.queue);
    VkCommandPoolCreateInfo pool{};
    pool.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool.queueFamilyIndex = handles.queueFamily;
    vkOk(vkCreateCommandPool(handles.device, &pool, nullptr, &pool_), "vkCreateCommandPool");
  }

  ~AppDevice() {
    for (const Owned& image : images_) {
      vkDestroyImage(handles.device, image.image, nullptr);
      vkFreeMemory(handles.device, image.memory, nullptr);
    }
    vkDestroyCommandPool(handles.device, pool_, nullptr);
    vkDestroyDevice(handles.device, nullptr);
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(handles.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(handles.instance, messenger_, nullptr);
    vkDestroyInstance(handles.instance, nullptr);
  }
  AppDevice(const AppDevice&) = delete;
  AppDevice& operator=(const AppDevice&) = delete;

  // An image the application owns (freed with the device): transfer source and destination.
  VkImage makeImage(VkFormat format, std::uint32_t width, std::uint32_t height) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    Owned owned;
    vkOk(vkCreateImage(handles.device, &info, nullptr, &owned.image), "vkCreateImage");
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(handles.device, owned.image, &needs);
    owned.memory = allocate(needs, 0);
    vkOk(vkBindImageMemory(handles.device, owned.image, owned.memory, 0), "vkBindImageMemory");
    images_.push_back(owned);
    return owned.image;
  }

  // The 8-bit texels of an image in TRANSFER_SRC_OPTIMAL, top row first (4 bytes per pixel).
  std::vector<std::uint8_t> read(VkImage image, std::uint32_t width, std::uint32_t height) {
    const VkDeviceSize bytes = VkDeviceSize{width} * height * 4;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = bytes;
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkOk(vkCreateBuffer(handles.device, &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(handles.device, buffer, &needs);
    VkDeviceMemory memory = allocate(needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkOk(vkBindBufferMemory(handles.device, buffer, memory, 0), "vkBindBufferMemory");
    VkCommandBufferAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocateInfo.commandPool = pool_;
    allocateInfo.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vkOk(vkAllocateCommandBuffers(handles.device, &allocateInfo, &cmd), "command buffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    vkBeginCommandBuffer(cmd, &begin);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &copy);
    VkMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    vkOk(vkQueueSubmit(handles.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
    vkQueueWaitIdle(handles.queue);
    std::vector<std::uint8_t> texels(bytes);
    void* mapped = nullptr;
    vkMapMemory(handles.device, memory, 0, bytes, 0, &mapped);
    std::memcpy(texels.data(), mapped, bytes);
    vkUnmapMemory(handles.device, memory);
    vkFreeCommandBuffers(handles.device, pool_, 1, &cmd);
    vkDestroyBuffer(handles.device, buffer, nullptr);
    vkFreeMemory(handles.device, memory, nullptr);
    return texels;
  }

  VulkanDeviceHandles handles;

 private:
  struct Owned {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
  };

  VkDeviceMemory allocate(const VkMemoryRequirements& needs, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(handles.physicalDevice, &memory);
    std::uint32_t type = 0;
    while (!((needs.memoryTypeBits >> type) & 1u) ||
           (memory.memoryTypes[type].propertyFlags & flags) != flags)
      ++type;
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = needs.size;
    info.memoryTypeIndex = type;
    VkDeviceMemory allocated = VK_NULL_HANDLE;
    vkOk(vkAllocateMemory(handles.device, &info, nullptr, &allocated), "vkAllocateMemory");
    return allocated;
  }

  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                  VkDebugUtilsMessageTypeFlagsEXT,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                  void* sink) {
    static_cast<std::vector<std::string>*>(sink)->push_back(data && data->pMessage ? data->pMessage
                                                                                     : "?");
    return VK_FALSE;
  }

  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::vector<Owned> images_;
};

}  // namespace confvis::test
