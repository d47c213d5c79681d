#include "confvis/backends/vulkan/device_requirements.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include <vulkan/vulkan.h>

#include "confvis/base/error.hpp"

namespace confvis::vulkan {
namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Higher is preferred: a real GPU before a software renderer.
int kindRank(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Discrete: return 4;
    case DeviceKind::Integrated: return 3;
    case DeviceKind::Virtual: return 2;
    case DeviceKind::Cpu: return 1;
    case DeviceKind::Other: return 0;
  }
  return 0;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string describe(const std::vector<DeviceCapabilities>& devices) {
  std::string out;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const auto missing = missingRequirements(devices[i]);
    out += "\n  " + std::to_string(i) + ": " + devices[i].name + " (" +
           toString(devices[i].kind) + ")" +
           (missing.empty() ? "" : ", lacks " + joined(missing));
  }
  return out;
}

bool isIndex(const std::string& s) {
  return !s.empty() && s.size() < 6 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::size_t usableOrThrow(const std::vector<DeviceCapabilities>& devices, std::size_t index) {
  const auto missing = missingRequirements(devices[index]);
  if (!missing.empty())
    throw Error(ErrorCode::DeviceUnsupported,
                "Vulkan device '" + devices[index].name + "' cannot run confvis: it lacks " +
                    joined(missing));
  return index;
}

}  // namespace

const char* toString(DeviceKind kind) noexcept {
  switch (kind) {
    case DeviceKind::Discrete: return "discrete";
    case DeviceKind::Integrated: return "integrated";
    case DeviceKind::Virtual: return "virtual";
    case DeviceKind::Cpu: return "cpu";
    case DeviceKind::Other: return "other";
  }
  return "other";
}

std::vector<std::string> missingRequirements(const DeviceCapabilities& d) {
  std::vector<std::string> missing;
  if (d.apiVersion < VK_API_VERSION_1_1) missing.push_back("Vulkan 1.1");
  if (!d.graphicsQueue) missing.push_back("a graphics queue");
  if (!d.tessellationShader) missing.push_back("tessellationShader");
  if (!d.geometryShader) missing.push_back("geometryShader");
  if (!d.multiview) missing.push_back("multiview");
  if (!d.multiviewTessellationShader) missing.push_back("multiviewTessellationShader");
  if (!d.multiviewGeometryShader) missing.push_back("multiviewGeometryShader");
  if (d.maxMultiviewViewCount < kRequiredMultiviewViews)
    missing.push_back("maxMultiviewViewCount >= " + std::to_string(kRequiredMultiviewViews));
  if (d.maxTessellationGenerationLevel < kRequiredTessellationLevel)
    missing.push_back("maxTessellationGenerationLevel >= " +
                      std::to_string(kRequiredTessellationLevel));
  if (!d.float32CubeSampling) missing.push_back("linearly filtered float32 RGBA cube images");
  if (!d.float32ColorAttachment) missing.push_back("float32 RGBA colour attachments");
  if (!d.depth32Attachment) missing.push_back("D32_SFLOAT depth attachments");
  return missing;
}

std::size_t chooseDevice(const std::vector<DeviceCapabilities>& devices,
                         const std::string& request) {
  if (devices.empty())
    throw Error(ErrorCode::DeviceUnsupported,
                "no Vulkan device found (install a GPU driver or mesa-vulkan-drivers for lavapipe)");
  if (request.empty() || request == "auto") {
    std::size_t best = devices.size();
    for (std::size_t i = 0; i < devices.size(); ++i)
      if (missingRequirements(devices[i]).empty() &&
          (best == devices.size() || kindRank(devices[i].kind) > kindRank(devices[best].kind)))
        best = i;
    if (best == devices.size())
      throw Error(ErrorCode::DeviceUnsupported,
                  "no Vulkan device can run confvis:" + describe(devices));
    return best;
  }
  if (isIndex(request)) {
    const std::size_t index = std::stoul(request);
    if (index >= devices.size())
      throw Error(ErrorCode::DeviceUnsupported, "Vulkan device index " + request +
                                                    " out of range; devices:" + describe(devices));
    return usableOrThrow(devices, index);
  }
  const std::string wanted = lowercase(request);
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (lowercase(devices[i].name).find(wanted) != std::string::npos)
      return usableOrThrow(devices, i);
  throw Error(ErrorCode::DeviceUnsupported,
              "no Vulkan device matches '" + request + "'; devices:" + describe(devices));
}

}  // namespace confvis::vulkan
