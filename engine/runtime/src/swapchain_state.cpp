#include "confvis/runtime/swapchain_state.hpp"

namespace confvis {

SwapchainStep SwapchainState::next(VkExtent2D surface) {
  if (surface.width == 0 || surface.height == 0) {
    // A swapchain of zero size cannot be made; the one there is may be out of date by the
    // time the surface has area again (a restored window), so it is made anew then.
    stale_ = stale_ || exists_;
    return SwapchainStep::Skip;
  }
  if (!exists_ || stale_ || surface.width != extent_.width || surface.height != extent_.height)
    return SwapchainStep::Recreate;
  return SwapchainStep::Present;
}

void SwapchainState::created(VkExtent2D extent) {
  if (extent.width == 0 || extent.height == 0) {
    stale_ = stale_ || exists_;  // none made: try again at the next frame
    return;
  }
  if (exists_) ++recreations_;
  exists_ = true;
  stale_ = false;
  extent_ = extent;
}

AcquireOutcome SwapchainState::afterAcquire(VkResult result) {
  switch (result) {
    case VK_SUCCESS:
      return AcquireOutcome::Use;
    case VK_SUBOPTIMAL_KHR:  // the image is usable; the surface wants another swapchain
      stale_ = true;
      return AcquireOutcome::Use;
    case VK_ERROR_OUT_OF_DATE_KHR:
      stale_ = true;
      return AcquireOutcome::Skip;
    default:  // the wait is unbounded, so VK_TIMEOUT and VK_NOT_READY cannot come either
      return AcquireOutcome::Fail;
  }
}

bool SwapchainState::afterPresent(VkResult result) {
  switch (result) {
    case VK_SUCCESS:
      return true;
    case VK_SUBOPTIMAL_KHR:
    case VK_ERROR_OUT_OF_DATE_KHR:  // the window changed under the swapchain
      stale_ = true;
      return true;
    default:
      return false;
  }
}

}  // namespace confvis
