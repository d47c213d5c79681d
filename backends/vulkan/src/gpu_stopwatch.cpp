#include "gpu_stopwatch.hpp"

#include <vector>

#include "vk_check.hpp"

namespace confvis::vulkan {

GpuStopwatch::GpuStopwatch(const VulkanContext& context) : device_(context.device()) {
  const std::uint32_t bits = context.timestampValidBits();
  if (bits == 0) return;  // the queue writes no timestamps: seconds() stays empty
  mask_ = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  nanosecondsPerTick_ = context.limits().timestampPeriod;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = kMaxMarks + 2;
  VkQueryPool pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(device_, &info, nullptr, &pool), "vkCreateQueryPool");
  pool_ = UniqueQueryPool(device_, pool);
}

void GpuStopwatch::start(VkCommandBuffer cmd) {
  recorded_ = false;
  written_ = 0;
  if (!pool_) return;
  vkCmdResetQueryPool(cmd, pool_.get(), 0, kMaxMarks + 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), written_++);
}

void GpuStopwatch::mark(VkCommandBuffer cmd) {
  if (!pool_ || written_ == 0 || written_ > kMaxMarks) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), written_++);
}

void GpuStopwatch::stop(VkCommandBuffer cmd) {
  if (!pool_ || written_ == 0) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), written_++);
  recorded_ = true;
}

std::optional<double> GpuStopwatch::seconds(std::vector<double>* intervals) {
  if (intervals) intervals->clear();
  if (!pool_ || !recorded_) return std::nullopt;
  recorded_ = false;
  std::vector<std::uint64_t> ticks(written_);
  check(vkGetQueryPoolResults(device_, pool_.get(), 0, written_,
                              ticks.size() * sizeof(std::uint64_t), ticks.data(),
                              sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults");
  const auto between = [&](std::size_t a, std::size_t b) {
    const std::uint64_t elapsed = ((ticks[b] & mask_) - (ticks[a] & mask_)) & mask_;
    return 1e-9 * nanosecondsPerTick_ * static_cast<double>(elapsed);
  };
  if (intervals)
    for (std::size_t i = 1; i < ticks.size(); ++i) intervals->push_back(between(i - 1, i));
  return between(0, ticks.size() - 1);
}

}  // namespace confvis::vulkan
