// Vulkan against Embree on a scene file shaped like real content (issue 23, point 4):
// tests/data/scenes/crosscheck-room.obj holds a textured ground plane 1.2 m under the viewer and
// a ceiling 0.6 m above it (each two triangles 40 m across: large near triangles, the ceiling
// squeezed into the tops of the CAVE's side walls by the map), thin poles and wires (8-12 cm, a
// few pixels on 96-pixel walls) and a texture (checker.png, repeated). Plain and conformal, the
// centre eye and both stereo eyes, the whole display and scene in metres, millimetres (x 1e-3) and
// kilometres (x 1e3); per-pixel tolerance and a bad-pixel budget, and deliberately broken renders
// (the thin geometry or the texture lost, wide triangles drawn whole) that must fail it.
//
// Found by this suite: conformal Vulkan with the head 20 cm off the warp's centre differs from
// Embree at the top of the front and left walls, 11-33 % of those images at every scale, for two
// reasons. (1) A saw-toothed band of the ceiling (two 40 m triangles 0.6 m above) was not drawn
// (1.1 % and 4.3 % of those walls' top quarter, centre eye): the map places the ceiling's middle
// outside its source field (above the rim seen from c, but inside the room), the head off c sees
// it along the top rim, where Embree's rays, bent through the map's extension, draw it, and Vulkan
// dropped the triangles outside the field. Fixed: the rim test below (coverage), which fails with
// VulkanOptions::dropOutsideSourceField. (2) The ceiling was shaded up to ~15 % darker there:
// Embree lit along the bent ray's last segment (|n . ray direction|), Vulkan with a point light
// at the eye's virtual position; the two agree only where rays are straight (the centre eye at
// c). Fixed: both light conformal frames from headlightPosition (confvis/backends/headlight.hpp);
// the off-centre comparison below went from 32.6 % to 0.24 % (worst image, left wall, left eye).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../backends/vulkan/test/vulkan_test_scenes.hpp"
#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/engine/scene_loader.hpp"

namespace confvis {
namespace {

constexpr float kTolerance = 0.1f;  // per channel, linear colour
// Share of a wall-and-eye image's pixels over the tolerance: edges that the raster and the rays
// place on either side of a pixel centre, and the texture filtered at a slightly different place
// (measured: plain <= 0.011 %, conformal with the head at c <= 0.34 %).
constexpr double kBudget = 0.01;

const Scene& roomInMetres() {
  static const Scene scene = loadScene(std::filesystem::path(CONFVIS_SOURCE_DIR) /
                                       "tests/data/scenes/crosscheck-room.obj");
  return scene;
}

struct ContentCase {
  DisplayConfig config;
  RetargetMap map;
  Scene scene;
  RenderSettings settings;
};

// The head 20 cm off the warp's centre: the stereo eyes, the head and the warp's centre all differ.
const glm::dvec3 kHeadOffCentre(0.2, -0.1, 0.15);

// The 5-sided CAVE with its analytic ceilingless map (lambda 1.5), the head at the reference
// point plus `head`, everything times `scale`.
ContentCase contentCase(double scale, RenderMode mode, const glm::dvec3& head) {
  const DisplayConfig unit = test::loadConfig("cave5");
  ContentCase c{test::scaledDisplay(unit, scale), {},
                test::scaledScene(roomInMetres(), static_cast<float>(scale)), {}};
  c.map = ceilinglessDilationMap(1.5, 128, c.config.reference);
  c.settings.mode = mode;
  c.settings.eyes = {Eye::Center, Eye::Left, Eye::Right};
  c.settings.head.position = c.config.reference + scale * head;
  c.settings.camera.position = c.config.reference;
  c.settings.resolutionScale = test::scaleFor(unit, 96);
  return c;
}

const RetargetMap* mapOf(const ContentCase& c) {
  return c.settings.mode == RenderMode::Conformal ? &c.map : nullptr;
}

RenderResult embreeRender(const ContentCase& c) {
  EmbreeBackend embree;
  embree.setScene(c.scene);
  return embree.render(c.config, mapOf(c), c.settings);
}

RenderResult vulkanRender(const ContentCase& c, VulkanOptions options = {}) {
  test::ValidatedBackend backend(options);
  backend->setScene(c.scene);
  RenderResult result = backend->render(c.config, mapOf(c), c.settings);
  test::expectNoValidationMessages(backend);
  return result;
}

// Worst share of a wall-and-eye image's pixels over the tolerance, with its name.
std::pair<double, std::string> worstBadFraction(const RenderResult& vulkan,
                                                const RenderResult& embree) {
  std::pair<double, std::string> worst{0.0, ""};
  for (const WallImage& image : embree.images) {
    const double bad =
        test::comparePixels(test::imageOf(vulkan, image.wall, image.eye).image, image.image,
                            kTolerance)
            .badFraction();
    if (bad > worst.first) worst = {bad, image.wall + " " + eyeName(image.eye)};
  }
  return worst;
}

void expectBackendsAgree(RenderMode mode, const glm::dvec3& head) {
  for (double scale : {1e-3, 1.0, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const ContentCase c = contentCase(scale, mode, head);
    const auto [bad, where] = worstBadFraction(vulkanRender(c), embreeRender(c));
    ::testing::Test::RecordProperty("worst_bad_fraction_at_scale_" + std::to_string(scale),
                                    std::to_string(bad) + " (" + where + ")");
    EXPECT_LE(bad, kBudget) << "worst image: " << where;
  }
}

TEST(BackendCrossCheckContent, PlainRoomMatchesEmbreeForEveryEyeAndScale) {
  expectBackendsAgree(RenderMode::Plain, kHeadOffCentre);
}

TEST(BackendCrossCheckContent, ConformalRoomMatchesEmbreeForEveryEyeAndScale) {
  expectBackendsAgree(RenderMode::Conformal, glm::dvec3(0.0));
}

// Both causes above: lighting along Embree's bent rays instead of from the headlight gives 32.6 %.
TEST(BackendCrossCheckContent, ConformalRoomWithTheHeadOffCentreMatchesEmbree) {
  expectBackendsAgree(RenderMode::Conformal, kHeadOffCentre);
}

// The top quarter of an image's rows: the rim of a side wall, next to the missing ceiling.
ImageRGBA topRim(const ImageRGBA& image) {
  ImageRGBA rim(image.width, image.height / 4);
  std::copy_n(image.pixels.begin(), rim.pixels.size(), rim.pixels.begin());
  return rim;
}

// Coverage alone (alpha: 1 where something is drawn), which tells the dropped band apart from
// any shading difference.
ImageRGBA coverage(const ImageRGBA& image) {
  ImageRGBA alpha(image.width, image.height);
  for (std::size_t i = 0; i < image.pixelCount(); ++i) alpha.pixels[4 * i] = image.pixels[4 * i + 3];
  return alpha;
}

// Worst share of a side wall's top rim drawn by one backend and not by the other, over the walls
// and eyes.
double worstSideWallRimCoverageMismatch(const RenderResult& vulkan, const RenderResult& embree) {
  double worst = 0.0;
  for (const WallImage& image : embree.images) {
    if (image.wall == "floor") continue;
    const ImageRGBA& drawn = test::imageOf(vulkan, image.wall, image.eye).image;
    worst = std::max(worst, test::comparePixels(coverage(topRim(drawn)),
                                                coverage(topRim(image.image)), 0.5f)
                                .badFraction());
  }
  return worst;
}

// Measured: none of the rim's pixels; 1.1 % (front) and 4.3 % (left) with the old drop.
constexpr double kRimCoverageBudget = 0.002;

// Along the top rim of the side walls, seen by the head off c (every eye), conformal Vulkan draws
// wherever Embree draws: no band; with the triangles outside the source field dropped (the old
// behaviour: a saw-toothed band) the same comparison fails.
TEST(BackendCrossCheckContent, ConformalTopRimOfTheSideWallsShowsNoBandWithTheHeadOffCentre) {
  const ContentCase c = contentCase(1.0, RenderMode::Conformal, kHeadOffCentre);
  const RenderResult embree = embreeRender(c);
  EXPECT_LE(worstSideWallRimCoverageMismatch(vulkanRender(c), embree), kRimCoverageBudget);
  VulkanOptions dropping;
  dropping.dropOutsideSourceField = true;
  EXPECT_GT(worstSideWallRimCoverageMismatch(vulkanRender(c, dropping), embree),
            5 * kRimCoverageBudget);
}

// The comparison can fail: the thin poles and wires lost, the ground's texture lost (Embree
// drawing the room without them), or conformal Vulkan drawing the ceiling and ground triangles
// whole instead of split before the warp.
TEST(BackendCrossCheckContent, BrokenRendersFailTheComparison) {
  ContentCase c = contentCase(1.0, RenderMode::Conformal, glm::dvec3(0.0));
  const RenderResult vulkan = vulkanRender(c);
  {
    ContentCase thin = c;
    std::erase_if(thin.scene.meshes, [&](const Mesh& mesh) {
      const std::string& material = thin.scene.materials[static_cast<std::size_t>(mesh.material)].name;
      return material == "pole" || material == "wire";
    });
    ASSERT_LT(thin.scene.meshes.size(), c.scene.meshes.size());
    EXPECT_GT(worstBadFraction(vulkan, embreeRender(thin)).first, 2 * kBudget);
  }
  {
    ContentCase untextured = c;
    for (Material& material : untextured.scene.materials) material.baseColorTexture = -1;
    EXPECT_GT(worstBadFraction(vulkan, embreeRender(untextured)).first, 2 * kBudget);
  }
  VulkanOptions whole;
  whole.splitWideTriangles = false;
  EXPECT_GT(worstBadFraction(vulkanRender(c, whole), embreeRender(c)).first, 2 * kBudget);
}

}  // namespace
}  // namespace confvis
