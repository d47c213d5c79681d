// bakeDisplay bakes a map once (issue 22): its checks bake each candidate map to judge it, and
// that bake is the one returned (SourcedDisplayMap), not a second bake of the same map.
#include <gtest/gtest.h>

#include <numbers>

#include "../src/bake_count.hpp"
#include "bake_test_support.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "display_test_configs.hpp"

namespace confvis {
namespace {

bool sameTexels(const RetargetMap& a, const RetargetMap& b) {
  if (a.resolution() != b.resolution() || a.reference != b.reference) return false;
  for (int f = 0; f < 6; ++f)
    if (a.ray.faces[f].pixels != b.ray.faces[f].pixels ||
        a.geom.faces[f].pixels != b.geom.faces[f].pixels)
      return false;
  return true;
}

DisplayMap capMap() {
  DisplayMap map;
  map.source = test::makeCapMesh(8, 0.5 * std::numbers::pi);
  map.target = test::makeCapMesh(8, 0.4 * std::numbers::pi);
  map.stats = {{"template", 0.0}, {"flow", 0.0}, {"alignment", 0.0}};
  return map;
}

BakeDisplayOptions uncached(int resolution) {
  BakeDisplayOptions options;
  options.resolution = resolution;
  options.useCache = false;
  return options;
}

// A source that hands back its own bake, marked (one texel's alpha 0.25, which no bake writes),
// made with `resolution` and `interpolation`.
struct PrebakingSource {
  int resolution;
  MapInterpolation interpolation;
  SourcedDisplayMap operator()(const DisplayConfig& effective) const {
    SourcedDisplayMap sourced(capMap());
    PrebakedRetargetMap baked;
    baked.options.reference = {effective.reference.x, effective.reference.y,
                               effective.reference.z};
    baked.options.interpolation = interpolation;
    baked.map = bakeRetargetMap(sourced.map, resolution, baked.options, &baked.timings);
    baked.map.ray.faces[0].pixels[3] = 0.25f;
    baked.timings.total = 1234.5;
    sourced.baked = std::move(baked);
    return sourced;
  }
};

TEST(BakeOnce, BakeDisplayWithReturnsTheSourcesBakeWhenItsOptionsMatch) {
  const DisplayConfig config = testing::shipped("cave5");
  const BakeDisplayOptions options = uncached(16);
  const MapInterpolation interpolation = bakeInterpolation(options);
  const std::size_t before = detail::retargetBakeCount();
  const BakedDisplay reused = bakeDisplayWith(config, options, PrebakingSource{16, interpolation});
  EXPECT_EQ(detail::retargetBakeCount() - before, 1u);  // the source's bake only
  EXPECT_EQ(reused.map.ray.faces[0].pixels[3], 0.25f);
  EXPECT_EQ(reused.timings.total, 1234.5);
  EXPECT_EQ(reused.sidecar["timings"]["bake"]["total"], 1234.5);

  // Another resolution or interpolation than bakeDisplayWith's: baked again, as without one.
  const MapInterpolation other = interpolation == MapInterpolation::Mobius
                                     ? MapInterpolation::Linear
                                     : MapInterpolation::Mobius;
  for (const PrebakingSource source : {PrebakingSource{8, interpolation}, PrebakingSource{16, other}}) {
    const std::size_t count = detail::retargetBakeCount();
    const BakedDisplay rebaked = bakeDisplayWith(config, options, source);
    EXPECT_EQ(detail::retargetBakeCount() - count, 2u);
    const RetargetMap fresh = bakeRetargetMap(capMap(), 16, displayBakeOptions(rebaked.config, options));
    EXPECT_TRUE(sameTexels(rebaked.map, fresh));
    EXPECT_NE(rebaked.timings.total, 1234.5);
  }
}

// bakeDisplay itself: the checks' bake is the returned one (one bake in all), with the texels a
// fresh bake of the returned display map has, and bake.json's bake timings are that bake's.
TEST(BakeOnce, BakeDisplayBakesTheCheckedMapOnce) {
  const DisplayConfig config = testing::shipped("cave5");
  for (MapInterpolation interpolation : {MapInterpolation::Linear, MapInterpolation::Mobius}) {
    BakeDisplayOptions options = uncached(24);
    options.interpolation = interpolation;
    const std::size_t before = detail::retargetBakeCount();
    const BakedDisplay baked = bakeDisplay(config, options);
    EXPECT_EQ(detail::retargetBakeCount() - before, 1u) << toString(interpolation);
    ASSERT_TRUE(baked.displayMap.has_value());
    const RetargetMap fresh =
        bakeRetargetMap(*baked.displayMap, 24, displayBakeOptions(baked.config, options));
    EXPECT_TRUE(sameTexels(baked.map, fresh)) << toString(interpolation);
    const nlohmann::json& timings = baked.sidecar["timings"];
    EXPECT_EQ(timings["bake"]["total"], baked.timings.total);
    EXPECT_GT(baked.timings.total, 0.0);
    EXPECT_GE(timings["display_map"]["checks"]["seconds"].get<double>(), 0.0);
  }
}

}  // namespace
}  // namespace confvis
