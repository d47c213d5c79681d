#include "map_images.hpp"

#include <vector>

#include "confvis/backends/vulkan/warp_interface.hpp"

namespace confvis::vulkan {

MapUploadData mapUploadData(const RetargetMap& map) {
  return {geomMapUploadData(map), rayMapUploadData(map), map.geom.faceSize, map.ray.faceSize};
}

MapImages recordMapImagesUpload(VulkanContext& context, VkCommandBuffer cmd,
                                const MapUploadData& data, std::vector<Buffer>& staging) {
  const auto cubeImage = [&](int faceSize) {
    ImageSpec spec;
    spec.format = kGeomMapFormat;
    spec.width = spec.height = static_cast<std::uint32_t>(faceSize);
    spec.layers = 6;
    spec.cube = true;
    spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    return Image(context, spec);
  };
  MapImages images{cubeImage(data.geomFaceSize), cubeImage(data.rayFaceSize)};
  staging.push_back(recordFloatImageUpload(context, cmd, images.geom, data.geom.data()));
  staging.push_back(recordFloatImageUpload(context, cmd, images.coverage, data.coverage.data()));
  return images;
}

MapImages uploadMapImages(VulkanContext& context, const RetargetMap& map) {
  const MapUploadData data = mapUploadData(map);  // validated before anything is recorded
  std::vector<Buffer> staging;
  MapImages images;
  context.submitAndWait(
      [&](VkCommandBuffer cmd) { images = recordMapImagesUpload(context, cmd, data, staging); });
  return images;
}

}  // namespace confvis::vulkan
