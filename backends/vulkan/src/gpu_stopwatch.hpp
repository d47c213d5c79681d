#pragma once
// GPU time of part of one submission, from two timestamps: what a frame costs the device,
// without the host's submission, wait and readback (which dominate wall-clock time on a GPU).
// Marks in between split it into intervals (the pre-pass's passes, for benchmarks).
#include <optional>
#include <vector>

#include "context.hpp"
#include "handles.hpp"

namespace confvis::vulkan {

using UniqueQueryPool = DeviceHandle<VkQueryPool, vkDestroyQueryPool>;

class GpuStopwatch {
 public:
  explicit GpuStopwatch(const VulkanContext& context);

  bool available() const { return static_cast<bool>(pool_); }
  // Record outside a render pass, start() before stop() in the same command buffer, marks
  // (at most kMaxMarks; more are ignored) in between, each after everything before it.
  void start(VkCommandBuffer cmd);
  void mark(VkCommandBuffer cmd);
  void stop(VkCommandBuffer cmd);
  // Seconds between start and stop once the submission has completed; nullopt where the queue
  // writes no timestamps or nothing was timed. `intervals`, if given, receives the seconds from
  // each timestamp to the next (start, marks, stop).
  std::optional<double> seconds(std::vector<double>* intervals = nullptr);

  static constexpr std::uint32_t kMaxMarks = 14;

 private:
  VkDevice device_;
  UniqueQueryPool pool_;  // kMaxMarks + 2 timestamps; empty where the queue has none
  double nanosecondsPerTick_ = 0.0;
  std::uint64_t mask_ = 0;  // the queue's valid timestamp bits
  std::uint32_t written_ = 0;  // timestamps recorded since start()
  bool recorded_ = false;
};

}  // namespace confvis::vulkan
