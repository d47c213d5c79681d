#pragma once
// What a window's presenter does each frame, decided from what the surface and the swapchain
// calls report, apart from Vulkan itself (so that every case is unit-tested, the minimised
// window's 0 x 0 surface included, which Xvfb never gives).
//
// In use (window_presenter.cpp):
//   SwapchainState state;
//   switch (state.next(surfaceExtent)) {        // 0 x 0 while minimised
//     case SwapchainStep::Skip: return false;   // present nothing, create nothing
//     case SwapchainStep::Recreate: state.created(createSwapchain()); break;  // 0 x 0: none
//     case SwapchainStep::Present: break;
//   }
//   if (state.afterAcquire(vkAcquireNextImageKHR(...)) == AcquireOutcome::Skip) return false;
//   ...
//   state.afterPresent(vkQueuePresentKHR(...));
#include <cstdint>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

enum class SwapchainStep {
  Skip,      // the surface has no area (minimised): present nothing, create no swapchain
  Recreate,  // (re)create the swapchain at the surface's extent, then present
  Present,   // the swapchain matches the surface: acquire and present
};

enum class AcquireOutcome {
  Use,   // write and present the image (a suboptimal one too; recreated at the next frame)
  Skip,  // out of date: nothing presented this frame, recreated at the next
  Fail,  // an error the presenter cannot recover from (device or surface lost, ...)
};

// Thread-safety: not thread-safe; a value owned by one presenter.
class SwapchainState {
 public:
  // Before each frame, with the surface's extent now (0 x 0 while minimised). A surface without
  // area leaves the swapchain stale: it is recreated once the surface has area again.
  SwapchainStep next(VkExtent2D surface);
  // After a Recreate step: the extent of the swapchain made, or 0 x 0 when none could be made
  // (the surface reported no area when asked again); the next frame then tries again.
  void created(VkExtent2D extent);
  // After vkAcquireNextImageKHR.
  AcquireOutcome afterAcquire(VkResult result);
  // After vkQueuePresentKHR: false for an error the presenter cannot recover from.
  bool afterPresent(VkResult result);

  bool hasSwapchain() const { return exists_; }
  VkExtent2D extent() const { return extent_; }  // of the current swapchain (kept while stale)
  bool stale() const { return stale_; }
  int recreations() const { return recreations_; }  // swapchains made after the first

 private:
  bool exists_ = false;  // a swapchain was made (it is kept, stale or not, until replaced)
  bool stale_ = false;   // out of date, suboptimal or the surface lost its area: recreate
  VkExtent2D extent_{0, 0};
  int recreations_ = 0;
};

}  // namespace confvis
