// Tracker datagrams (UDP): the DTrack ASCII and JSON-lines parsers of tracker_packets.hpp. They
// never throw, a datagram is a pose or it is dropped, so any exception at all is a finding
// (libFuzzer reports the uncaught exception), and so is a pose that is not finite or whose
// orientation is not a unit quaternion. Every input goes through both protocols, DTrack with head
// body 0 and 1 (the seeds' bodies).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "confvis/runtime/tracker_packets.hpp"

namespace {

void requireUsablePose(const std::optional<confvis::RawTrackerPose>& pose) {
  if (!pose) return;
  const auto& p = pose->position;
  const auto& q = pose->orientation;
  const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                      std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) &&
                      std::isfinite(q.z) && (!pose->seconds || std::isfinite(*pose->seconds));
  const double norm = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  if (!finite || std::abs(norm - 1.0) > 1e-6) {
    std::fprintf(stderr, "FUZZ FINDING: a parsed pose is not finite or not a rotation\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view datagram(reinterpret_cast<const char*>(data), size);
  requireUsablePose(confvis::parseDTrackFrame(datagram, 0));
  requireUsablePose(confvis::parseDTrackFrame(datagram, 1));
  for (const auto& pose : confvis::parseJsonLines(datagram)) requireUsablePose(pose);
  return 0;
}
