#pragma once
// Bring-your-own Vulkan (issue 25): the application's device and queue, on which the byo_*
// helpers (map upload, conformal pre-pass) create their resources and submit their uploads.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

// Handles the application owns and keeps alive longer than every helper object made with them.
// The device must be Vulkan 1.1 or newer; `queue` (of `queueFamily`) must support graphics and
// compute (the pre-pass is compute work recorded on the application's command buffer; uploads
// are submitted on this queue and waited for). An application that draws the warp's
// tessellation stages (warp.tesc / warp_projected.tese / warp.tese / warp.geom, see
// backends/vulkan/README.md) enables `tessellationShader` and `geometryShader`.
// Thread-safety: the helpers submit on `queue` from the calling thread; the application must not
// use the queue from another thread at the same time (Vulkan's external synchronization rule).
struct AppDevice {
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
};

}  // namespace vulkan
}  // namespace confvis
