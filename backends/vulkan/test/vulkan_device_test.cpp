// Device discovery and selection, required features, and errors for bad requests.
#include <gtest/gtest.h>

#include <vulkan/vulkan.h>

#include "confvis/backends/vulkan/device_requirements.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_support.hpp"
// The module's own internals, to provoke a validation error on purpose.
#include "../src/context.hpp"
#include "../src/memory.hpp"

namespace confvis {
namespace {

using vulkan::DeviceCapabilities;
using vulkan::DeviceKind;

DeviceCapabilities capable(const std::string& name, DeviceKind kind) {
  DeviceCapabilities d;
  d.name = name;
  d.kind = kind;
  d.apiVersion = VK_API_VERSION_1_3;
  d.graphicsQueue = d.tessellationShader = d.geometryShader = true;
  d.multiview = d.multiviewTessellationShader = d.multiviewGeometryShader = true;
  d.maxMultiviewViewCount = 6;
  d.maxTessellationGenerationLevel = 64;
  d.float32CubeSampling = d.float32ColorAttachment = d.depth32Attachment = true;
  return d;
}

// Runs f, expecting Error(code) whose message contains every string of `parts`.
template <class F>
void expectError(F&& f, ErrorCode code, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    for (const std::string& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "'" << part << "' missing from: " << e.what();
  }
}

TEST(VulkanDevice, LavapipeIsInstalledAndCanRunConfvis) {
  // CI renders every Vulkan test on lavapipe; without it they cannot run at all.
  const std::vector<VulkanDeviceInfo> devices = listVulkanDevices();
  std::string seen;
  bool found = false;
  for (const VulkanDeviceInfo& d : devices) {
    seen += "\n  " + d.name + " (" + d.type + ")";
    if (d.name.find(test::kLavapipe) != std::string::npos) {
      found = true;
      EXPECT_EQ(d.type, "cpu");
      EXPECT_TRUE(d.missing.empty()) << d.name << " lacks " << d.missing.front();
    }
  }
  EXPECT_TRUE(found) << "lavapipe (llvmpipe) not found; install mesa-vulkan-drivers "
                        "(tools/setup.sh). Devices:" << seen;
}

TEST(VulkanDevice, ValidationMessagesReachTheCallback) {
  // "Zero validation messages" in the other tests means something only if messages arrive.
  std::vector<std::string> messages;
  vulkan::VulkanContext context(
      {test::kLavapipe, true, [&](const std::string& m) { messages.push_back(m); }});
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;  // invalid: VUID-VkBufferCreateInfo-size-00912
  info.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(context.device(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(context.device(), buffer, nullptr);
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-size"), std::string::npos)
      << messages.front();
}

TEST(VulkanDevice, ScenesBeyondTheTexelBufferLimitAreRejectedWithTheLimit) {
  // The conformal pre-pass reads the scene through texel buffer views: a scene needing more
  // texels than the device allows gets a clear error, not a view the driver may reject or crash
  // on. A view one texel past the limit is never created (the buffer stays one texel).
  std::vector<std::string> messages;
  vulkan::VulkanContext context(
      {test::kLavapipe, true, [&](const std::string& m) { messages.push_back(m); }});
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  const std::size_t limit = properties.limits.maxTexelBufferElements;
  vulkan::Buffer buffer(context, 16, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, false);
  expectError(
      [&] {
        vulkan::texelView(context, buffer.get(), VK_FORMAT_R32_UINT, 4, limit + 1,
                          "the scene's indices");
      },
      ErrorCode::DeviceUnsupported,
      {std::to_string(limit), std::to_string(limit + 1), "the scene's indices", "llvmpipe"});
  // Within the limit: a view, and no validation message.
  EXPECT_NE(vulkan::texelView(context, buffer.get(), VK_FORMAT_R32_UINT, 4, 4, "four").get(),
            VK_NULL_HANDLE);
  EXPECT_TRUE(messages.empty()) << messages.front();
}

TEST(VulkanDevice, AutomaticChoicePrefersARealGpuThatHasEveryFeature) {
  DeviceCapabilities weakGpu = capable("Weak GPU", DeviceKind::Discrete);
  weakGpu.multiviewGeometryShader = false;
  const std::vector<DeviceCapabilities> devices = {
      capable("llvmpipe", DeviceKind::Cpu), weakGpu, capable("iGPU", DeviceKind::Integrated),
      capable("Big GPU", DeviceKind::Discrete)};
  EXPECT_EQ(vulkan::chooseDevice(devices, ""), 3u);
  EXPECT_EQ(vulkan::chooseDevice(devices, "auto"), 3u);
  EXPECT_EQ(vulkan::chooseDevice({devices[0], devices[1]}, ""), 0u);  // lavapipe fallback
  EXPECT_EQ(vulkan::chooseDevice(devices, "2"), 2u);
  EXPECT_EQ(vulkan::chooseDevice(devices, "LLVMPIPE"), 0u);
  EXPECT_EQ(vulkan::chooseDevice(devices, "big"), 3u);
}

TEST(VulkanDevice, DevicesWithoutARequiredFeatureAreRejectedByName) {
  DeviceCapabilities noTess = capable("Old GPU", DeviceKind::Discrete);
  noTess.tessellationShader = false;
  noTess.multiviewTessellationShader = false;
  EXPECT_EQ(vulkan::missingRequirements(noTess),
            (std::vector<std::string>{"tessellationShader", "multiviewTessellationShader"}));
  expectError([&] { vulkan::chooseDevice({noTess}, "old"); }, ErrorCode::DeviceUnsupported,
              {"Old GPU", "tessellationShader"});
  expectError([&] { vulkan::chooseDevice({noTess}, ""); }, ErrorCode::DeviceUnsupported,
              {"no Vulkan device can run confvis", "Old GPU", "tessellationShader"});

  DeviceCapabilities vulkan10 = capable("Vulkan 1.0 GPU", DeviceKind::Integrated);
  vulkan10.apiVersion = VK_API_VERSION_1_0;
  vulkan10.multiview = false;
  vulkan10.float32CubeSampling = false;
  const auto missing = vulkan::missingRequirements(vulkan10);
  EXPECT_EQ(missing.front(), "Vulkan 1.1");
  EXPECT_NE(std::find(missing.begin(), missing.end(), "multiview"), missing.end());
  EXPECT_NE(std::find(missing.begin(), missing.end(), "linearly filtered float32 RGBA cube images"),
            missing.end());
  EXPECT_TRUE(vulkan::missingRequirements(capable("ok", DeviceKind::Cpu)).empty());
}

TEST(VulkanDevice, UnknownDeviceRequestsListTheDevices) {
  const std::vector<DeviceCapabilities> devices = {capable("llvmpipe", DeviceKind::Cpu)};
  expectError([&] { vulkan::chooseDevice(devices, "radeon"); }, ErrorCode::DeviceUnsupported,
              {"'radeon'", "0: llvmpipe"});
  expectError([&] { vulkan::chooseDevice(devices, "7"); }, ErrorCode::DeviceUnsupported,
              {"index 7", "llvmpipe"});
  expectError([&] { vulkan::chooseDevice({}, ""); }, ErrorCode::DeviceUnsupported,
              {"no Vulkan device"});
  // The same through the public entry point, on the real instance.
  VulkanOptions options;
  options.device = "no-such-gpu";
  expectError([&] { makeVulkanBackend(options); }, ErrorCode::DeviceUnsupported,
              {"no-such-gpu", "llvmpipe"});
}

TEST(VulkanDevice, BadOptionsAndRequestsGiveClearErrors) {
  VulkanOptions options;
  options.tessellationErrorPixels = 0.0;
  expectError([&] { makeVulkanBackend(options); }, ErrorCode::InvalidInput, {"tessellation"});

  test::ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave5");
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(config, 8);
  expectError([&] { vk->render(config, nullptr, settings); }, ErrorCode::InvalidInput,
              {"setScene"});
  vk->setScene(builtinScene("graph"));
  settings.walls = {"front", "ceiling"};
  expectError([&] { vk->render(config, nullptr, settings); }, ErrorCode::InvalidInput,
              {"ceiling"});
  settings.walls = {};
  settings.samplesPerPixel = 4;
  expectError([&] { vk->render(config, nullptr, settings); }, ErrorCode::InvalidInput, {"spp"});
  settings.samplesPerPixel = 1;
  settings.mode = RenderMode::Conformal;
  expectError([&] { vk->render(config, nullptr, settings); }, ErrorCode::InvalidInput,
              {"retarget map"});
  settings.mode = RenderMode::Plain;
  settings.eyes = {};
  expectError([&] { vk->render(config, nullptr, settings); }, ErrorCode::InvalidInput, {"eye"});
  Scene empty;
  empty.name = "empty";
  expectError([&] { vk->setScene(empty); }, ErrorCode::InvalidInput, {"empty"});
  test::expectNoValidationMessages(vk);
}

}  // namespace
}  // namespace confvis
