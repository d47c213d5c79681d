// The Vulkan backend on an application's instance and device, writing into the application's
// images (external_device.hpp): the texels equal what render() reads back, converted to the
// image's format; side-by-side eyes land in their own halves; bad targets are one clear error;
// the validation layer on the application's instance reports nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_app_device.hpp"

namespace confvis {
namespace {

using test::AppDevice;

constexpr std::uint32_t kSize = 48;

// Texels of `region` in an RGBA8 image `imageWidth` wide against a rendered image: RGB as the
// format encodes the linear values (sRGB or UNORM), alpha as UNORM; one code of rounding allowed.
// Returns the pixels off by more.
std::size_t badTexels(const std::vector<std::uint8_t>& texels, std::uint32_t imageWidth,
                      VkRect2D region, const ImageRGBA& rendered, bool srgb) {
  std::size_t bad = 0;
  for (std::uint32_t y = 0; y < region.extent.height; ++y)
    for (std::uint32_t x = 0; x < region.extent.width; ++x) {
      const float* linear = rendered.at(static_cast<int>(x), static_cast<int>(y));
      const std::uint8_t* texel =
          &texels[((region.offset.y + y) * imageWidth + region.offset.x + x) * 4];
      bool off = false;
      for (int k = 0; k < 4; ++k) {
        const float v = std::clamp(linear[k], 0.0f, 1.0f);
        const long expected = std::lround(255.0f * (srgb && k < 3 ? linearToSrgb(v) : v));
        off = off || std::abs(expected - long(texel[k])) > 1;
      }
      bad += off;
    }
  return bad;
}

RenderSettings plainSettings(const DisplayConfig& config) {
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(config, static_cast<int>(kSize));
  return settings;
}

TEST(VulkanOnAppDevice, WritesTheApplicationsImagesAsRenderReadsBack) {
  AppDevice app;
  const std::unique_ptr<VulkanRenderer> vk = makeVulkanRendererOn(app.handles);
  EXPECT_EQ(vk->deviceHandles().device, app.handles.device);
  const DisplayConfig config = test::loadConfig("cave6");
  vk->setScene(builtinScene("checker-sphere"));
  RenderSettings settings = plainSettings(config);
  settings.walls = {"front", "left"};
  const RenderResult reference = vk->render(config, nullptr, settings);

  const VkImage front = app.makeImage(VK_FORMAT_R8G8B8A8_SRGB, kSize, kSize);
  const VkImage left = app.makeImage(VK_FORMAT_R8G8B8A8_UNORM, kSize, kSize);
  const std::vector<VulkanImageTarget> targets = {
      {"front", Eye::Center, front, VK_FORMAT_R8G8B8A8_SRGB, {kSize, kSize}, 0, {},
       VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
      {"left", Eye::Center, left, VK_FORMAT_R8G8B8A8_UNORM, {kSize, kSize}, 0, {},
       VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL}};
  settings.walls.clear();  // the targets name them
  const FrameStats stats = vk->renderImages(config, nullptr, settings, targets);
  ASSERT_TRUE(stats.vulkan.has_value());
  EXPECT_EQ(stats.vulkan->walls, 2u);
  const VkRect2D whole{{0, 0}, {kSize, kSize}};
  const std::vector<std::uint8_t> frontTexels = app.read(front, kSize, kSize);
  const std::vector<std::uint8_t> leftTexels = app.read(left, kSize, kSize);
  EXPECT_EQ(badTexels(frontTexels, kSize, whole, test::imageOf(reference, "front").image, true), 0u);
  EXPECT_EQ(badTexels(leftTexels, kSize, whole, test::imageOf(reference, "left").image, false), 0u);
  // The comparison can fail: the front wall's texels are not the left wall's image.
  EXPECT_GT(badTexels(frontTexels, kSize, whole, test::imageOf(reference, "left").image, true),
            kSize * kSize / 4);
  EXPECT_TRUE(app.messages->empty()) << app.messages->size() << " validation message(s), first: "
                                     << (app.messages->empty() ? "" : app.messages->front());
}

TEST(VulkanOnAppDevice, SideBySideEyesShareOneImageWithSemaphores) {
  AppDevice app;
  {
    const std::unique_ptr<VulkanRenderer> vk = makeVulkanRendererOn(app.handles);
    const DisplayConfig config = test::loadConfig("cave6");
    vk->setScene(builtinScene("checker-sphere"));
    RenderSettings settings = plainSettings(config);
    settings.walls = {"front"};
    settings.eyes = {Eye::Left, Eye::Right};
    settings.head.position = {0.0, 0.0, 0.2};  // off centre: the eyes see different pixels
    const RenderResult reference = vk->render(config, nullptr, settings);

    const VkImage image = app.makeImage(VK_FORMAT_B8G8R8A8_SRGB, 2 * kSize, kSize);
    const VkRect2D leftHalf{{0, 0}, {kSize, kSize}}, rightHalf{{int(kSize), 0}, {kSize, kSize}};
    VulkanImageTarget left{"front", Eye::Left, image, VK_FORMAT_B8G8R8A8_SRGB, {2 * kSize, kSize},
                           0, leftHalf, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    VkSemaphoreCreateInfo semaphoreInfo{};
    semaphoreInfo.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore done = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateSemaphore(app.handles.device, &semaphoreInfo, nullptr, &done), VK_SUCCESS);
    left.signalSemaphore = done;
    VulkanImageTarget right = left;
    right.eye = Eye::Right;
    right.region = rightHalf;
    vk->renderImages(config, nullptr, settings, {left, right});
    // The application's next submission waits for the semaphore, as a present would.
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence fence = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateFence(app.handles.device, &fenceInfo, nullptr, &fence), VK_SUCCESS);
    const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &done;
    submit.pWaitDstStageMask = &stage;
    ASSERT_EQ(vkQueueSubmit(app.handles.queue, 1, &submit, fence), VK_SUCCESS);
    EXPECT_EQ(vkWaitForFences(app.handles.device, 1, &fence, VK_TRUE, 10'000'000'000ull),
              VK_SUCCESS)
        << "the semaphore was signalled";
    vkDestroyFence(app.handles.device, fence, nullptr);
    vkDestroySemaphore(app.handles.device, done, nullptr);

    std::vector<std::uint8_t> texels = app.read(image, 2 * kSize, kSize);
    for (std::size_t i = 0; i < texels.size(); i += 4) std::swap(texels[i], texels[i + 2]);  // BGRA
    const ImageRGBA& leftEye = test::imageOf(reference, "front", Eye::Left).image;
    const ImageRGBA& rightEye = test::imageOf(reference, "front", Eye::Right).image;
    EXPECT_EQ(badTexels(texels, 2 * kSize, leftHalf, leftEye, true), 0u);
    EXPECT_EQ(badTexels(texels, 2 * kSize, rightHalf, rightEye, true), 0u);
    // The eyes differ, so swapped halves fail.
    EXPECT_GT(badTexels(texels, 2 * kSize, leftHalf, rightEye, true), 20u);
  }
  EXPECT_TRUE(app.messages->empty()) << app.messages->size() << " validation message(s), first: "
                                     << (app.messages->empty() ? "" : app.messages->front());
}

TEST(VulkanOnAppDevice, BadTargetsAreOneClearError) {
  AppDevice app;
  const std::unique_ptr<VulkanRenderer> vk = makeVulkanRendererOn(app.handles);
  const DisplayConfig config = test::loadConfig("cave6");
  vk->setScene(builtinScene("checker-sphere"));
  const RenderSettings settings = plainSettings(config);
  const VkImage image = app.makeImage(VK_FORMAT_R8G8B8A8_UNORM, kSize, kSize);
  const VulkanImageTarget good{"front", Eye::Center, image, VK_FORMAT_R8G8B8A8_UNORM,
                               {kSize, kSize}, 0, {}, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  const auto message = [&](std::vector<VulkanImageTarget> targets) -> std::string {
    try {
      vk->renderImages(config, nullptr, settings, targets);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      return e.what();
    }
    return "no error";
  };
  VulkanImageTarget unknown = good;
  unknown.wall = "attic";
  EXPECT_NE(message({unknown}).find("attic"), std::string::npos);
  VulkanImageTarget eye = good;
  eye.eye = Eye::Left;
  EXPECT_NE(message({eye}).find("do not render that eye"), std::string::npos);
  VulkanImageTarget outside = good;
  outside.region = {{int(kSize) / 2, 0}, {kSize, kSize}};
  EXPECT_NE(message({outside}).find("leaves the 48x48 image"), std::string::npos);
  VulkanImageTarget other = good;
  other.wall = "left";
  other.layoutAfter = VK_IMAGE_LAYOUT_GENERAL;
  EXPECT_NE(message({good, other}).find("not its layouts and semaphores"), std::string::npos);
  EXPECT_NE(message({}).find("no target"), std::string::npos);
  VulkanDeviceHandles none = app.handles;
  none.queue = VK_NULL_HANDLE;
  EXPECT_THROW((void)makeVulkanRendererOn(none), Error);
}

}  // namespace
}  // namespace confvis
