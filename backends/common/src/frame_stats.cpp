#include "confvis/backends/frame_stats.hpp"

#include <nlohmann/json.hpp>

#include "confvis/backends/render_plan.hpp"

namespace confvis {
namespace {

void addEmbree(const EmbreeFrameStats& e, nlohmann::json& json) {
  nlohmann::json images = nlohmann::json::array();
  for (const EmbreeImageStats& image : e.images)
    images.push_back({{"wall", image.wall},
                      {"eye", eyeName(image.eye)},
                      {"width", image.width},
                      {"height", image.height},
                      {"seconds", image.seconds}});
  json.update({{"threads", e.threads},
               {"bvh_build_seconds", e.bvhBuildSeconds},
               {"map_build_seconds", e.mapBuildSeconds},
               {"direction_table_samples", e.directionTableSamples},
               {"cached_direction_table_bytes", e.cachedDirectionTableBytes},
               {"cached_wall_grids", e.cachedWallGrids},
               {"camera_rays", e.cameraRays},
               {"occlusion_rays", e.occlusionRays},
               {"retraced_rays", e.retracedRays},
               {"shading_simd", e.shadingSimd},
               {"rays_per_second", e.raysPerSecond},
               {"images", images}});
  if (e.curvedRaySegments) json["curved_ray_segments"] = *e.curvedRaySegments;
}

void addVulkan(const VulkanFrameStats& v, nlohmann::json& json) {
  json.update({{"device", v.device},
               {"mode", v.conformal ? "conformal" : "plain"},
               {"walls", v.walls},
               {"views_per_pass", v.viewsPerPass},
               {"stereo_passes", v.multiview ? "multiview" : "per-eye"}});
  if (v.gpuSeconds) json["gpu_seconds"] = *v.gpuSeconds;
  if (!v.conformalPrepass) return;
  const VulkanConformalStats& c = *v.conformalPrepass;
  json.update({{"tessellation_error_pixels", c.tessellationErrorPixels},
               {"tessellation", c.tessellation},
               {"triangles_split_before_warp", c.trianglesSplitBeforeWarp},
               {"triangles_drawn_flat", c.trianglesDrawnFlat},
               {"triangles_tessellated", c.trianglesTessellated},
               {"triangles_through_geometry_shader", c.trianglesThroughGeometryShader},
               {"triangles_split_along_cut", c.trianglesSplitAlongCut},
               {"prepass_seconds", c.prepassSeconds},
               {"prepass_reused", c.prepassReused}});
  if (c.prepassGpuSeconds) json["prepass_gpu_seconds"] = *c.prepassGpuSeconds;
  if (!c.passGpuSeconds.empty()) json["prepass_pass_gpu_seconds"] = c.passGpuSeconds;
}

}  // namespace

nlohmann::json toJson(const FrameStats& stats) {
  nlohmann::json json = {{"backend", stats.backend}};
  // The keys render.json has always had: each backend names the shared figures its own way.
  const bool embree = stats.embree.has_value();
  json[embree ? "render_seconds" : "seconds"] = stats.seconds;
  json[embree ? "scene_triangles" : "triangles"] = stats.sceneTriangles;
  if (stats.embree) addEmbree(*stats.embree, json);
  if (stats.vulkan) addVulkan(*stats.vulkan, json);
  return json;
}

}  // namespace confvis
