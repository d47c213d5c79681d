// confvis devices: the Vulkan devices the loader reports, which one `--device auto` picks and
// what the others lack, so a lab can tell why the GPU it expected is not used.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

#include "command.hpp"
#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/base/error.hpp"

namespace confvis::cli {
namespace {

int runDevices(bool json) {
  const std::vector<VulkanDeviceInfo> devices = listVulkanDevices();  // throws without a driver
  bool usable = false;
  for (const VulkanDeviceInfo& d : devices) usable = usable || d.missing.empty();
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const VulkanDeviceInfo& d : devices)
      list.push_back({{"index", d.index},
                      {"name", d.name},
                      {"type", d.type},
                      {"api_version", d.apiVersion},
                      {"missing", d.missing},
                      {"automatic", d.automatic}});
    std::printf("%s\n", list.dump(2).c_str());
  } else {
    std::printf("Vulkan devices (* the one --device auto picks; the Embree backend needs none):\n");
    for (const VulkanDeviceInfo& d : devices) {
      std::printf("%s %d: %s (%s, Vulkan %s)\n", d.automatic ? "*" : " ", d.index,
                  d.name.c_str(), d.type.c_str(), d.apiVersion.c_str());
      if (d.missing.empty()) continue;
      std::string lacks;
      for (const std::string& m : d.missing) lacks += (lacks.empty() ? "" : ", ") + m;
      std::printf("    lacks: %s\n", lacks.c_str());
    }
  }
  if (!usable)
    throw Error(ErrorCode::DeviceUnsupported,
                "no Vulkan device can run confvis (each lacks what is listed); install "
                "mesa-vulkan-drivers for lavapipe, or use --backend embree");
  return 0;
}

const RegisterCommand registration{Command{
    "devices", "List the Vulkan devices, the one --device auto picks and what the others lack",
    [](CLI::App& sub) {
      auto json = std::make_shared<bool>(false);
      sub.add_flag("--json", *json, "Print the list as JSON");
      return [json] { return runDevices(*json); };
    }}};

}  // namespace
}  // namespace confvis::cli
