// The live tracking protocols without sockets: ART DTrack2 ASCII frames as a DTrack2 sends them
// (several bodies, other record types around the 6d line) and JSON lines, each pose checked
// against closed forms, and every kind of malformed packet dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "confvis/runtime/tracker_packets.hpp"
#include "tracker_test_support.hpp"

using namespace confvis;
using namespace confvis::tracker_testing;

TEST(DTrackFrame, PicksTheHeadBodyFromAMultiBodyFrame) {
  // Body 1 is the head (millimetres), turned 30 degrees left about +y; bodies 0 and 4 around it.
  const glm::dmat3 head = yawMatrix(30);
  const std::string frame = dtrackFrame(
      {{0, 0.95, {10, 20, 30}, yawMatrix(-70)}, {1, 1.0, {1200, 1650.5, -300.25}, head},
       {4, 0.5, {-800, 900, 100}, glm::dmat3(1.0)}},
      /*withAngles=*/true);
  const std::optional<RawTrackerPose> pose = parseDTrackFrame(frame, 1);
  ASSERT_TRUE(pose) << frame;
  EXPECT_TRUE(near(pose->position, {1200, 1650.5, -300.25}, 1e-9));
  ASSERT_TRUE(pose->seconds);
  EXPECT_DOUBLE_EQ(*pose->seconds, 39596.024831);
  // Column-wise: the third column is the body's +z, so it looks along minus that column.
  EXPECT_TRUE(near(pose->orientation * glm::dvec3(0, 0, -1),
                   {-std::sin(std::numbers::pi / 6), 0, -std::cos(std::numbers::pi / 6)}, 1e-5));
  EXPECT_TRUE(near(pose->orientation * glm::dvec3(1, 0, 0), head[0], 1e-5));
  // The other bodies are there too.
  EXPECT_TRUE(parseDTrackFrame(frame, 0));
  EXPECT_TRUE(near(parseDTrackFrame(frame, 4)->position, {-800, 900, 100}, 1e-9));
}

TEST(DTrackFrame, ReadsTheThreeNumberLocationBlockAndFramesWithoutTimestamp) {
  std::string frame = dtrackFrame({{0, 1.0, {1, 2, 3}, glm::dmat3(1.0)}}, /*withAngles=*/false);
  frame.erase(frame.find("ts "), frame.find("\r\n", frame.find("ts ")) + 2 - frame.find("ts "));
  const std::optional<RawTrackerPose> pose = parseDTrackFrame(frame, 0);
  ASSERT_TRUE(pose) << frame;
  EXPECT_TRUE(near(pose->position, {1, 2, 3}, 1e-12));
  EXPECT_FALSE(pose->seconds);
}

TEST(DTrackFrame, ARealRecordedFrameParses) {
  // A frame as printed by a running DTrack (quoted in a public parser example): 4 decimals in
  // the angles, 6 in the matrix, one body with id 45.
  const std::string frame =
      "fr 518169\r\nts 30331.359222\r\n6dcal 46\r\n"
      "6d 1 [45 1.000][-5.026 695.186 763.716 -7.7879 -10.9331 -3.3467]"
      "[0.980175 -0.032183 0.195503 0.057318 0.990587 -0.124306 -0.189662 0.133047 0.972793]\r\n"
      "3d 0\r\n";
  const std::optional<RawTrackerPose> pose = parseDTrackFrame(frame, 45);
  ASSERT_TRUE(pose);
  EXPECT_TRUE(near(pose->position, {-5.026, 695.186, 763.716}, 1e-9));
  // Its matrix rebuilt from the quaternion, column by column.
  const glm::dmat3 m = glm::mat3_cast(pose->orientation);
  EXPECT_TRUE(near(m[0], {0.980175, -0.032183, 0.195503}, 1e-5));
  EXPECT_TRUE(near(m[2], {-0.189662, 0.133047, 0.972793}, 1e-5));
  EXPECT_FALSE(parseDTrackFrame(frame, 0)) << "body 0 is not in this frame";
}

TEST(DTrackFrame, AMissingOrUntrackedHeadBodyIsNoPose) {
  const std::string frame = dtrackFrame({{0, 1.0, {0, 0, 0}, glm::dmat3(1.0)}}, true);
  EXPECT_FALSE(parseDTrackFrame(frame, 2));
  EXPECT_FALSE(parseDTrackFrame(dtrackFrame({{2, -1.0, {0, 0, 0}, glm::dmat3(1.0)}}, true), 2));
  EXPECT_FALSE(parseDTrackFrame("fr 12\r\nts 1.5\r\n6d 0\r\n", 0));
  EXPECT_FALSE(parseDTrackFrame("fr 12\r\n", 0));
}

TEST(DTrackFrame, MalformedFramesAreDropped) {
  const std::string good = dtrackFrame({{0, 1.0, {1, 2, 3}, yawMatrix(10)}}, true);
  ASSERT_TRUE(parseDTrackFrame(good, 0));
  const auto broken = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  const std::string cases[] = {
      broken("6d 1 ", "6d 2 "),                      // fewer bodies than announced
      broken("6d 1 ", "6d x "),                      // the count is not a number
      broken("6d 1 ", "6d -1 "),                     // negative count
      broken("[0 1.000]", "[0]"),                    // id block arity
      broken("[0 1.000]", "[0.5 1.000]"),            // fractional id
      broken("[1.000 2.000 3.000 ", "[1.000 2.000 "),  // location arity 5
      broken("[1.000 2.000 3.000 ", "[nan 2.000 3.000 "),
      broken("[1.000 2.000 3.000 ", "[inf 2.000 3.000 "),
      broken("[1.000 2.000 3.000 ", "[1e999 2.000 3.000 "),
      broken("][", "]junk["),                        // text between blocks
      broken("fr ", "fr x"),                         // frame counter not a number
      broken("ts ", "ts x"),                         // timestamp not a number
      good + "6d 1 [0 1.000][1 2 3][1 0 0 0 1 0 0 0 1]\r\n",  // two 6d lines
      good + "fr 13\r\n",                            // two frame counters
      good.substr(0, good.find("\r\n6df2") - 5),   // cut short inside the matrix
      std::string("\x01\xff garbage \x00 6d", 15),
      "",
  };
  for (const std::string& frame : cases) EXPECT_FALSE(parseDTrackFrame(frame, 0)) << frame;
  // The matrix: 8 or 10 numbers, a scaled matrix, a reflection, a shear.
  const auto withMatrix = [&](const std::string& matrix) {
    return "fr 1\r\n6d 1 [0 1.000][1 2 3 0 0 0][" + matrix + "]\r\n";
  };
  EXPECT_TRUE(parseDTrackFrame(withMatrix("1 0 0 0 1 0 0 0 1"), 0));
  for (const char* matrix : {"1 0 0 0 1 0 0 0", "1 0 0 0 1 0 0 0 1 0", "2 0 0 0 2 0 0 0 2",
                             "-1 0 0 0 1 0 0 0 1", "1 0 0 0.5 1 0 0 0 1", "0 0 0 0 0 0 0 0 0"})
    EXPECT_FALSE(parseDTrackFrame(withMatrix(matrix), 0)) << matrix;
}

TEST(DTrackFrame, WorkPerPacketIsBounded) {
  std::string manyLines;
  for (std::size_t i = 0; i <= kMaxLinesPerDatagram; ++i) manyLines += "3d 0\r\n";
  manyLines += "6d 1 [0 1.000][1 2 3][1 0 0 0 1 0 0 0 1]\r\n";
  EXPECT_FALSE(parseDTrackFrame(manyLines, 0));
  std::string huge = dtrackFrame({{0, 1.0, {1, 2, 3}, glm::dmat3(1.0)}}, true);
  huge += "3d 1 [1 1.0][" + std::string(kMaxDatagramBytes, ' ') + "]\r\n";
  EXPECT_FALSE(parseDTrackFrame(huge, 0));
}

TEST(JsonLines, ReadsEveryLineOfADatagramInOrder) {
  const double h = std::sqrt(0.5);
  const std::string datagram =
      "{\"t\": 1.5, \"pos\": [0.1, 1.7, -0.2], \"quat\": [0, " + std::to_string(h) + ", 0, " +
      std::to_string(h) + "]}\n\n{\"pos\": [1, 2, 3], \"quat\": [0, 0, 0, 1]}\r\n";
  const auto poses = parseJsonLines(datagram);
  ASSERT_EQ(poses.size(), 2u);
  ASSERT_TRUE(poses[0] && poses[1]);
  EXPECT_TRUE(near(poses[0]->position, {0.1, 1.7, -0.2}, 1e-15));
  EXPECT_EQ(poses[0]->seconds, 1.5);
  // [x, y, z, w]: 90 degrees about +y, so the head looks along -x.
  EXPECT_TRUE(near(poses[0]->orientation * glm::dvec3(0, 0, -1), {-1, 0, 0}, 1e-6));
  EXPECT_FALSE(poses[1]->seconds);
  EXPECT_TRUE(near(poses[1]->orientation * glm::dvec3(0, 0, -1), {0, 0, -1}, 1e-15));
}

TEST(JsonLines, MalformedLinesAreDroppedOneByOne) {
  const char* bad[] = {
      "{\"pos\": [0, 0], \"quat\": [0, 0, 0, 1]}",        // pos arity
      "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 1]}",        // quat arity
      "{\"pos\": [0, 0, 0]}",                             // no quat
      "{\"quat\": [0, 0, 0, 1]}",                         // no pos
      "{\"pos\": [0, \"1\", 0], \"quat\": [0, 0, 0, 1]}",  // a string
      "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 2]}",     // far from unit length
      "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 0]}",     // zero
      "{\"pos\": [NaN, 0, 0], \"quat\": [0, 0, 0, 1]}",   // not JSON
      "{\"pos\": [1e999, 0, 0], \"quat\": [0, 0, 0, 1]}",
      "{\"t\": \"now\", \"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 1]}",
      "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 1], \"position\": [1, 1, 1]}",  // unknown key
      "[0, 0, 0]", "garbage", "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 1]",
  };
  const std::string good = "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 1]}";
  for (const char* line : bad) {
    const auto poses = parseJsonLines(good + "\n" + line + "\n" + good);
    ASSERT_EQ(poses.size(), 3u) << line;
    EXPECT_TRUE(poses[0] && poses[2]) << line;
    EXPECT_FALSE(poses[1]) << line;
  }
  // A line over the length bound, and a datagram over the line-count bound.
  const std::string longLine = "{\"pos\": [0, 0, 0], \"quat\": [0, 0, 0, 1]" +
                               std::string(kMaxJsonLineBytes, ' ') + "}";
  ASSERT_EQ(parseJsonLines(longLine).size(), 1u);
  EXPECT_FALSE(parseJsonLines(longLine)[0]);
  std::string many;
  for (std::size_t i = 0; i <= kMaxLinesPerDatagram; ++i) many += good + "\n";
  const auto tooMany = parseJsonLines(many);
  ASSERT_EQ(tooMany.size(), 1u);
  EXPECT_FALSE(tooMany[0]);
  // Deep nesting stays a dropped line, not a stack overflow.
  EXPECT_FALSE(parseJsonLines(std::string(1000, '['))[0]);
}
