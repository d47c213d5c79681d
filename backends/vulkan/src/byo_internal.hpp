#pragma once
// What the bring-your-own objects hold (byo_upload.hpp): shared between their sources.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/vulkan/byo_upload.hpp"
#include "context.hpp"
#include "handles.hpp"
#include "map_images.hpp"
#include "memory.hpp"

namespace confvis::vulkan {

struct UploadedRetargetMap::Impl {
  std::unique_ptr<VulkanContext> context;  // on the application's device; destroyed last
  MapImages images;
  UniqueSampler sampler;
  glm::dvec3 reference{0.0};
  std::uint64_t fingerprint = 0;
};

struct UploadStaging::Impl {
  std::vector<Buffer> buffers;
};

}  // namespace confvis::vulkan
