#include "confvis/runtime/window_presenter.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "confvis/base/error.hpp"
#include "confvis/runtime/display_window.hpp"
#include "confvis/runtime/zero_extent_injection.hpp"
#include "vk_check.hpp"

namespace confvis {

using vulkan::check;

namespace {

bool isSrgb(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB;
}

bool isBgra(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
}

// 8-bit formats only: the composed codes are sRGB already, so a UNORM swapchain shows them as
// they are and an sRGB one gets an sRGB source (the blit decodes and encodes again).
VkSurfaceFormatKHR chooseFormat(const std::vector<VkSurfaceFormatKHR>& formats, bool preferSrgb) {
  const std::vector<VkFormat> unorm = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM},
                              srgb = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB};
  for (const std::vector<VkFormat>* family : {preferSrgb ? &srgb : &unorm, preferSrgb ? &unorm : &srgb})
    for (VkFormat wanted : *family)
      for (const VkSurfaceFormatKHR& f : formats)
        if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  throw Error(ErrorCode::DeviceUnsupported,
              "the window's surface offers no 8-bit RGBA/BGRA format to present to");
}

VkPresentModeKHR choosePresentMode(const std::vector<VkPresentModeKHR>& modes, bool vsync) {
  if (!vsync)
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
      if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;  // every surface offers it
}

void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                  VkPipelineStageFlags dstStage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(commands, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

constexpr VkImageSubresourceLayers kColourLayer{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};

}  // namespace

WindowPresenter::WindowPresenter(PresentContext& context, GLFWwindow* window, bool vsync,
                                 bool preferSrgb)
    : context_(context), window_(window), vsync_(vsync), preferSrgb_(preferSrgb) {
  if (const DisplayWindow* owner = DisplayWindow::of(window_)) wall_ = owner->plan().wall;
  const VkDevice device = context_.device();
  try {
    check(glfwCreateWindowSurface(context_.instance(), window_, nullptr, &surface_),
          "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    check(vkGetPhysicalDeviceSurfaceSupportKHR(context_.physicalDevice(), context_.queueFamily(),
                                               surface_, &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported)
      throw Error(ErrorCode::DeviceUnsupported,
                  context_.deviceName() + " cannot present to this window's surface");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context_.commandPool();
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &allocate, &commands_), "vkAllocateCommandBuffers");
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    check(vkCreateSemaphore(device, &semaphore, nullptr, &imageAcquired_), "vkCreateSemaphore");
    check(vkCreateSemaphore(device, &semaphore, nullptr, &imageWritten_), "vkCreateSemaphore");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(device, &fence, nullptr, &frameDone_), "vkCreateFence");
    ensureSwapchainMatchesWindow();
    frame_ = 0;  // frames count from the first present() or acquire()
  } catch (...) {
    release();
    throw;
  }
}

WindowPresenter::~WindowPresenter() { release(); }

void WindowPresenter::release() noexcept {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  destroyContentImage();
  destroyBuffer(staging_);
  destroyBuffer(readback_);
  destroySwapchain(swapchain_);
  swapchain_ = VK_NULL_HANDLE;
  for (VkSemaphore s : renderDone_) vkDestroySemaphore(device, s, nullptr);
  renderDone_.clear();
  if (imageAcquired_) vkDestroySemaphore(device, imageAcquired_, nullptr);
  if (imageWritten_) vkDestroySemaphore(device, imageWritten_, nullptr);
  imageWritten_ = VK_NULL_HANDLE;
  if (frameDone_) vkDestroyFence(device, frameDone_, nullptr);
  if (commands_) vkFreeCommandBuffers(device, context_.commandPool(), 1, &commands_);
  if (surface_) vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
  imageAcquired_ = VK_NULL_HANDLE;
  frameDone_ = VK_NULL_HANDLE;
  commands_ = VK_NULL_HANDLE;
  surface_ = VK_NULL_HANDLE;
}

void WindowPresenter::destroySwapchain(VkSwapchainKHR swapchain) noexcept {
  if (swapchain) vkDestroySwapchainKHR(context_.device(), swapchain, nullptr);
}

VkExtent2D WindowPresenter::createSwapchain() {
  const VkPhysicalDevice physical = context_.physicalDevice();
  const VkDevice device = context_.device();
  VkSurfaceCapabilitiesKHR caps;
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps),
        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == std::numeric_limits<std::uint32_t>::max()) {
    extent.width = std::clamp<std::uint32_t>(width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp<std::uint32_t>(height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return {0, 0};  // minimised: wait for a size

  std::uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface_, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface_, &count, formats.data());
  const VkSurfaceFormatKHR format = chooseFormat(formats, preferSrgb_);
  vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface_, &count, nullptr);
  std::vector<VkPresentModeKHR> modes(count);
  vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface_, &count, modes.data());

  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(physical, format.format, &properties);
  if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
    throw Error(ErrorCode::DeviceUnsupported,
                context_.deviceName() + " cannot blit into the window's swapchain format");
  canCapture_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    throw Error(ErrorCode::DeviceUnsupported,
                "the window's swapchain images cannot be written by transfers");

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    (canCapture_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & info.compositeAlpha))
    for (VkCompositeAlphaFlagBitsKHR bit :
         {VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR, VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR,
          VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
      if (caps.supportedCompositeAlpha & bit) {
        info.compositeAlpha = bit;
        break;
      }
  info.presentMode = choosePresentMode(modes, vsync_);
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  check(vkCreateSwapchainKHR(device, &info, nullptr, &created), "vkCreateSwapchainKHR");
  destroySwapchain(swapchain_);
  swapchain_ = created;
  format_ = format.format;
  presentMode_ = info.presentMode;
  extent_ = extent;
  vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data());
  for (VkSemaphore s : renderDone_) vkDestroySemaphore(device, s, nullptr);
  renderDone_.assign(count, VK_NULL_HANDLE);
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  for (VkSemaphore& s : renderDone_)
    check(vkCreateSemaphore(device, &semaphore, nullptr, &s), "vkCreateSemaphore");
  return extent;
}

VkExtent2D WindowPresenter::surfaceExtent() {
  if (zeroExtentInjected(wall_, frame_++)) return {0, 0};
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width <= 0 || height <= 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE)
    return {0, 0};
  return {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)};
}

// True when a swapchain of the window's current size exists (recreated if the size changed or
// it went stale); false when this frame presents nothing to the window.
bool WindowPresenter::ensureSwapchainMatchesWindow() {
  switch (state_.next(surfaceExtent())) {
    case SwapchainStep::Skip:
      return false;
    case SwapchainStep::Present:
      return true;
    case SwapchainStep::Recreate:
      break;
  }
  vkDeviceWaitIdle(context_.device());  // no frame may still use the old images
  state_.created(createSwapchain());
  return state_.hasSwapchain() && !state_.stale();
}

bool WindowPresenter::acquireImage(std::uint32_t& index) {
  const VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX,
                                                imageAcquired_, VK_NULL_HANDLE, &index);
  switch (state_.afterAcquire(result)) {
    case AcquireOutcome::Use:
      return true;
    case AcquireOutcome::Skip:  // out of date: recreated at the next frame
      return false;
    case AcquireOutcome::Fail:
      break;
  }
  check(result, "vkAcquireNextImageKHR");  // throws: no failing result is VK_SUCCESS
  throw Error(ErrorCode::Internal, "vkAcquireNextImageKHR: unexpected result");
}

void WindowPresenter::ensureBuffer(Buffer& buffer, VkDeviceSize size, VkBufferUsageFlags usage) {
  if (buffer.buffer && buffer.size >= size) return;
  destroyBuffer(buffer);
  const VkDevice device = context_.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device, &info, nullptr, &buffer.buffer), "vkCreateBuffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(device, buffer.buffer, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = context_.memoryType(
      needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkAllocateMemory(device, &allocate, nullptr, &buffer.memory), "vkAllocateMemory");
  check(vkBindBufferMemory(device, buffer.buffer, buffer.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped), "vkMapMemory");
  buffer.size = size;
}

void WindowPresenter::destroyBuffer(Buffer& buffer) noexcept {
  const VkDevice device = context_.device();
  if (buffer.buffer) vkDestroyBuffer(device, buffer.buffer, nullptr);
  if (buffer.memory) vkFreeMemory(device, buffer.memory, nullptr);
  buffer = {};
}

void WindowPresenter::ensureContentImage(int width, int height) {
  const VkFormat format = isSrgb(format_) ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  if (content_ && format == contentFormat_ && width == imageWidth_ && height == imageHeight_)
    return;
  destroyContentImage();
  const VkDevice device = context_.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device, &info, nullptr, &content_), "vkCreateImage");
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(device, content_, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = context_.memoryType(needs.memoryTypeBits, 0);
  check(vkAllocateMemory(device, &allocate, nullptr, &contentMemory_), "vkAllocateMemory");
  check(vkBindImageMemory(device, content_, contentMemory_, 0), "vkBindImageMemory");
  contentFormat_ = format;
  imageWidth_ = width;
  imageHeight_ = height;
}

void WindowPresenter::destroyContentImage() noexcept {
  const VkDevice device = context_.device();
  if (content_) vkDestroyImage(device, content_, nullptr);
  if (contentMemory_) vkFreeMemory(device, contentMemory_, nullptr);
  content_ = VK_NULL_HANDLE;
  contentMemory_ = VK_NULL_HANDLE;
}

std::uint8_t* WindowPresenter::beginFrame(int width, int height) {
  finish();
  ensureBuffer(staging_, static_cast<VkDeviceSize>(width) * height * 4,
               VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  frameWidth_ = width;  // the image itself is (re)made in present(), once the format is known
  frameHeight_ = height;
  return static_cast<std::uint8_t*>(staging_.mapped);
}

void WindowPresenter::finish() {
  if (!frameInFlight_) return;
  check(vkWaitForFences(context_.device(), 1, &frameDone_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  check(vkResetFences(context_.device(), 1, &frameDone_), "vkResetFences");
  frameInFlight_ = false;
  if (captureInFlight_) collectScreenshot();
  captureInFlight_ = false;
}

bool WindowPresenter::present(bool capture) {
  if (!ensureSwapchainMatchesWindow()) return false;
  ensureContentImage(frameWidth_, frameHeight_);
  std::uint32_t index = 0;
  if (!acquireImage(index)) return false;
  capture = capture && canCapture_;
  if (capture)
    ensureBuffer(readback_, static_cast<VkDeviceSize>(extent_.width) * extent_.height * 4,
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT);

  check(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  record(commands_, index, capture);
  submitAndPresent(imageAcquired_, index, capture);
  return true;
}

void WindowPresenter::submitAndPresent(VkSemaphore wait, std::uint32_t index, bool capture) {
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &wait;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &renderDone_[index];
  check(vkQueueSubmit(context_.queue(), 1, &submit, frameDone_), "vkQueueSubmit");
  frameInFlight_ = true;
  captureInFlight_ = capture;

  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &renderDone_[index];
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  // Out of date or suboptimal: the window changed under the swapchain, recreated next frame.
  const VkResult presented = vkQueuePresentKHR(context_.queue(), &info);
  if (!state_.afterPresent(presented)) check(presented, "vkQueuePresentKHR");
}

std::optional<WindowPresenter::Acquired> WindowPresenter::acquire() {
  finish();
  if (!ensureSwapchainMatchesWindow() || !acquireImage(acquiredIndex_)) return std::nullopt;
  return Acquired{images_[acquiredIndex_], format_, extent_, imageAcquired_, imageWritten_};
}

void WindowPresenter::presentAcquired(bool capture) {
  capture = capture && canCapture_;
  if (capture)
    ensureBuffer(readback_, static_cast<VkDeviceSize>(extent_.width) * extent_.height * 4,
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  check(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands_, &begin), "vkBeginCommandBuffer");
  recordCaptureAndPresentLayout(commands_, images_[acquiredIndex_], capture);
  check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
  submitAndPresent(imageWritten_, acquiredIndex_, capture);
}

bool WindowPresenter::srgb() const { return isSrgb(format_); }

void WindowPresenter::record(VkCommandBuffer commands, std::uint32_t index, bool capture) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
  const VkImage target = images_[index];
  imageBarrier(commands, content_, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy upload{};
  upload.imageSubresource = kColourLayer;
  upload.imageExtent = {static_cast<std::uint32_t>(imageWidth_),
                        static_cast<std::uint32_t>(imageHeight_), 1};
  vkCmdCopyBufferToImage(commands, staging_.buffer, content_,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &upload);
  imageBarrier(commands, content_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
  imageBarrier(commands, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               0, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = kColourLayer;
  blit.srcOffsets[1] = {imageWidth_, imageHeight_, 1};
  blit.dstOffsets[1] = {static_cast<std::int32_t>(extent_.width),
                        static_cast<std::int32_t>(extent_.height), 1};
  // One to one (the usual case, and the screenshot tests') copies the codes exactly.
  const bool sameSize = static_cast<std::uint32_t>(imageWidth_) == extent_.width &&
                        static_cast<std::uint32_t>(imageHeight_) == extent_.height;
  vkCmdBlitImage(commands, content_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                 sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
  imageBarrier(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
  recordCaptureAndPresentLayout(commands, target, capture);
  check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
}

void WindowPresenter::recordCaptureAndPresentLayout(VkCommandBuffer commands, VkImage target,
                                                    bool capture) {
  if (capture) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = kColourLayer;
    copy.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(commands, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_.buffer, 1, &copy);
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_.buffer;
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         0, nullptr, 1, &toHost, 0, nullptr);
  }
  // The writes before (this buffer's blit, or a GPU frame's writer behind the semaphore) are
  // transfers; the read for the capture too.
  imageBarrier(commands, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
               VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, 0,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
  screenshot_.width = static_cast<int>(extent_.width);  // what the capture will hold
  screenshot_.height = static_cast<int>(extent_.height);
  screenshotBgra_ = isBgra(format_);
}

void WindowPresenter::collectScreenshot() {
  const std::size_t bytes = static_cast<std::size_t>(screenshot_.width) * screenshot_.height * 4;
  screenshot_.rgba.resize(bytes);
  std::memcpy(screenshot_.rgba.data(), readback_.mapped, bytes);
  for (std::size_t i = 0; i < bytes; i += 4) {
    if (screenshotBgra_) std::swap(screenshot_.rgba[i], screenshot_.rgba[i + 2]);
    screenshot_.rgba[i + 3] = 255;  // the window is opaque whatever the surface's alpha says
  }
}

}  // namespace confvis
