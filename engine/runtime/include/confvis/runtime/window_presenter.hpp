#pragma once
// Presents one window's frames with a Vulkan swapchain: the frame's pixels (8-bit sRGB codes,
// composed on the CPU from the renderer's wall images) go through a host-visible staging buffer
// into an image and are blitted into the swapchain image, stretched to the window. The
// swapchain is recreated when the window is resized or the surface reports it out of date;
// a minimised window (a 0 x 0 surface) presents nothing and gets a new swapchain once it has an
// area again (SwapchainState decides: swapchain_state.hpp). One frame in flight per window.
// Frames the GPU renders (the Vulkan backend on the presenting device) skip the staging buffer:
// acquire() hands out the swapchain image, the backend blits each eye straight into it, and
// presentAcquired() presents it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"
#include "confvis/runtime/present_context.hpp"
#include "confvis/runtime/swapchain_state.hpp"

struct GLFWwindow;

namespace confvis CONFVIS_API {

// A presented frame read back from the swapchain image: RGBA 8-bit codes, top row first.
struct Screenshot {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// Thread-safety: not thread-safe; one thread presents (the one that owns the window and the
// PresentContext's queue).
class WindowPresenter {
 public:
  // vsync: FIFO; otherwise MAILBOX, else IMMEDIATE, where the surface offers them (else FIFO).
  // preferSrgb: an sRGB swapchain format first (for GPU frames, whose linear values the blit
  // encodes), else 8-bit UNORM first (for composed sRGB codes).
  WindowPresenter(PresentContext& context, GLFWwindow* window, bool vsync,
                  bool preferSrgb = false);
  ~WindowPresenter();
  WindowPresenter(const WindowPresenter&) = delete;
  WindowPresenter& operator=(const WindowPresenter&) = delete;

  // Waits for this window's previous frame, then returns where to write width x height RGBA
  // pixels (sRGB codes, top row first) for the next present().
  std::uint8_t* beginFrame(int width, int height);
  // Presents what beginFrame's pixels hold. False when nothing was presented (minimised, or the
  // swapchain was out of date and is recreated for the next frame). capture: the swapchain image
  // is also read back (latestScreenshot, after the next beginFrame or finish()).
  bool present(bool capture);
  // Waits for the last frame; its screenshot is then complete.
  void finish();
  const Screenshot& latestScreenshot() const { return screenshot_; }

  // GPU frames: the swapchain image to write, after the window's previous frame has finished;
  // nullopt when nothing can be presented now (minimised, or out of date and recreated for the
  // next frame). The writer waits for `acquired` before writing, signals `written` when done,
  // and leaves the image in TRANSFER_SRC_OPTIMAL.
  struct Acquired {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkSemaphore acquired = VK_NULL_HANDLE, written = VK_NULL_HANDLE;
  };
  std::optional<Acquired> acquire();
  // Presents the image acquire() gave once `written` is signalled (capture: as present()).
  void presentAcquired(bool capture);
  // The swapchain encodes sRGB (a GPU frame's linear values come out as the composed codes).
  bool srgb() const;

  int recreations() const { return state_.recreations(); }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  VkExtent2D extent() const { return extent_; }
  VkFormat format() const { return format_; }

 private:
  struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkDeviceSize size = 0;
  };

  void release() noexcept;
  // The extent of the swapchain made, 0 x 0 when the surface has no area to make one for.
  VkExtent2D createSwapchain();
  // The window's surface extent this frame: 0 x 0 while minimised (or injected so,
  // zero_extent_injection.hpp).
  VkExtent2D surfaceExtent();
  void destroySwapchain(VkSwapchainKHR swapchain) noexcept;
  bool ensureSwapchainMatchesWindow();
  void ensureBuffer(Buffer& buffer, VkDeviceSize size, VkBufferUsageFlags usage);
  void destroyBuffer(Buffer& buffer) noexcept;
  void ensureContentImage(int width, int height);
  void destroyContentImage() noexcept;
  void record(VkCommandBuffer commands, std::uint32_t imageIndex, bool capture);
  // The image is in TRANSFER_SRC_OPTIMAL: the optional copy for a screenshot, then PRESENT_SRC.
  void recordCaptureAndPresentLayout(VkCommandBuffer commands, VkImage target, bool capture);
  // Submits commands_ (waiting for `wait` at the transfer stage) and presents images_[index].
  void submitAndPresent(VkSemaphore wait, std::uint32_t index, bool capture);
  // Acquires the next image into `index`; false when this frame presents nothing.
  bool acquireImage(std::uint32_t& index);
  void collectScreenshot();

  PresentContext& context_;
  GLFWwindow* window_;
  bool vsync_;
  bool preferSrgb_;
  std::string wall_;  // of the DisplayWindow that made window_ ("" for another window)
  long frame_ = 0;    // frames asked for so far (for the zero-extent injection)
  SwapchainState state_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{0, 0};
  std::vector<VkImage> images_;
  std::vector<VkSemaphore> renderDone_;  // per swapchain image: a present may still hold one
  bool canCapture_ = false;

  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkSemaphore imageAcquired_ = VK_NULL_HANDLE;
  VkSemaphore imageWritten_ = VK_NULL_HANDLE;  // GPU frames: signalled by their writer
  std::uint32_t acquiredIndex_ = 0;
  VkFence frameDone_ = VK_NULL_HANDLE;
  bool frameInFlight_ = false;
  bool captureInFlight_ = false;

  Buffer staging_, readback_;
  VkImage content_ = VK_NULL_HANDLE;
  VkDeviceMemory contentMemory_ = VK_NULL_HANDLE;
  VkFormat contentFormat_ = VK_FORMAT_UNDEFINED;
  int imageWidth_ = 0, imageHeight_ = 0;  // of content_
  int frameWidth_ = 0, frameHeight_ = 0;  // asked for by beginFrame
  Screenshot screenshot_;
  bool screenshotBgra_ = false;
};

}  // namespace confvis
