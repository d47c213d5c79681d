#include "confvis/runtime/udp_tracker.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// Datagrams read per wake-up before the stop flag is looked at again: a flood cannot delay
// shutdown by more than this many (bounded) parses.
constexpr int kDatagramsPerWakeUp = 256;

bool isFinite(const HeadPose& head) {
  const glm::dvec3& p = head.position;
  const glm::dquat& q = head.orientation;
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(q.w) &&
         std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

}  // namespace

UdpTracker::UdpTracker(TrackerProtocol protocol, int port, TrackingConfig tracking)
    : protocol_(protocol),
      tracking_(tracking),
      metresPerUnit_(tracking.metresPerUnit(protocol == TrackerProtocol::DTrack
                                                ? TrackingUnit::Millimetres
                                                : TrackingUnit::Metres)),
      start_(Clock::now()),
      lastAccepted_(start_) {
  if (port < 0 || port > 65535)
    throw Error(ErrorCode::InvalidInput,
                "UDP tracker port must be 0..65535, got " + std::to_string(port));
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0)
    throw Error(ErrorCode::IoFailure,
                std::string("UDP tracker: cannot create a socket: ") + std::strerror(errno));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  socklen_t length = sizeof address;
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      ::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    const int error = errno;
    ::close(socket_);
    throw Error(ErrorCode::IoFailure, "UDP tracker: cannot listen on port " +
                                          std::to_string(port) + ": " + std::strerror(error));
  }
  port_ = ntohs(address.sin_port);
  thread_ = std::thread([this] { receiveLoop(); });
}

UdpTracker::~UdpTracker() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  ::close(socket_);
}

std::optional<TrackedPose> UdpTracker::latest() {
  const std::lock_guard lock(mutex_);
  return latest_;
}

TrackerStatus UdpTracker::status() const {
  const std::lock_guard lock(mutex_);
  const std::chrono::duration<double> silence = Clock::now() - lastAccepted_;
  return TrackerStatus{received_, dropped_, silence.count() > tracking_.timeoutSeconds};
}

double UdpTracker::secondsSinceStart() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void UdpTracker::accept(const std::optional<RawTrackerPose>& raw) {
  std::optional<TrackedPose> pose;
  if (raw) {
    pose = TrackedPose{tracking_.toRoom(raw->position, raw->orientation, metresPerUnit_),
                       raw->seconds.value_or(secondsSinceStart())};
    if (!isFinite(pose->head)) pose.reset();  // finite but absurd numbers can overflow
  }
  const std::lock_guard lock(mutex_);
  if (!pose) {
    ++dropped_;
    return;
  }
  latest_ = pose;
  lastAccepted_ = Clock::now();
  ++received_;
}

void UdpTracker::receiveLoop() {
  // One byte more than the largest accepted datagram; MSG_TRUNC reports a longer one's length.
  std::vector<char> buffer(kMaxDatagramBytes + 1);
  while (!stop_) {
    pollfd readable{socket_, POLLIN, 0};
    if (::poll(&readable, 1, static_cast<int>(kPollInterval.count())) <= 0) continue;
    for (int i = 0; i < kDatagramsPerWakeUp && !stop_; ++i) {
      const ssize_t size = ::recv(socket_, buffer.data(), buffer.size(), MSG_DONTWAIT | MSG_TRUNC);
      if (size < 0) break;  // drained (EAGAIN), or a transient error: poll again
      if (static_cast<std::size_t>(size) > kMaxDatagramBytes) {
        accept(std::nullopt);
        continue;
      }
      const std::string_view datagram(buffer.data(), static_cast<std::size_t>(size));
      if (protocol_ == TrackerProtocol::DTrack) {
        accept(parseDTrackFrame(datagram, tracking_.headBody));
        continue;
      }
      const std::vector<std::optional<RawTrackerPose>> poses = parseJsonLines(datagram);
      if (poses.empty()) accept(std::nullopt);  // an empty datagram carries no pose
      for (const std::optional<RawTrackerPose>& pose : poses) accept(pose);
    }
  }
}

}  // namespace confvis
