#pragma once
// GPU time of part of one submission, from two timestamps: what a frame costs the device,
// without the host's submission, wait and readback (which dominate wall-clock time on a GPU).
#include <optional>

#include "context.hpp"
#include "handles.hpp"

namespace confvis::vulkan {

using UniqueQueryPool = DeviceHandle<VkQueryPool, vkDestroyQueryPool>;

class GpuStopwatch {
 public:
  explicit GpuStopwatch(const VulkanContext& context);

  bool available() const { return static_cast<bool>(pool_); }
  // Record outside a render pass, start() before stop() in the same command buffer.
  void start(VkCommandBuffer cmd);
  void stop(VkCommandBuffer cmd);
  // Seconds between start and stop once the submission has completed; nullopt where the queue
  // writes no timestamps or nothing was timed.
  std::optional<double> seconds();

 private:
  VkDevice device_;
  UniqueQueryPool pool_;  // two timestamps; empty where the queue has none
  double nanosecondsPerTick_ = 0.0;
  std::uint64_t mask_ = 0;  // the queue's valid timestamp bits
  bool recorded_ = false;
};

}  // namespace confvis::vulkan
