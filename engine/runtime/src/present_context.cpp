#include "confvis/runtime/present_context.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "confvis/base/error.hpp"
#include "context.hpp"

namespace confvis {

namespace {

constexpr std::size_t kKeptMessages = 20;

vulkan::ContextOptions contextOptions(const PresentContextOptions& options,
                                      std::function<void(const std::string&)> sink) {
  std::uint32_t glfwCount = 0;
  const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
  if (!glfwExtensions)
    throw Error(ErrorCode::DeviceUnsupported,
                "the Vulkan loader offers no window-system surface extension (is a Vulkan "
                "driver installed and a display reachable?)");
  vulkan::ContextOptions context;
  context.device = options.device;
  context.validation = options.validation;
  context.onValidationMessage = std::move(sink);
  context.instanceExtensions.assign(glfwExtensions, glfwExtensions + glfwCount);
  context.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  context.canPresent = [](VkInstance instance, VkPhysicalDevice device, std::uint32_t family) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
  };
  context.requireRendering = options.forRendering;
  return context;
}

}  // namespace

PresentContext::PresentContext(const PresentContextOptions& options) {
  validation_.enabled = options.validation;
  context_ = std::make_unique<vulkan::VulkanContext>(
      contextOptions(options, [this](const std::string& message) { count(message); }));
}

PresentContext::~PresentContext() = default;

VkInstance PresentContext::instance() const { return context_->instance(); }
VkPhysicalDevice PresentContext::physicalDevice() const { return context_->physicalDevice(); }
VkDevice PresentContext::device() const { return context_->device(); }
VkQueue PresentContext::queue() const { return context_->queue(); }
std::uint32_t PresentContext::queueFamily() const { return context_->queueFamily(); }
VkCommandPool PresentContext::commandPool() const { return context_->commandPool(); }
VulkanDeviceHandles PresentContext::handles() const { return context_->handles(); }
const std::string& PresentContext::deviceName() const { return context_->capabilities().name; }

std::uint32_t PresentContext::memoryType(std::uint32_t typeBits,
                                         VkMemoryPropertyFlags required) const {
  return context_->memoryType(typeBits, required);
}

ValidationReport PresentContext::validation() const {
  const std::lock_guard lock(validationMutex_);
  return validation_;
}

// The context's messenger prefixes each message with its severity (context.cpp).
void PresentContext::count(const std::string& message) {
  const std::lock_guard lock(validationMutex_);
  if (message.rfind("validation error: ", 0) == 0) ++validation_.errors;
  else ++validation_.warnings;
  if (validation_.messages.size() < kKeptMessages) validation_.messages.push_back(message);
}

}  // namespace confvis
