#pragma once
// The Vulkan backend on an application's device, rendering into the application's images.
//
// An application (or confvis' own presenter, `confvis view`) that already has a VkInstance,
// VkPhysicalDevice, VkDevice and a graphics queue hands them over (VulkanDeviceHandles); the
// backend then creates only its own command pool, buffers, images and pipelines on that device,
// and renders a wall's eye into any VkImage of the application (VulkanImageTarget) with one
// blit from its float colour target, instead of reading the pixels back to the host.
//
// The device must have been created with Vulkan 1.1 or later and the features of
// VulkanRequiredFeatures enabled (tessellationShader, geometryShader, multiview,
// multiviewTessellationShader and multiviewGeometryShader: chain VulkanRequiredFeatures::features
// into VkDeviceCreateInfo::pNext). Validation messages go to whatever debug messenger the
// application installed on its instance.
//
// Thread-safety: as RenderBackend (one thread at a time). The backend submits to the given
// queue and waits for its own work, so the application must not use that queue from another
// thread during a call (Vulkan requires queue access to be externally synchronized).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

struct VulkanDeviceHandles {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;  // a queue with VK_QUEUE_GRAPHICS_BIT
  std::uint32_t queueFamily = 0;   // the family `queue` was taken from
};

// The device features the backend needs, chained and ready for VkDeviceCreateInfo::pNext:
//   VulkanRequiredFeatures required;  createInfo.pNext = &required.features;
// Not copyable (the chain points into itself).
// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct VulkanRequiredFeatures {
  VkPhysicalDeviceMultiviewFeatures multiview{};  // sType, pNext and the flags: set by the constructor
  VkPhysicalDeviceFeatures2 features{};
  VulkanRequiredFeatures();
  VulkanRequiredFeatures(const VulkanRequiredFeatures&) = delete;
  VulkanRequiredFeatures& operator=(const VulkanRequiredFeatures&) = delete;
};

// Where one wall's eye goes: a rectangle of an application-owned image.
//  - The image: 2D, optimal tiling, created with VK_IMAGE_USAGE_TRANSFER_DST_BIT, one mip level;
//    its format must support VK_FORMAT_FEATURE_BLIT_DST_BIT (8-bit UNORM and sRGB colour
//    formats do, as do 16- and 32-bit float ones). The backend writes array layer `layer`.
//  - Colour: the backend renders linear RGB with alpha 1 where something was drawn and 0
//    elsewhere; the blit converts it to `format`: an _SRGB format gets sRGB codes (what
//    `confvis render` writes into its PNGs), a UNORM format the linear values, clamped to [0, 1].
//  - Size: the wall is rendered at its planned size (wall resolution x
//    RenderSettings::resolutionScale) and blitted into `region` (empty: the whole image,
//    `extent`): pixel for pixel where the sizes match, else stretched with linear filtering.
//  - Layouts: the image is in `layoutBefore` when the GPU work starts (VK_IMAGE_LAYOUT_UNDEFINED:
//    its old contents may be dropped, fine for an image the call fills completely) and is left in
//    `layoutAfter` (e.g. PRESENT_SRC_KHR, SHADER_READ_ONLY_OPTIMAL, TRANSFER_SRC_OPTIMAL).
//    Several targets may share one image (the eyes of a side-by-side stereo window); they must
//    then agree on the layouts and semaphores, and the image is transitioned once before its
//    first blit and once after its last.
//  - Semaphores (binary, optional): the GPU waits for `waitSemaphore` before the first write
//    into the image (at the transfer stage: e.g. a swapchain image's acquire semaphore) and
//    signals `signalSemaphore` once the image is written and in layoutAfter (e.g. what
//    vkQueuePresentKHR waits for).
struct VulkanImageTarget {
  std::string wall;
  Eye eye = Eye::Center;
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{0, 0};      // the image's size
  std::uint32_t layer = 0;      // array layer written
  VkRect2D region{{0, 0}, {0, 0}};  // the rectangle written; extent 0 x 0: the whole image
  VkImageLayout layoutBefore = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout layoutAfter = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkSemaphore waitSemaphore = VK_NULL_HANDLE;
  VkSemaphore signalSemaphore = VK_NULL_HANDLE;
};

// Thread-safety: as RenderBackend: one thread at a time; the application must not use the
// given queue from another thread during a call.
class VulkanRenderer : public RenderBackend {
 public:
  // Renders every wall and eye the targets name (settings.walls and settings.eyes are taken from
  // them: the targets' walls, the settings' eyes that some target names, in the settings' order)
  // and writes each into its target. Returns when the GPU has finished (the semaphores serve
  // the application's own queue ordering); stats as RenderResult::stats.
  // Error(InvalidInput) naming the culprit: an unknown wall, an eye the settings do not render,
  // a null image, a region outside the image, targets of one image that disagree on layouts or
  // semaphores, a format the device cannot blit into.
  virtual FrameStats renderImages(const DisplayConfig& config, const RetargetMap* map,
                                  const RenderSettings& settings,
                                  const std::vector<VulkanImageTarget>& targets) = 0;
  // The device it renders on (its own, or the application's).
  virtual VulkanDeviceHandles deviceHandles() const = 0;
};

// On a device of its own (as makeVulkanBackend): the targets must be images of that device
// (deviceHandles()).
std::unique_ptr<VulkanRenderer> makeVulkanRenderer(const VulkanOptions& options = {});

// On the application's device. VulkanOptions::device, validation and onValidationMessage are
// ignored (the device is chosen and its instance's messenger installed by the application).
// Error(InvalidInput) when a handle is null, Error(DeviceUnsupported) when the queue's family
// lacks graphics or compute or the physical device lacks a required feature (naming it); the features must also be enabled on `device`, which Vulkan offers no
// way to check.
std::unique_ptr<VulkanRenderer> makeVulkanRendererOn(const VulkanDeviceHandles& device,
                                                     const VulkanOptions& options = {});

}  // namespace confvis
