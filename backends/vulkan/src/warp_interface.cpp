#include "confvis/backends/vulkan/warp_interface.hpp"

#include <cmath>
#include <string>

#include "confvis/base/error.hpp"

namespace confvis::vulkan {

namespace {

std::vector<float> cubeUploadData(const CubeMap& cube, const std::string& name) {
  const int n = cube.faceSize;
  if (n <= 0)
    throw Error(ErrorCode::InvalidInput, "retarget map: the " + name + " cube map is empty");
  for (CubeFace face : kCubeFaces) {
    const ImageRGBA& image = cube.face(face);
    if (image.width != n || image.height != n)
      throw Error(ErrorCode::InvalidInput, "retarget map: " + name + " face " + toString(face) +
                                               " is not " + std::to_string(n) + " x " +
                                               std::to_string(n));
    if (!image.allFinite())
      throw Error(ErrorCode::InvalidInput, "retarget map: " + name + " face " + toString(face) +
                                               " has non-finite texels");
  }
  const CubeMap vulkanLayout = toVulkanLayout(cube);
  std::vector<float> data;
  data.reserve(static_cast<std::size_t>(n) * n * 4 * 6);
  for (const ImageRGBA& face : vulkanLayout.faces)
    data.insert(data.end(), face.pixels.begin(), face.pixels.end());
  return data;
}

}  // namespace

std::vector<float> geomMapUploadData(const RetargetMap& map) {
  return cubeUploadData(map.geom, "geom");
}

std::vector<float> rayMapUploadData(const RetargetMap& map) {
  return cubeUploadData(map.ray, "ray");
}

namespace {

VkDescriptorSetLayoutBinding cubeMapBinding(std::uint32_t number, VkShaderStageFlags stages) {
  VkDescriptorSetLayoutBinding binding{};
  binding.binding = number;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  binding.descriptorCount = 1;
  binding.stageFlags = stages;
  return binding;
}

}  // namespace

VkDescriptorSetLayoutBinding warpLayoutBinding(VkShaderStageFlags stages) {
  return cubeMapBinding(kWarpBinding, stages);
}

VkDescriptorSetLayoutBinding coverageLayoutBinding(VkShaderStageFlags stages) {
  return cubeMapBinding(kCoverageBinding, stages);
}

std::array<VkDescriptorSetLayoutBinding, 2> warpSetLayoutBindings(VkShaderStageFlags warpStages,
                                                                  VkShaderStageFlags rimStages) {
  return {warpLayoutBinding(warpStages), coverageLayoutBinding(rimStages)};
}

VkSamplerCreateInfo warpSamplerInfo() {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  info.unnormalizedCoordinates = VK_FALSE;
  return info;
}

}  // namespace confvis::vulkan
