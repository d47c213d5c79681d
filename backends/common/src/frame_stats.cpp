#include "confvis/backends/frame_stats.hpp"

#include <type_traits>

#include "confvis/base/error.hpp"

namespace confvis {
namespace {

template <typename T>
std::optional<T> optionalKey(const nlohmann::json& stats, const char* key) {
  const auto it = stats.find(key);
  if (it == stats.end() || it->is_null()) return std::nullopt;
  if constexpr (std::is_same_v<T, bool>) {
    if (!it->is_boolean()) return std::nullopt;
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!it->is_string()) return std::nullopt;
  } else {
    if (!it->is_number()) return std::nullopt;
  }
  return it->get<T>();
}

template <typename T>
T requiredKey(const nlohmann::json& stats, const char* key) {
  if (const std::optional<T> value = optionalKey<T>(stats, key)) return *value;
  throw Error(ErrorCode::InvalidInput,
              std::string("frame statistics: no valid \"") + key + "\" (not a backend's result)");
}

}  // namespace

FrameStats frameStats(const RenderResult& result) {
  const nlohmann::json& s = result.stats;
  if (!s.is_object())
    throw Error(ErrorCode::InvalidInput, "frame statistics: not a JSON object");
  FrameStats stats;
  stats.backend = requiredKey<std::string>(s, "backend");
  const bool embree = stats.backend == "embree";
  stats.seconds = requiredKey<double>(s, embree ? "render_seconds" : "seconds");
  stats.sceneTriangles =
      optionalKey<std::uint64_t>(s, embree ? "scene_triangles" : "triangles").value_or(0);
  stats.gpuSeconds = optionalKey<double>(s, "gpu_seconds");
  stats.device = optionalKey<std::string>(s, "device").value_or("");
  stats.mapBuildSeconds = optionalKey<double>(s, "map_build_seconds");
  stats.cameraRays = optionalKey<std::uint64_t>(s, "camera_rays");
  stats.retracedRays = optionalKey<std::uint64_t>(s, "retraced_rays");
  stats.occlusionRays = optionalKey<std::uint64_t>(s, "occlusion_rays");
  stats.raysPerSecond = optionalKey<double>(s, "rays_per_second");
  stats.threads = optionalKey<int>(s, "threads");
  stats.prepassSeconds = optionalKey<double>(s, "prepass_seconds");
  stats.prepassGpuSeconds = optionalKey<double>(s, "prepass_gpu_seconds");
  stats.prepassReused = optionalKey<bool>(s, "prepass_reused");
  return stats;
}

}  // namespace confvis
