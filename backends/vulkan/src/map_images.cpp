#include "map_images.hpp"

#include <vector>

#include "confvis/backends/vulkan/warp_interface.hpp"

namespace confvis::vulkan {

MapImages uploadMapImages(VulkanContext& context, const RetargetMap& map) {
  const std::vector<float> geom = geomMapUploadData(map);  // validates the map
  const std::vector<float> coverage = rayMapUploadData(map);
  const auto cubeImage = [&](int faceSize) {
    ImageSpec spec;
    spec.format = kGeomMapFormat;
    spec.width = spec.height = static_cast<std::uint32_t>(faceSize);
    spec.layers = 6;
    spec.cube = true;
    spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    return Image(context, spec);
  };
  MapImages images{cubeImage(map.geom.faceSize), cubeImage(map.ray.faceSize)};
  uploadFloatImage(context, images.geom, geom.data());
  uploadFloatImage(context, images.coverage, coverage.data());
  return images;
}

}  // namespace confvis::vulkan
