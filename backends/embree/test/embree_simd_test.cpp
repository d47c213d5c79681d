// The Embree surface kernel's two builds (baseline SSE2 and AVX2, chosen at startup) render the
// same pixels, bit for bit: both compute the same floats in the same order.
#include <gtest/gtest.h>

#include "confvis/engine/builtin_scenes.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

// The checker-sphere (textured, one material per face) with two squares in front of the front
// wall, one with vertex normals and one without (the geometric normal steps in), so that
// packets mix textured and untextured lanes, materials, and hits and misses along the squares'
// edges.
Scene mixedScene() {
  Scene scene = builtinScene("checker-sphere");
  const auto paint = static_cast<int>(scene.materials.size());
  scene.materials.push_back({"paint", glm::vec4(0.8f, 0.4f, 0.2f, 1.0f), -1});
  Mesh lit = test::facingSquare({0.1, 0.05, -0.6}, glm::dvec3(0.0), 0.3);
  lit.material = paint;
  Mesh bare = test::facingSquare({-0.15, -0.1, -0.7}, glm::dvec3(0.3, 0.2, 0.0), 0.25);
  bare.normals.clear();
  bare.material = -1;
  scene.meshes.push_back(lit);
  scene.meshes.push_back(bare);
  return scene;
}

void expectIdenticalPixels(const RenderResult& a, const RenderResult& b) {
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) {
    SCOPED_TRACE(a.images[i].wall);
    EXPECT_TRUE(a.images[i].image.pixels == b.images[i].image.pixels)
        << test::compareImages(a.images[i].image, b.images[i].image, 0.0).badPixels
        << " pixels differ";
  }
}

TEST(EmbreeSimd, BaselineAndDefaultShadingRenderIdenticalPixels) {
  const DisplayConfig config = test::shippedConfig("cave5");
  EmbreeOptions baselineOptions;
  baselineOptions.baselineShading = true;
  for (const char* name : {"mixed", "graph"}) {
    SCOPED_TRACE(name);
    const Scene scene = std::string(name) == "mixed" ? mixedScene() : builtinScene(name);
    EmbreeBackend baseline(baselineOptions), standard;
    baseline.setScene(scene);
    standard.setScene(scene);
    RenderSettings settings;
    settings.mode = RenderMode::Plain;
    settings.resolutionScale = test::scaleFor(64);
    settings.samplesPerPixel = 2;
    settings.ambientOcclusion = true;
    const RenderResult a = baseline.render(config, nullptr, settings);
    const RenderResult b = standard.render(config, nullptr, settings);
    EXPECT_EQ(a.stats.embree.value().shadingSimd, "sse2");
    if (b.stats.embree.value().shadingSimd != "avx2")
      GTEST_SKIP() << "no AVX2 here: both renders ran the baseline build";
    expectIdenticalPixels(a, b);
    // The painted square is in view (red = 2 green = 4 blue), so untextured lanes are compared.
    std::size_t painted = 0;
    for (const WallImage& image : a.images)
      for (std::size_t p = 0; p < image.image.pixelCount(); ++p) {
        const float* c = &image.image.pixels[4 * p];
        painted += c[2] > 0.05f && std::abs(c[0] - 2 * c[1]) < 1e-3f &&
                   std::abs(c[1] - 2 * c[2]) < 1e-3f;
      }
    if (std::string(name) == "mixed") {
      EXPECT_GT(painted, 100u);
    }
  }
}

}  // namespace
}  // namespace confvis
