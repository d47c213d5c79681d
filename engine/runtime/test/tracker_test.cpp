// Recorded head paths: keys are reproduced exactly, in-between poses follow closed forms (linear
// position, shortest-arc rotation), looping and clamping, the shipped sample, and bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/runtime/tracker.hpp"
#include "../../core/test/engine/display_test_support.hpp"

using namespace confvis;
using confvis::testing::configDir;
using confvis::testing::vecNear;

namespace {

// Rotation about +y (the head turning left) by `degrees`.
glm::dquat yaw(double degrees) {
  const double half = degrees * std::numbers::pi / 360.0;
  return {std::cos(half), 0.0, std::sin(half), 0.0};
}

::testing::AssertionResult sameRotation(const glm::dquat& a, const glm::dquat& b) {
  // q and -q are the same rotation.
  if (std::abs(std::abs(glm::dot(a, b)) - 1.0) <= 1e-12) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.w << ", " << a.x << ", " << a.y << ", " << a.z
                                       << ") vs (" << b.w << ", " << b.x << ", " << b.y << ", "
                                       << b.z << ")";
}

RecordedPath twoKeys(const glm::dquat& second) {
  return RecordedPath({{1.0, HeadPose{{0, 0, 0}}}, {3.0, HeadPose{{0.4, 0.2, -0.8}, second}}});
}

void expectInvalidPath(const std::string& text, std::initializer_list<std::string> fragments) {
  try {
    (void)RecordedPath::parse(text, "walk.csv");
    ADD_FAILURE() << "expected an Error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    for (const std::string& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << "lacks " << f << ": " << e.what();
  }
}

}  // namespace

TEST(RecordedPath, InterpolatesPositionLinearlyAndRotationAlongTheShortArc) {
  const RecordedPath path = twoKeys(yaw(60));
  for (const bool loop : {false, true}) {
    const HeadPose first = path.at(1.0, loop);
    EXPECT_TRUE(vecNear(first.position, {0, 0, 0}));
    EXPECT_TRUE(sameRotation(first.orientation, glm::dquat(1, 0, 0, 0)));
  }
  const HeadPose quarter = path.at(1.5, false);
  EXPECT_TRUE(vecNear(quarter.position, {0.1, 0.05, -0.2}, 1e-15));
  EXPECT_TRUE(sameRotation(quarter.orientation, yaw(15)));
  // The second key written as -q (the same rotation) must not send the head the long way round.
  const HeadPose negated = twoKeys(-yaw(60)).at(2.0, false);
  EXPECT_TRUE(sameRotation(negated.orientation, yaw(30)));
  EXPECT_TRUE(sameRotation(path.at(3.0, false).orientation, yaw(60)));
}

TEST(RecordedPath, LoopsWithItsDurationOrClampsAtTheEnds) {
  const RecordedPath path = twoKeys(yaw(60));
  EXPECT_DOUBLE_EQ(path.duration(), 2.0);
  for (const double t : {1.25, 2.0, 2.9}) {
    SCOPED_TRACE(t);
    const HeadPose inside = path.at(t, true);
    for (const double wrapped : {t + 2.0, t + 20.0, t - 2.0, t - 6.0}) {
      EXPECT_TRUE(vecNear(path.at(wrapped, true).position, inside.position, 1e-12));
      EXPECT_TRUE(sameRotation(path.at(wrapped, true).orientation, inside.orientation));
    }
  }
  EXPECT_TRUE(vecNear(path.at(-5.0, false).position, {0, 0, 0}));
  EXPECT_TRUE(vecNear(path.at(50.0, false).position, {0.4, 0.2, -0.8}));
  // One key: a head standing still.
  const RecordedPath still({{0.0, HeadPose{{1, 2, 3}}}});
  EXPECT_TRUE(vecNear(still.at(7.0, true).position, {1, 2, 3}));
}

TEST(RecordedPath, TrackerPlaysThePathOnItsClock) {
  double now = 0.0;
  RecordedPathTracker tracker(twoKeys(yaw(60)), /*loop=*/false, [&now] { return now; });
  now = 0.5;  // half a second after the path's first key (t = 1.0)
  const std::optional<TrackedPose> pose = tracker.latest();
  ASSERT_TRUE(pose);
  EXPECT_DOUBLE_EQ(pose->seconds, 0.5);
  EXPECT_TRUE(vecNear(pose->head.position, {0.1, 0.05, -0.2}, 1e-15));
  EXPECT_TRUE(sameRotation(pose->head.orientation, yaw(15)));
}

TEST(RecordedPath, ShippedSampleIsAClosedWalkInsideTheCave) {
  const RecordedPath path = RecordedPath::load(configDir() / "paths" / "cave-walk.csv");
  ASSERT_EQ(path.keys().size(), 6u);
  EXPECT_DOUBLE_EQ(path.duration(), 7.0);
  const HeadPose& first = path.keys().front().head;
  const HeadPose& last = path.keys().back().head;
  EXPECT_TRUE(vecNear(first.position, last.position));  // closed: loops without a jump
  EXPECT_TRUE(sameRotation(first.orientation, last.orientation));
  EXPECT_TRUE(vecNear(path.at(3.0, true).position, {0, 0, -0.4}));
  EXPECT_TRUE(sameRotation(path.at(3.0, true).orientation, yaw(30)));
  for (const PathKey& k : path.keys()) {  // well inside the 3 m cube around the origin
    EXPECT_LT(glm::length(k.head.position), 1.0);
    EXPECT_NEAR(glm::length(k.head.orientation), 1.0, 1e-12);
  }
}

TEST(RecordedPath, BadFilesNameTheFileAndLine) {
  const std::string header = "seconds,x,y,z,qw,qx,qy,qz\n";
  expectInvalidPath("time,x,y,z\n0,0,0,0\n", {"walk.csv:1:", "header"});
  expectInvalidPath(header + "0,0,0,0,1,0,0\n", {"walk.csv:2:", "8 comma-separated", "got 7"});
  expectInvalidPath(header + "# comment\n0,0,0,0,1,0,0,0\n1,0,0.5m,0,1,0,0,0\n",
                    {"walk.csv:4:", "field 3", "0.5m"});
  expectInvalidPath(header + "0,0,0,0,1,0,0,0\n0,1,0,0,1,0,0,0\n", {"walk.csv:3:", "does not increase"});
  expectInvalidPath(header + "0,0,0,0,0,0,0,0\n", {"walk.csv:2:", "quaternion is zero"});
  expectInvalidPath(header, {"walk.csv", "no keys"});
  expectInvalidPath("", {"walk.csv", "no keys"});
  try {
    (void)RecordedPath::load("/no/such/walk.csv");
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
  }
}
