#include "gpu_stopwatch.hpp"

#include <array>

#include "vk_check.hpp"

namespace confvis::vulkan {

GpuStopwatch::GpuStopwatch(const VulkanContext& context) : device_(context.device()) {
  const std::uint32_t bits = context.timestampValidBits();
  if (bits == 0) return;  // the queue writes no timestamps: seconds() stays empty
  mask_ = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  nanosecondsPerTick_ = context.limits().timestampPeriod;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2;
  VkQueryPool pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(device_, &info, nullptr, &pool), "vkCreateQueryPool");
  pool_ = UniqueQueryPool(device_, pool);
}

void GpuStopwatch::start(VkCommandBuffer cmd) {
  recorded_ = false;
  if (!pool_) return;
  vkCmdResetQueryPool(cmd, pool_.get(), 0, 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), 0);
}

void GpuStopwatch::stop(VkCommandBuffer cmd) {
  if (!pool_) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 1);
  recorded_ = true;
}

std::optional<double> GpuStopwatch::seconds() {
  if (!pool_ || !recorded_) return std::nullopt;
  recorded_ = false;
  std::array<std::uint64_t, 2> ticks{};
  check(vkGetQueryPoolResults(device_, pool_.get(), 0, 2, sizeof(ticks), ticks.data(),
                              sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults");
  const std::uint64_t elapsed = ((ticks[1] & mask_) - (ticks[0] & mask_)) & mask_;
  return 1e-9 * nanosecondsPerTick_ * static_cast<double>(elapsed);
}

}  // namespace confvis::vulkan
