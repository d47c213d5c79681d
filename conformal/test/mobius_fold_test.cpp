// The Möbius blend's fold guard (smooth_interpolation.hpp) and the accurate preset that uses the
// blend (bake_preset.hpp): a baked map with flipped texels is refused by the bake's verdict, so
// the blend must never turn a triangle over.
#include <gtest/gtest.h>

#include <cstddef>

#include "../src/smooth_interpolation.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_verdict.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "display_test_configs.hpp"

namespace confvis {
namespace {

std::size_t foldedTriangles(const detail::MobiusBlend& blend, const SphereDiskMesh& mesh) {
  std::size_t folded = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    folded += blend.folds(static_cast<int>(t));
  return folded;
}

// cave5 on uniform 20 cm edges: around the cut's leaves (the top corners, where the map goes like
// the square root of the distance) the raw blend of the leaf's power chart with its neighbours'
// Möbius maps folds; it baked 10 flipped ray texels and a conformality ratio of 669.
TEST(MobiusFoldGuard, Cave5sUniformMapNoLongerFoldsNorFlipsTexels) {
  DisplayMapOptions options;
  options.edgeLength = 0.2;
  const DisplayMap map = computeDisplayMap(testing::shipped("cave5"), options);
  const detail::MobiusBlend raw(map.source, false), guarded(map.source);
  EXPECT_GT(foldedTriangles(raw, map.source), 0u);  // what the guard is for: the test can fail
  EXPECT_EQ(raw.linearVertices(), 0u);
  EXPECT_EQ(foldedTriangles(guarded, map.source), 0u);
  // Only the few vertices around the folds fall back to the linear map.
  EXPECT_GT(guarded.linearVertices(), 0u);
  EXPECT_LT(guarded.linearVertices(), map.source.sphere.size() / 50);
  const detail::MobiusBlend target(map.target);
  EXPECT_EQ(foldedTriangles(target, map.target), 0u);

  BakeOptions bake;
  bake.interpolation = MapInterpolation::Mobius;
  const RetargetMap baked = bakeRetargetMap(map, 256, bake);
  const BakedConformality ray = measureBakedConformality(baked.ray);
  EXPECT_EQ(ray.flipped, 0u);
  EXPECT_LT(ray.ratioMax, 20.0);  // was 669 without the guard; the linear bake's is 4.3
  EXPECT_LT(ray.ratioP50, 1.01);  // still the smooth map elsewhere (linear: 1.05)
  EXPECT_TRUE(judgeBake(map, baked).ok()) << judgeBake(map, baked).summary();
}

// The accurate preset (what `confvis bake` and `render` use) bakes with Möbius blending, and its
// bake of cave5 passes the verdict without flipped texels. At 20 cm instead of the preset's 10
// cm edges (its grading and interpolation stay) so that the test takes about a second.
TEST(MobiusFoldGuard, TheAccuratePresetBakesCave5WithMobiusBlendingAndNoFlippedTexels) {
  BakeDisplayOptions options;
  options.preset = BakePreset::Accurate;
  options.edgeLength = 0.2;
  options.resolution = 128;
  options.useCache = false;
  ASSERT_EQ(bakeInterpolation(options), MapInterpolation::Mobius);
  const BakedDisplay baked = bakeDisplay(testing::shipped("cave5"), options);
  EXPECT_EQ(baked.sidecar.at("map_settings").at("interpolation"), "mobius");
  ASSERT_TRUE(baked.displayMap.has_value());
  const BakeVerdict verdict = judgeBake(*baked.displayMap, baked.map);
  EXPECT_TRUE(verdict.ok()) << verdict.summary();
  EXPECT_EQ(verdict.flippedTexels, 0u);
  const BakedConformality ray = measureBakedConformality(baked.map.ray);
  EXPECT_EQ(ray.flipped, 0u);
  EXPECT_LT(ray.ratioMax, 5.0);
  // The map is the Möbius bake of that mesh, not the linear one.
  BakeOptions linear;
  linear.reference = baked.map.reference;
  const RetargetMap linearMap = bakeRetargetMap(*baked.displayMap, 128, linear);
  const BakedConformality linearRay = measureBakedConformality(linearMap.ray);
  EXPECT_LT(ray.ratioP95, linearRay.ratioP95);  // smoother than linear at the same mesh
}

}  // namespace
}  // namespace confvis
