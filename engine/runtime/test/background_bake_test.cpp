// backgroundBake: the MapFollower's real bake with its thread count; by default half the cores.
#include <gtest/gtest.h>

#include <thread>

#include "../../core/test/engine/display_test_support.hpp"
#include "confvis/base/error.hpp"
#include "confvis/runtime/background_bake.hpp"

using namespace confvis;
using confvis::testing::shippedConfigJson;
using confvis::testing::vecNear;

TEST(BackgroundBake, LeavesHalfTheHardwareThreadsToTheRendererByDefault) {
  const int hardware = static_cast<int>(std::thread::hardware_concurrency());
  const int threads = defaultBackgroundBakeThreads();
  EXPECT_GE(threads, 1);
  if (hardware >= 2) {
    EXPECT_LE(threads, hardware / 2);
    EXPECT_GE(threads, (hardware - 1) / 2);
  }
}

TEST(BackgroundBake, BakesTheMovedDisplayAroundItsReferenceWithoutTheCache) {
  nlohmann::json json = shippedConfigJson("cave5.json");
  json["cube_resolution"] = 16;
  json["edge_length"] = 0.5;
  const DisplayConfig moved = withReference(parseDisplayConfig(json, "cave5 (coarse)"), {0.2, 0, 0});
  const RetargetMap map = backgroundBake(1)(moved, moved.reference);
  EXPECT_TRUE(vecNear(map.reference, {0.2, 0, 0}));
  EXPECT_EQ(map.resolution(), 16);
  // Straight ahead lies on the front wall, shown there: the map has a direction for it.
  EXPECT_TRUE(map.toVirtual(glm::dvec3{0, 0, -1}).has_value());
}

TEST(BackgroundBake, RefusesANegativeThreadCount) {
  try {
    backgroundBake(-2);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(error.what()).find("-2"), std::string::npos) << error.what();
  }
}
