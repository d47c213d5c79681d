// Bring-your-own Vulkan (issue 25): the example application under tools/byo_vulkan_example, with
// its own instance, device and pipelines, renders through the byo_* helpers what the Vulkan
// backend renders (the same scene, baked map and walls) within the goldens' tolerance; broken
// renders (the map's two cube maps swapped, the pre-pass's lists but the flat one left out, the
// application's vertex layout described with a wrong position offset) must fail the same comparison; bad
// geometry and maps get one clear error. The example hands the pre-pass its own vertex and index
// buffers in float32, half-float and mixed layouts, and records the map upload on its own
// command buffer (recordRetargetMapUpload).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

// The example application's own headers (not an include directory of the test binary).
#include "../../../tools/byo_vulkan_example/app_device.hpp"
#include "../../../tools/byo_vulkan_example/app_renderer.hpp"
#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "confvis/backends/vulkan/byo_upload.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "../src/byo_vertex_formats.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

// The goldens' comparison (vulkan_golden_test.cpp): a pixel is bad when a channel is off by more
// than kTolerance; a render passes with at most kBudget of each wall's pixels bad.
constexpr float kTolerance = 0.05f;
constexpr double kBudget = 0.01;
constexpr int kWallPixels = 64;
constexpr int kBakeResolution = 64;

struct Fixture {
  DisplayConfig config;
  Scene scene = builtinScene("checker-sphere");
  RetargetMap map;
  RenderResult backend;
  explicit Fixture(const std::string& configName) : config(test::loadConfig(configName)) {
    map = test::bakeUncached(config, kBakeResolution);
    test::ValidatedBackend vulkan;
    vulkan->setScene(scene);
    RenderSettings settings;
    settings.mode = RenderMode::Conformal;
    settings.resolutionScale = test::scaleFor(config, kWallPixels);
    backend = vulkan->render(config, &map, settings);
    test::expectNoValidationMessages(vulkan);
  }
};

// One bake and one backend render per config for every test here.
const Fixture& fixture(const std::string& configName = "cave5") {
  static std::map<std::string, std::unique_ptr<Fixture>> fixtures;
  std::unique_ptr<Fixture>& f = fixtures[configName];
  if (!f) f = std::make_unique<Fixture>(configName);
  return *f;
}

struct AppRun {
  std::vector<WallImage> images;
  std::vector<std::string> messages;
};

AppRun runExample(const Fixture& f, const RetargetMap& map, byo_example::AppOptions options = {}) {
  AppRun run;
  options.device = test::testDevice();
  options.validation = true;
  options.onValidationMessage = [&run](const std::string& m) { run.messages.push_back(m); };
  options.resolutionScale = test::scaleFor(f.config, kWallPixels);
  run.images = byo_example::renderThroughMap(f.config, f.scene, map, options);
  return run;
}

// The largest share of bad pixels over the walls, example against backend.
double worstBadFraction(const Fixture& f, const std::vector<WallImage>& images) {
  EXPECT_EQ(images.size(), f.backend.images.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(images.size(), f.backend.images.size()); ++i) {
    EXPECT_EQ(images[i].wall, f.backend.images[i].wall);
    const test::PixelComparison c =
        test::comparePixels(images[i].image, f.backend.images[i].image, kTolerance);
    worst = std::max(worst, c.badFraction());
  }
  return worst;
}

// cave5 (the missing ceiling squeezed onto the side walls' tops) and cave3 (whose cut runs down
// the left wall's rim: the pre-pass's split along the cut and the snap to the rim at work).
// Both in the example's float32 layout and its half-float one (positions and normals
// R16G16B16A16_SFLOAT, uvs R16G16_SFLOAT, 16-bit indices), read from its own buffers.
TEST(VulkanBringYourOwn, ExampleAppMatchesTheBackendThroughTheBakedMap) {
  using Format = byo_example::AppOptions::VertexFormat;
  for (const std::string config : {"cave5", "cave3"})
    for (const Format format : {Format::Float32, Format::Half}) {
      const std::string what = config + (format == Format::Half ? " half" : " float32");
      const Fixture& f = fixture(config);
      byo_example::AppOptions options;
      options.vertexFormat = format;
      const AppRun run = runExample(f, f.map, options);
      EXPECT_TRUE(run.messages.empty()) << what << ": " << run.messages.size()
                                        << " validation message(s), first: "
                                        << (run.messages.empty() ? "" : run.messages.front());
      EXPECT_LE(worstBadFraction(f, run.images), kBudget) << what;
      // Something was drawn on every wall (the comparison alone would pass two empty renders).
      for (const WallImage& image : run.images)
        EXPECT_GT(test::drawnPixels(image.image), image.image.pixelCount() / 2)
            << what << " " << image.wall;
    }
}

// The map uploaded on the application's command buffer with the pre-pass: the same pixels as
// uploaded by its own submission, but for a few: the pre-pass appends its piece lists with
// atomics, lavapipe's compute threads vary their order from run to run, and pieces meeting at
// the same depth along the cut (both sides now reach the rim) may then draw in either order
// (4 of 12 runs differed in 1 pixel with 2 lavapipe threads, none with LP_NUM_THREADS=1). A
// wrong upload changes whole walls. The mixed layout (positions R32G32B32A32_SFLOAT, normals
// R16G16B16A16_SFLOAT, uvs R16G16_UNORM) within the tolerance.
constexpr std::size_t kDrawOrderPixels = 4;

TEST(VulkanBringYourOwn, RecordedUploadAndMixedLayoutMatch) {
  const Fixture& f = fixture();
  byo_example::AppOptions recorded;
  recorded.recordedUpload = true;
  const AppRun viaRecorded = runExample(f, f.map, recorded);
  const AppRun viaSubmitted = runExample(f, f.map);
  EXPECT_TRUE(viaRecorded.messages.empty())
      << (viaRecorded.messages.empty() ? "" : viaRecorded.messages.front());
  ASSERT_EQ(viaRecorded.images.size(), viaSubmitted.images.size());
  for (std::size_t i = 0; i < viaRecorded.images.size(); ++i)
    EXPECT_LE(test::comparePixels(viaRecorded.images[i].image, viaSubmitted.images[i].image, 0.0f)
                  .bad,
              kDrawOrderPixels)
        << viaRecorded.images[i].wall;
  byo_example::AppOptions mixed;
  mixed.vertexFormat = byo_example::AppOptions::VertexFormat::Mixed;
  const AppRun run = runExample(f, f.map, mixed);
  EXPECT_TRUE(run.messages.empty()) << (run.messages.empty() ? "" : run.messages.front());
  EXPECT_LE(worstBadFraction(f, run.images), kBudget);
}

// The staging memory lives in the returned object until the application says its submission
// completed; a malformed map is refused before anything is recorded.
TEST(VulkanBringYourOwn, RecordedUploadKeepsItsStagingUntilReleased) {
  byo_example::AppVulkan vk(test::testDevice(), false, nullptr);
  const RetargetMap map = RetargetMap::identity(8);
  std::optional<vulkan::RecordedRetargetMapUpload> upload;
  vk.submitAndWait([&](VkCommandBuffer cmd) {
    upload.emplace(vulkan::recordRetargetMapUpload(vk.appDevice(), cmd, map));
    // Both cube maps' texels, RGBA float: 2 x 6 x 8 x 8 x 16 bytes.
    EXPECT_EQ(upload->staging.bytes(), VkDeviceSize{2 * 6 * 8 * 8 * 16});
  });
  EXPECT_TRUE(upload->staging.holding());
  upload->staging.submissionCompleted();
  EXPECT_FALSE(upload->staging.holding());
  EXPECT_EQ(upload->staging.bytes(), 0u);
  EXPECT_EQ(upload->map.faceSize(), 8u);
  EXPECT_EQ(upload->map.fingerprint(), vulkan::uploadRetargetMap(vk.appDevice(), map).fingerprint());

  RetargetMap broken = map;
  broken.geom.faces[1].pixels[3] = std::nanf("");
  vk.submitAndWait([&](VkCommandBuffer cmd) {
    try {
      vulkan::recordRetargetMapUpload(vk.appDevice(), cmd, broken);
      ADD_FAILURE() << "a map with a NaN texel was recorded";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    }
  });
}

// Closed forms of the attribute formats the pre-pass reads: half floats (1.5 = 0x3E00,
// -2 = 0xC000, 0.25 = 0x3400) and 16-bit unorm (65535 = 1, 0 = 0).
TEST(VulkanBringYourOwn, VertexAttributeFormatsReadAsFloats) {
  const std::uint16_t half[4] = {0x3E00, 0xC000, 0x3400, 0x3C00};
  unsigned char bytes[16];
  std::memcpy(bytes, half, 8);
  EXPECT_EQ(vulkan::readAttribute(VK_FORMAT_R16G16B16A16_SFLOAT, bytes), glm::vec3(1.5f, -2.0f, 0.25f));
  EXPECT_EQ(vulkan::readAttribute(VK_FORMAT_R16G16_SFLOAT, bytes), glm::vec3(1.5f, -2.0f, 0.0f));
  const std::uint16_t unorm[2] = {65535, 0};
  std::memcpy(bytes, unorm, 4);
  EXPECT_EQ(vulkan::readAttribute(VK_FORMAT_R16G16_UNORM, bytes), glm::vec3(1.0f, 0.0f, 0.0f));
  const float floats[4] = {0.5f, -7.0f, 3.25f, 9.0f};
  std::memcpy(bytes, floats, 16);
  EXPECT_EQ(vulkan::readAttribute(VK_FORMAT_R32G32B32A32_SFLOAT, bytes), glm::vec3(0.5f, -7.0f, 3.25f));
  EXPECT_EQ(vulkan::readAttribute(VK_FORMAT_R32G32_SFLOAT, bytes), glm::vec3(0.5f, -7.0f, 0.0f));
  EXPECT_EQ(vulkan::attributeBytes(vulkan::AttributeRole::Position, "position",
                                   VK_FORMAT_R16G16B16A16_SFLOAT), 8u);
  EXPECT_EQ(vulkan::attributeBytes(vulkan::AttributeRole::Uv, "uv", VK_FORMAT_R16G16_UNORM), 4u);
  // A uv format for a position, a position format for a uv: refused by name.
  EXPECT_THROW(vulkan::attributeBytes(vulkan::AttributeRole::Position, "position",
                                      VK_FORMAT_R32G32_SFLOAT), Error);
  EXPECT_THROW(vulkan::attributeBytes(vulkan::AttributeRole::Uv, "uv",
                                      VK_FORMAT_R32G32B32_SFLOAT), Error);
}

TEST(VulkanBringYourOwn, BrokenAppRendersFailTheComparison) {
  const Fixture& f = fixture();
  RetargetMap swapped = f.map;
  std::swap(swapped.geom, swapped.ray);
  EXPECT_GT(worstBadFraction(f, runExample(f, swapped).images), 10 * kBudget);
  byo_example::AppOptions flatOnly;
  flatOnly.onlyFlatList = true;  // no pieces at the cut, no tessellation: holes and chords
  EXPECT_GT(worstBadFraction(f, runExample(f, f.map, flatOnly).images), kBudget);
  byo_example::AppOptions wrongLayout;
  wrongLayout.wrongPositionOffset = true;  // the unit normals read as positions
  EXPECT_GT(worstBadFraction(f, runExample(f, f.map, wrongLayout).images), 10 * kBudget);
}

TEST(VulkanBringYourOwn, WallBoundsAreTheBackendsInRadians) {
  const DisplayConfig config = test::loadConfig("cave5");  // no bake: any centre will do
  const Wall& front = config.wall("front");
  const glm::dvec3 c = config.reference + glm::dvec3(0.1, -0.2, 0.3);
  const vulkan::WallWarpBounds b = vulkan::wallWarpBounds(front, 64, 64, c);
  // The angle a pixel step along the wall subtends at c, measured at the lit rectangle's corners
  // (the farthest points): the bound may not exceed any of them (a bend of `errorAngle` stays
  // within half a pixel everywhere) and, being the smallest, lies close to the smallest.
  const Wall lit = front.litRectangle();
  const double pitch = std::min(lit.widthMetres(), lit.heightMetres()) / 64;
  const glm::dvec3 centre = 0.5 * (lit.lowerLeft + lit.upperRight());
  double smallest = 1e9;
  for (const glm::dvec3& corner : {lit.lowerLeft, lit.lowerRight, lit.upperLeft, lit.upperRight()})
    for (const glm::dvec3& axis : {lit.right(), lit.up()}) {
      const glm::dvec3 inward = glm::dot(axis, centre - corner) > 0 ? axis : -axis;
      const glm::dvec3 a0 = glm::normalize(corner - c);
      const glm::dvec3 a1 = glm::normalize(corner + pitch * inward - c);
      smallest = std::min(smallest, std::acos(std::clamp(glm::dot(a0, a1), -1.0, 1.0)));
    }
  EXPECT_LE(b.pixelAngle, smallest * (1.0 + 1e-6));
  EXPECT_GE(b.pixelAngle, 0.5 * smallest);
  EXPECT_DOUBLE_EQ(b.errorAngle, 0.5 * b.pixelAngle);
  EXPECT_DOUBLE_EQ(b.cutGapAngle, 4.0 * b.pixelAngle);
  EXPECT_NEAR(b.maxSegmentAngle, 20.0 * 3.14159265358979 / 180.0, 1e-9);
  EXPECT_THROW(vulkan::wallWarpBounds(front, 0, 64, c), Error);
}

TEST(VulkanBringYourOwn, BadGeometryAndMapsGetOneClearError) {
  byo_example::AppVulkan vk(test::testDevice(), false, nullptr);
  const float vertices[] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
  vulkan::PrepassGeometry geometry;
  geometry.vertices = vertices;
  geometry.vertexCount = 3;
  geometry.layout.stride = 12;
  geometry.indices = {0, 1, 2};
  const auto message = [&](const vulkan::PrepassGeometry& g) {
    try {
      vulkan::ConformalPrepassStep step(vk.appDevice(), g);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  vulkan::PrepassGeometry normalPastStride = geometry;
  normalPastStride.layout.normalOffset = 4;
  EXPECT_NE(message(normalPastStride).find("normal at offset 4"), std::string::npos);
  vulkan::PrepassGeometry halfPositions = geometry;
  halfPositions.layout.positionFormat = VK_FORMAT_R16G16B16_SFLOAT;  // three halves: no
  const std::string halfMessage = message(halfPositions);
  EXPECT_NE(halfMessage.find("position format VK_FORMAT_R16G16B16_SFLOAT is not supported"),
            std::string::npos) << halfMessage;
  EXPECT_NE(halfMessage.find("VK_FORMAT_R16G16B16A16_SFLOAT"), std::string::npos) << halfMessage;
  vulkan::PrepassGeometry byteUvs = geometry;
  byteUvs.layout.uvOffset = 0;
  byteUvs.layout.uvFormat = VK_FORMAT_R8G8_UNORM;
  EXPECT_NE(message(byteUvs).find("uv format VK_FORMAT_R8G8_UNORM is not supported"), std::string::npos)
      << message(byteUvs);
  vulkan::PrepassGeometry badIndex = geometry;
  badIndex.indices = {0, 1, 3};
  EXPECT_NE(message(badIndex).find("names vertex 3 of 3"), std::string::npos);
  vulkan::PrepassGeometry badMesh = geometry;
  badMesh.meshes = {{3, 3, 0}};
  EXPECT_NE(message(badMesh).find("mesh 0"), std::string::npos);

  // From buffers: checked before anything is copied.
  const auto bufferMessage = [&](const vulkan::PrepassBuffers& b) {
    try {
      vulkan::ConformalPrepassStep step(vk.appDevice(), b);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  vulkan::PrepassBuffers noBuffers;
  noBuffers.vertexCount = 3;
  noBuffers.layout.stride = 12;
  noBuffers.indexCount = 3;
  EXPECT_NE(bufferMessage(noBuffers).find("no vertex buffer"), std::string::npos);
  vulkan::PrepassBuffers byteIndices = noBuffers;
  byteIndices.indexType = VK_INDEX_TYPE_UINT8_EXT;
  EXPECT_NE(bufferMessage(byteIndices).find("index type"), std::string::npos);

  RetargetMap broken = RetargetMap::identity(8);
  broken.geom.faces[2].pixels[5] = std::nanf("");
  try {
    vulkan::uploadRetargetMap(vk.appDevice(), broken);
    ADD_FAILURE() << "a map with a NaN texel was uploaded";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace confvis
