// Live trackers over real UDP on 127.0.0.1: DTrack2 frames and JSON lines become room poses
// through the display's tracking section, the off-axis frusta of the walls follow them, garbage
// is counted and dropped while good packets keep arriving, and a silent tracker is lost but keeps
// its last pose. Every wait polls for the expected state with a deadline.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/engine/view.hpp"
#include "confvis/runtime/tracker_factory.hpp"
#include "confvis/runtime/udp_tracker.hpp"
#include "tracker_test_support.hpp"

using namespace confvis;
using namespace confvis::tracker_testing;

namespace {

DisplayConfig cave5() {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / "cave5.json");
}

// An ART room calibration with z up and y towards the front wall, its origin on the floor of the
// 3 m CAVE (1.5 m below the reference point): pitch -90 turns it into confvis' frame.
TrackingConfig zUpFloorTracker() {
  TrackingConfig t;
  t.pitchDegrees = -90;
  t.offset = {0, -1.5, 0};
  return t;
}

// The tracker frame's matrix of a yaw by `degrees` about its up axis (z).
glm::dmat3 zUpYawMatrix(double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  return glm::dmat3(std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1);
}

std::string jsonPose(double t, const glm::dvec3& p, const glm::dquat& q) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer,
                "{\"t\": %.6f, \"pos\": [%.9f, %.9f, %.9f], \"quat\": [%.9f, %.9f, %.9f, %.9f]}", t,
                p.x, p.y, p.z, q.x, q.y, q.z, q.w);
  return buffer;
}

bool hasPoseAt(Tracker& tracker, const glm::dvec3& position) {
  const std::optional<TrackedPose> pose = tracker.latest();
  return pose && glm::length(pose->head.position - position) < 1e-9;
}

}  // namespace

TEST(UdpTracker, DTrackFramesBecomeRoomPosesInMetres) {
  UdpTracker tracker(TrackerProtocol::DTrack, 0, [] {
    TrackingConfig t = zUpFloorTracker();
    t.headBody = 2;
    return t;
  }());
  ASSERT_GT(tracker.port(), 0);
  EXPECT_FALSE(tracker.latest());
  // Head (body 2) 1700 mm above the floor, 400 mm towards the front wall, 250 mm right, turned
  // 30 degrees left; a Flystick-like body 0 and a body 3 in the same frame.
  sendUdp(tracker.port(),
          dtrackFrame({{0, 1.0, {900, -300, 1000}, zUpYawMatrix(-80)},
                       {2, 0.98, {250, 400, 1700}, zUpYawMatrix(30)},
                       {3, 1.0, {0, 0, 0}, glm::dmat3(1.0)}},
                      true));
  ASSERT_TRUE(eventually([&] { return tracker.status().packetsReceived == 1; }));
  const TrackedPose pose = *tracker.latest();
  EXPECT_TRUE(near(pose.head.position, {0.25, 0.2, -0.4}, 1e-12));
  EXPECT_DOUBLE_EQ(pose.seconds, 39596.024831);  // DTrack's own timestamp
  // Turned left by 30 degrees about the room's up axis: looks along (-sin 30, 0, -cos 30).
  EXPECT_TRUE(near(pose.head.orientation * glm::dvec3(0, 0, -1),
                   {-std::sin(std::numbers::pi / 6), 0, -std::cos(std::numbers::pi / 6)}, 1e-5));
  EXPECT_TRUE(near(pose.head.orientation * glm::dvec3(0, 1, 0), {0, 1, 0}, 1e-5));
  EXPECT_EQ(tracker.status().packetsDropped, 0u);
  EXPECT_FALSE(tracker.status().lost);
}

TEST(UdpTracker, JsonLinesFollowTheLastPoseOfEachDatagram) {
  TrackingConfig t;
  t.offset = {0.5, 0, 0};
  UdpTracker tracker(TrackerProtocol::JsonLines, 0, t);
  const glm::dquat identity(1, 0, 0, 0);
  sendUdp(tracker.port(), jsonPose(1.0, {0, 1.6, 0}, identity) + "\n" +
                              jsonPose(1.1, {0.1, 1.6, 0}, identity) + "\n");
  ASSERT_TRUE(eventually([&] { return tracker.status().packetsReceived == 2; }));
  EXPECT_TRUE(hasPoseAt(tracker, {0.6, 1.6, 0}));  // metres by default, offset applied
  EXPECT_DOUBLE_EQ(tracker.latest()->seconds, 1.1);
  // A sender in millimetres, said so in the config.
  t.unit = TrackingUnit::Millimetres;
  UdpTracker mm(TrackerProtocol::JsonLines, 0, t);
  sendUdp(mm.port(), jsonPose(0, {100, 1600, -50}, identity));
  EXPECT_TRUE(eventually([&] { return hasPoseAt(mm, {0.6, 1.6, -0.05}); }));
}

TEST(UdpTracker, TheWallFrustaFollowTheFedPoses) {
  const DisplayConfig cave = cave5();
  UdpTracker tracker(TrackerProtocol::DTrack, 0, zUpFloorTracker());
  const auto frustum = [&](const std::string& wallName, Eye eye) {
    const HeadPose head = tracker.latest()->head;
    for (const WallView& view : makeViews(cave, head, eye))
      if (view.wall->name == wallName) return view;
    throw std::logic_error("no wall " + wallName);
  };
  // Centred: every wall 1.5 m away, symmetric frusta.
  sendUdp(tracker.port(), dtrackFrame({{0, 1.0, {0, 0, 1500}, glm::dmat3(1.0)}}, true));
  ASSERT_TRUE(eventually([&] { return hasPoseAt(tracker, {0, 0, 0}); }));
  EXPECT_DOUBLE_EQ(frustum("left", Eye::Center).nearDistance, 1.5);
  // The head 0.2 m left, 0.1 m up, 0.3 m towards the front wall (tracker: x left-right, y
  // forward, z up, millimetres), turned 90 degrees left to face the left wall.
  sendUdp(tracker.port(), dtrackFrame({{0, 1.0, {-200, 300, 1600}, zUpYawMatrix(90)}}, true));
  ASSERT_TRUE(eventually([&] { return hasPoseAt(tracker, {-0.2, 0.1, -0.3}); }));
  // Kooima's off-axis extents, measured in each wall plane from the foot of the perpendicular
  // from the eye e = (-0.2, 0.1, -0.3). Left wall (x = -1.5, right axis -z): d = 1.3,
  // l = -(1.5 - e.z) = -1.8, r = 1.5 + e.z = 1.2, b = -1.5 - e.y, t = 1.5 - e.y.
  const WallView left = frustum("left", Eye::Center);
  EXPECT_NEAR(left.nearDistance, 1.3, 1e-9);
  EXPECT_NEAR(left.left, -1.8, 1e-9);
  EXPECT_NEAR(left.right, 1.2, 1e-9);
  EXPECT_NEAR(left.bottom, -1.6, 1e-9);
  EXPECT_NEAR(left.top, 1.4, 1e-9);
  // Front wall (z = -1.5, right axis +x): d = 1.2, l = -1.3, r = 1.7.
  const WallView front = frustum("front", Eye::Center);
  EXPECT_NEAR(front.nearDistance, 1.2, 1e-9);
  EXPECT_NEAR(front.left, -1.3, 1e-9);
  EXPECT_NEAR(front.right, 1.7, 1e-9);
  // Facing the left wall, the head's right axis is -z: the left eye sits 32 mm towards +z, so
  // the left wall's frustum for that eye shifts by it, its distance unchanged.
  const WallView leftEye = frustum("left", Eye::Left);
  EXPECT_NEAR(leftEye.nearDistance, 1.3, 1e-6);
  EXPECT_NEAR(leftEye.left, -1.8 + 0.032, 1e-6);
  EXPECT_NEAR(leftEye.right, 1.2 + 0.032, 1e-6);
}

TEST(UdpTracker, GarbageIsCountedAndDroppedWhileGoodPacketsArrive) {
  UdpTracker tracker(TrackerProtocol::DTrack, 0, TrackingConfig{});
  const std::string garbage[] = {
      std::string("\x00\x01\x02\xff\xfe", 5),
      "6d 1 [0 1.000][nan 0 0][1 0 0 0 1 0 0 0 1]\r\n",
      "6d 1 [0 1.000][1 2 3][2 0 0 0 2 0 0 0 2]\r\n",  // not a rotation
      "6d 1 [0 1.000][1 2 3][1 0 0 0 1 0 0 0]\r\n",    // 8 matrix numbers
      "fr 5\r\n6d 1 [7 1.000][1 2 3][1 0 0 0 1 0 0 0 1]\r\n",  // no head body
      std::string(kMaxDatagramBytes + 100, '6'),     // over the size bound
      "",
  };
  int good = 0;
  for (const std::string& bad : garbage) {
    sendUdp(tracker.port(), bad);
    ++good;
    sendUdp(tracker.port(), dtrackFrame({{0, 1.0, {1000.0 * good, 0, 0}, glm::dmat3(1.0)}}, true));
  }
  ASSERT_TRUE(eventually([&] {
    const TrackerStatus s = tracker.status();
    return s.packetsReceived == std::size(garbage) && s.packetsDropped == std::size(garbage);
  })) << tracker.status().packetsReceived << " received, " << tracker.status().packetsDropped
      << " dropped";
  EXPECT_TRUE(hasPoseAt(tracker, {double(good), 0, 0}));  // the last good one, in metres
}

TEST(UdpTracker, ASilentTrackerIsLostAndKeepsItsLastPose) {
  TrackingConfig t;
  t.timeoutSeconds = 0.05;
  UdpTracker tracker(TrackerProtocol::JsonLines, 0, t);
  sendUdp(tracker.port(), jsonPose(3.0, {0.1, 1.5, 0.2}, glm::dquat(1, 0, 0, 0)));
  ASSERT_TRUE(eventually([&] { return tracker.status().packetsReceived == 1; }));
  ASSERT_TRUE(eventually([&] { return tracker.status().lost; }));
  EXPECT_TRUE(hasPoseAt(tracker, {0.1, 1.5, 0.2}));
  EXPECT_DOUBLE_EQ(tracker.latest()->seconds, 3.0);
  // A new pose finds it again.
  sendUdp(tracker.port(), jsonPose(4.0, {0.2, 1.5, 0.2}, glm::dquat(1, 0, 0, 0)));
  ASSERT_TRUE(eventually([&] { return hasPoseAt(tracker, {0.2, 1.5, 0.2}); }));
  // (lost may already be true again after 50 ms on a loaded machine; the pose is what counts.)
}

TEST(TrackerFactory, OpensLiveTrackersOnTheNamedPort) {
  const DisplayConfig cave = cave5();
  int port = 0;
  {
    UdpTracker probe(TrackerProtocol::JsonLines, 0, TrackingConfig{});  // find a free port
    port = probe.port();
  }
  const std::unique_ptr<Tracker> tracker = openTracker("udp:" + std::to_string(port), cave);
  sendUdp(port, jsonPose(0, {0.3, 0, 0}, glm::dquat(1, 0, 0, 0)));
  EXPECT_TRUE(eventually([&] { return hasPoseAt(*tracker, {0.3, 0, 0}); }));
  // The port is taken now: one clear error naming the spec.
  try {
    (void)openTracker("dtrack:" + std::to_string(port), cave);
    ADD_FAILURE() << "expected an Error for a port in use";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::IoFailure);
    EXPECT_NE(std::string(e.what()).find("dtrack:" + std::to_string(port)), std::string::npos)
        << e.what();
  }
}

TEST(TrackerFactory, RejectsPortsOutsideOneTo65535) {
  const DisplayConfig cave = cave5();
  for (const char* spec : {"udp:0", "udp:65536", "dtrack:70000", "dtrack:-5", "udp:12ab",
                           "udp: 5000", "dtrack:123456"}) {
    try {
      (void)openTracker(spec, cave);
      ADD_FAILURE() << "expected an Error for " << spec;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << spec;
      EXPECT_NE(std::string(e.what()).find(std::string("tracker '") + spec + "'"),
                std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("1 to 65535"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)openTracker("vrpn:Head@localhost", cave), Error);
  EXPECT_THROW((void)openTracker("udp:", cave), Error);
}
