#include "backend_factory.hpp"

#include <functional>
#include <utility>

#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/base/error.hpp"

namespace confvis::cli {

namespace {

using Factory = std::function<std::unique_ptr<RenderBackend>(const BackendOptions&)>;

const std::vector<std::pair<std::string, Factory>>& factories() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"embree",
       [](const BackendOptions& options) {
         if (options.tessellationErrorPixels)
           throw Error(ErrorCode::InvalidInput,
                       "--tess-error applies to --backend vulkan only (Embree traces every "
                       "pixel's ray through the map exactly)");
         return std::make_unique<EmbreeBackend>();
       }},
      {"vulkan",
       [](const BackendOptions& options) {
         VulkanOptions vulkan;
         vulkan.device = options.device;
         if (options.tessellationErrorPixels)
           vulkan.tessellationErrorPixels = *options.tessellationErrorPixels;
         return makeVulkanBackend(vulkan);
       }},
  };
  return table;
}

}  // namespace

std::vector<std::string> backendNames() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : factories()) names.push_back(name);
  return names;
}

std::unique_ptr<RenderBackend> makeBackend(const std::string& name,
                                           const BackendOptions& options) {
  for (const auto& [known, factory] : factories())
    if (known == name) return factory(options);
  std::string list;
  for (const std::string& known : backendNames()) list += (list.empty() ? "" : ", ") + known;
  throw Error(ErrorCode::InvalidInput, "unknown backend '" + name + "' (known: " + list + ")");
}

std::unique_ptr<RenderBackend> makeBackendOn(const VulkanDeviceHandles& device,
                                             const std::string& name,
                                             const BackendOptions& options) {
  if (name != "vulkan") return makeBackend(name, options);
  VulkanOptions vulkan;
  if (options.tessellationErrorPixels) vulkan.tessellationErrorPixels = *options.tessellationErrorPixels;
  return makeVulkanRendererOn(device, vulkan);
}

}  // namespace confvis::cli
