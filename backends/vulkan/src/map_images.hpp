#pragma once
// A RetargetMap's two cube maps as images on the device: the backend's frame renderer and the
// bring-your-own upload (byo_upload.cpp) share this.
#include <vector>

#include "confvis/conformal/retarget_map.hpp"
#include "memory.hpp"

namespace confvis::vulkan {

struct MapImages {
  Image geom;      // kGeomMapFormat cube, shader-read-only
  Image coverage;  // the ray map (its alpha: the display's coverage), the same kind
};

// Validates the map (Error(InvalidInput) naming the culprit) and uploads both cube maps.
MapImages uploadMapImages(VulkanContext& context, const RetargetMap& map);
// The texels as the images take them (geomMapUploadData, rayMapUploadData: validates the map).
struct MapUploadData {
  std::vector<float> geom, coverage;
  int geomFaceSize = 0, rayFaceSize = 0;
};
MapUploadData mapUploadData(const RetargetMap& map);
// The upload recorded on `cmd` (not submitted); the staging buffers, which must live until that
// submission has completed, are appended to `staging`.
MapImages recordMapImagesUpload(VulkanContext& context, VkCommandBuffer cmd,
                                const MapUploadData& data, std::vector<Buffer>& staging);

}  // namespace confvis::vulkan
