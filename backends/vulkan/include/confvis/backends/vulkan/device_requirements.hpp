#pragma once
// What confvis needs from a Vulkan device, and how one is picked. Pure functions on a plain
// description of each device, so that selection and the errors for unsuitable devices are
// testable without such a device.
#include <cstdint>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

enum class DeviceKind { Discrete, Integrated, Virtual, Cpu, Other };
const char* toString(DeviceKind kind) noexcept;

struct DeviceCapabilities {
  std::string name;
  DeviceKind kind = DeviceKind::Other;
  std::uint32_t apiVersion = 0;  // VK_MAKE_API_VERSION
  bool graphicsQueue = false;
  bool tessellationShader = false;
  bool geometryShader = false;
  bool multiview = false;
  bool multiviewTessellationShader = false;
  bool multiviewGeometryShader = false;
  std::uint32_t maxMultiviewViewCount = 0;
  std::uint32_t maxTessellationGenerationLevel = 0;
  bool float32CubeSampling = false;  // R32G32B32A32_SFLOAT cube images, sampled with linear filter
  bool float32ColorAttachment = false;
  bool depth32Attachment = false;
};

// Highest tessellation level the warp asks for (confvis_warp.glsl clamps to it).
inline constexpr std::uint32_t kRequiredTessellationLevel = 64;
// Views per multiview pass: left and right eye (a centre eye alone is one).
inline constexpr std::uint32_t kRequiredMultiviewViews = 2;

// Names of the missing requirements ("Vulkan 1.1", "tessellationShader", ...); empty = usable.
std::vector<std::string> missingRequirements(const DeviceCapabilities& device);

// Index of the device `request` names (see VulkanOptions::device). Throws
// Error(DeviceUnsupported) naming the request and listing the devices when none matches, or
// naming the device and its missing features when the chosen one cannot run confvis; with no
// request, the best usable device by kind (discrete first), and an error listing every device
// with what it lacks when none is usable.
std::size_t chooseDevice(const std::vector<DeviceCapabilities>& devices,
                         const std::string& request);

}  // namespace vulkan
}  // namespace confvis
