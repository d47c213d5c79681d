// The accurate preset's per-display edge rule (bake_preset.hpp: smallestBoundaryCornerAngle).
#include <gtest/gtest.h>

#include <numbers>

#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_preset.hpp"
#include "display_test_configs.hpp"

namespace confvis {
namespace {

constexpr double kPi = std::numbers::pi;

// A cube's face seen from its centre is a spherical square with angles of 2π/3: cave3's open back
// corners are one face's corner, cave5's top corners two faces', cave6 (closed) has no boundary.
TEST(BakePresetRule, CubeCornersHaveTheirClosedFormAngles) {
  EXPECT_NEAR(smallestBoundaryCornerAngle(testing::shipped("cave3")), 2 * kPi / 3, 1e-9);
  EXPECT_NEAR(smallestBoundaryCornerAngle(testing::shipped("cave5")), 4 * kPi / 3, 1e-9);
  EXPECT_NEAR(smallestBoundaryCornerAngle(testing::shipped("cave6")), 2 * kPi, 1e-9);
  // The front half of a box: its boundary is the great circle z = 0, straight at every corner.
  EXPECT_NEAR(smallestBoundaryCornerAngle(testing::frontHemisphereDisplay()), kPi, 1e-9);
  // md230x6's outer panel corners are convex.
  EXPECT_LT(smallestBoundaryCornerAngle(testing::shipped("md230x6")), kPi - 0.2);
}

TEST(BakePresetRule, AccurateTakesFinerEdgesOnlyWhereTheDisplayHasConvexCorners) {
  for (const char* name : {"cave3", "cave5", "cave6", "md230x6"}) {
    const DisplayConfig config = testing::shipped(name);
    EXPECT_EQ(presetSettings(BakePreset::Fast, config).edgeScale, 1.0) << name;
    const BakePresetSettings accurate = presetSettings(BakePreset::Accurate, config);
    const BakePresetSettings plain = presetSettings(BakePreset::Accurate);
    const bool convex = std::string(name) == "cave3" || std::string(name) == "md230x6";
    EXPECT_EQ(accurate.edgeScale, convex ? 0.4 : plain.edgeScale) << name;
    EXPECT_EQ(accurate.grading.radiusDegrees, plain.grading.radiusDegrees) << name;
    EXPECT_EQ(accurate.interpolation, plain.interpolation) << name;
  }
  EXPECT_EQ(presetSettings(BakePreset::Accurate).edgeScale, 0.5);
}

// What `confvis bake` and `render` bake: the rule reaches the effective config (and with it the
// cache key), and an explicit edge length still wins.
TEST(BakePresetRule, TheBakedConfigTakesTheRulesEdge) {
  for (const char* name : {"cave3", "cave5"}) {
    const DisplayConfig config = testing::shipped(name);
    BakeDisplayOptions options;
    options.preset = BakePreset::Accurate;
    const double scale = std::string(name) == "cave3" ? 0.4 : 0.5;
    EXPECT_NEAR(effectiveBakeConfig(config, options).edgeLength, scale * config.edgeLength, 1e-12)
        << name;
    options.edgeLength = 0.3;
    EXPECT_NEAR(effectiveBakeConfig(config, options).edgeLength, 0.3, 1e-12) << name;
  }
}

}  // namespace
}  // namespace confvis
