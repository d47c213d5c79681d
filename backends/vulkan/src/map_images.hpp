#pragma once
// A RetargetMap's two cube maps as images on the device: the backend's frame renderer and the
// bring-your-own upload (byo_upload.cpp) share this.
#include "confvis/conformal/retarget_map.hpp"
#include "memory.hpp"

namespace confvis::vulkan {

struct MapImages {
  Image geom;      // kGeomMapFormat cube, shader-read-only
  Image coverage;  // the ray map (its alpha: the display's coverage), the same kind
};

// Validates the map (Error(InvalidInput) naming the culprit) and uploads both cube maps.
MapImages uploadMapImages(VulkanContext& context, const RetargetMap& map);

}  // namespace confvis::vulkan
