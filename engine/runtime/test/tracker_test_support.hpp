#pragma once
// Shared by the live-tracker tests: DTrack2 frames written as a DTrack2 writes them, a UDP sender
// to 127.0.0.1, and polling for an expected state with a deadline (no fixed sleeps).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

namespace confvis::tracker_testing {

inline ::testing::AssertionResult near(const glm::dvec3& actual, const glm::dvec3& expected,
                                       double tolerance) {
  if (glm::length(actual - expected) <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") != (" << expected.x
         << ", " << expected.y << ", " << expected.z << ")";
}

// Rotation by `degrees` about +y (turning left in a y-up frame), as a matrix.
inline glm::dmat3 yawMatrix(double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  return glm::dmat3(std::cos(a), 0, -std::sin(a),  // column 0: the body's x axis
                    0, 1, 0,                       // column 1
                    std::sin(a), 0, std::cos(a));  // column 2
}

struct DTrackBody {
  int id;
  double quality;
  glm::dvec3 millimetres;
  glm::dmat3 rotation;  // body -> room
};

// One DTrack2 ASCII frame as the tracker sends it: CR LF line ends, the records in DTrack2's
// order (fr, ts, 6dcal, 6d, 6df2, 3d), positions with 3 decimals, the matrix with 6, written
// column-wise. withAngles: the location block carries "x y z eta theta phi" (DTrack2's classic
// output, angles ignored by confvis) instead of "x y z".
inline std::string dtrackFrame(const std::vector<DTrackBody>& bodies, bool withAngles) {
  char buffer[512];
  std::string frame = "fr 21753\r\nts 39596.024831\r\n6dcal " +
                      std::to_string(bodies.size() + 1) + "\r\n6d " +
                      std::to_string(bodies.size());
  for (const DTrackBody& b : bodies) {
    std::snprintf(buffer, sizeof buffer, " [%d %.3f][%.3f %.3f %.3f", b.id, b.quality,
                  b.millimetres.x, b.millimetres.y, b.millimetres.z);
    frame += buffer;
    frame += withAngles ? " 0.0000 0.0000 0.0000][" : "][";
    const glm::dmat3& m = b.rotation;
    std::snprintf(buffer, sizeof buffer, "%.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f]",
                  m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1],
                  m[2][2]);
    frame += buffer;
  }
  return frame + "\r\n6df2 1 0\r\n3d 1 [77 1.000][100.000 200.000 300.000]\r\n";
}

// Sends one datagram to 127.0.0.1:port.
inline void sendUdp(int port, const std::string& datagram) {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(s, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const ssize_t sent = ::sendto(s, datagram.data(), datagram.size(), 0,
                                reinterpret_cast<const sockaddr*>(&to), sizeof to);
  ::close(s);
  ASSERT_EQ(sent, static_cast<ssize_t>(datagram.size()));
}

// Polls `condition` until it holds or `deadline` passes; true when it held.
template <typename Condition>
bool eventually(Condition condition, std::chrono::milliseconds deadline = std::chrono::seconds(3)) {
  const auto end = std::chrono::steady_clock::now() + deadline;
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return condition();
}

}  // namespace confvis::tracker_testing
