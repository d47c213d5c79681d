// The display config's "tracking" section: defaults, the tracker-to-room transform against closed
// forms, the canonical round trip (outside the bake hash), and one clear error per bad field.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/tracking_config.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::shippedConfigJson;
using confvis::testing::vecNear;
using nlohmann::json;

namespace {

glm::dquat aboutAxis(double degrees, const glm::dvec3& axis) {
  return glm::angleAxis(degrees * std::numbers::pi / 180.0, axis);
}

::testing::AssertionResult sameRotation(const glm::dquat& a, const glm::dquat& b) {
  if (std::abs(std::abs(glm::dot(a, b)) - 1.0) <= 1e-12) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.w << ", " << a.x << ", " << a.y << ", " << a.z
                                       << ") vs (" << b.w << ", " << b.x << ", " << b.y << ", "
                                       << b.z << ")";
}

json caveWithTracking(const json& tracking) {
  json j = shippedConfigJson("cave5.json");
  j["tracking"] = tracking;
  return j;
}

void expectInvalidTracking(const json& tracking, std::initializer_list<std::string> fragments) {
  try {
    (void)parseDisplayConfig(caveWithTracking(tracking), "broken.json");
    ADD_FAILURE() << "expected an Error for " << tracking.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    for (const std::string& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos)
          << "lacks " << f << ": " << e.what();
  }
}

}  // namespace

TEST(TrackingConfig, AbsentSectionTakesTheDocumentedDefaults) {
  const DisplayConfig c = parseDisplayConfig(shippedConfigJson("cave5.json"), "cave5.json");
  EXPECT_TRUE(vecNear(c.tracking.offset, {0, 0, 0}));
  EXPECT_TRUE(sameRotation(c.tracking.rotation(), glm::dquat(1, 0, 0, 0)));
  EXPECT_EQ(c.tracking.unit, TrackingUnit::ProtocolDefault);
  EXPECT_EQ(c.tracking.headBody, 0);
  EXPECT_DOUBLE_EQ(c.tracking.timeoutSeconds, 0.5);
  // The protocol decides the unit unless the config does.
  EXPECT_DOUBLE_EQ(c.tracking.metresPerUnit(TrackingUnit::Millimetres), 1e-3);
  EXPECT_DOUBLE_EQ(c.tracking.metresPerUnit(TrackingUnit::Metres), 1.0);
}

TEST(TrackingConfig, ReadsEveryField) {
  const DisplayConfig c = parseDisplayConfig(
      caveWithTracking({{"offset", {0.1, -1.2, 0.3}},
                        {"rotation", {{"yaw", 10}, {"pitch", -90}, {"roll", 5}}},
                        {"unit", "m"},
                        {"head_body", 3},
                        {"timeout_seconds", 2.5}}),
      "cave.json");
  EXPECT_TRUE(vecNear(c.tracking.offset, {0.1, -1.2, 0.3}));
  EXPECT_EQ(c.tracking.yawDegrees, 10.0);
  EXPECT_EQ(c.tracking.pitchDegrees, -90.0);
  EXPECT_EQ(c.tracking.rollDegrees, 5.0);
  EXPECT_EQ(c.tracking.unit, TrackingUnit::Metres);
  EXPECT_EQ(c.tracking.headBody, 3);
  EXPECT_DOUBLE_EQ(c.tracking.timeoutSeconds, 2.5);
  // "unit" overrides the protocol's own.
  EXPECT_DOUBLE_EQ(c.tracking.metresPerUnit(TrackingUnit::Millimetres), 1.0);
}

TEST(TrackingConfig, RotationIsYawAboutYThenPitchAboutXThenRollAboutZ) {
  TrackingConfig t;
  t.yawDegrees = 90;  // counter-clockwise seen from above: forward (-z) turns to -x
  EXPECT_TRUE(vecNear(t.rotation() * glm::dvec3(0, 0, -1), {-1, 0, 0}, 1e-15));
  t = {};
  t.pitchDegrees = 90;  // forward tilts up
  EXPECT_TRUE(vecNear(t.rotation() * glm::dvec3(0, 0, -1), {0, 1, 0}, 1e-15));
  t = {};
  t.rollDegrees = 90;  // right (+x) turns to up
  EXPECT_TRUE(vecNear(t.rotation() * glm::dvec3(1, 0, 0), {0, 1, 0}, 1e-15));
  // Composition order: R = Ry(yaw) Rx(pitch) Rz(roll).
  t = {};
  t.yawDegrees = 30, t.pitchDegrees = -20, t.rollDegrees = 50;
  const glm::dquat expected = aboutAxis(30, {0, 1, 0}) * aboutAxis(-20, {1, 0, 0}) *
                              aboutAxis(50, {0, 0, 1});
  EXPECT_TRUE(sameRotation(t.rotation(), expected));
}

TEST(TrackingConfig, ZUpTrackerMapsIntoTheYUpRoomInMetres) {
  // An ART room calibration with z up and y towards the front wall: pitch -90 turns it into
  // confvis' frame (+y up, -z forward); the tracker origin sits on the floor, 1.5 m below c.
  TrackingConfig t;
  t.pitchDegrees = -90;
  t.offset = {0, -1.5, 0};
  const double mm = t.metresPerUnit(TrackingUnit::Millimetres);
  // 1700 mm up, 400 mm towards the front wall, 250 mm to the right.
  const HeadPose head = t.toRoom({250, 400, 1700}, glm::dquat(1, 0, 0, 0), mm);
  EXPECT_TRUE(vecNear(head.position, {0.25, 0.2, -0.4}, 1e-12));
  // A body at the identity (calibrated parallel to the room, facing forward) is the identity head.
  EXPECT_TRUE(sameRotation(head.orientation, glm::dquat(1, 0, 0, 0)));
  // Turning left by 30 degrees about the tracker's up axis (z) turns left about the room's (y).
  const HeadPose turned = t.toRoom({0, 0, 0}, aboutAxis(30, {0, 0, 1}), mm);
  EXPECT_TRUE(sameRotation(turned.orientation, aboutAxis(30, {0, 1, 0})));
  EXPECT_TRUE(vecNear(turned.orientation * glm::dvec3(0, 0, -1),
                      {-std::sin(std::numbers::pi / 6), 0, -std::cos(std::numbers::pi / 6)},
                      1e-12));
}

TEST(TrackingConfig, RoundTripsThroughTheCanonicalJsonOutsideTheHash) {
  const json tracking = {{"offset", {0.5, 0, 0}}, {"unit", "mm"}, {"head_body", 2}};
  const DisplayConfig c = parseDisplayConfig(caveWithTracking(tracking), "cave.json");
  const DisplayConfig again = parseDisplayConfig(toJson(c), "round trip");
  EXPECT_EQ(toJson(again), toJson(c));
  EXPECT_EQ(again.tracking.unit, TrackingUnit::Millimetres);
  EXPECT_EQ(again.tracking.headBody, 2);
  // The tracker does not change the conformal map, so it leaves the bake cache's key alone.
  EXPECT_EQ(c.hash, parseDisplayConfig(shippedConfigJson("cave5.json"), "cave5.json").hash);
}

TEST(TrackingConfig, EachBadFieldIsOneErrorNamingIt) {
  expectInvalidTracking({{"ofset", {0, 0, 0}}}, {"broken.json: tracking", "unknown key 'ofset'"});
  expectInvalidTracking({{"offset", {0, 0}}}, {"broken.json: tracking", "'offset'", "3 numbers"});
  expectInvalidTracking({{"offset", {0, "x", 0}}}, {"'offset'", "must be a number"});
  expectInvalidTracking({{"rotation", {{"yaw", "90"}}}}, {"tracking: rotation", "'yaw'"});
  expectInvalidTracking({{"rotation", {{"heading", 90}}}},
                        {"tracking: rotation", "unknown key 'heading'"});
  expectInvalidTracking({{"rotation", {0, 0, 0, 1}}}, {"tracking: rotation", "JSON object"});
  expectInvalidTracking({{"unit", "cm"}}, {"'unit'", "\"mm\" or \"m\"", "\"cm\""});
  expectInvalidTracking({{"head_body", -1}}, {"'head_body'", "non-negative integer", "-1"});
  expectInvalidTracking({{"head_body", 1.5}}, {"'head_body'", "1.5"});
  expectInvalidTracking({{"head_body", 10000000000LL}}, {"'head_body'", "10000000000"});
  expectInvalidTracking({{"timeout_seconds", 0}}, {"'timeout_seconds'", "positive"});
  expectInvalidTracking({{"timeout_seconds", "1"}}, {"'timeout_seconds'", "number"});
  expectInvalidTracking(json::array(), {"broken.json: tracking", "JSON object"});
}
