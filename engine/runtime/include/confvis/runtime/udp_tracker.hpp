#pragma once
// Live head tracking over UDP: a receiver thread reads ART DTrack2 ASCII frames or JSON-lines
// poses (tracker_packets.hpp), maps them into the room with the display's tracking section
// (tracking_config.hpp) and publishes the newest pose. latest() and status() only copy under a
// short lock: a render loop never waits on the network.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>

#include "confvis/base/export.hpp"
#include "confvis/engine/tracking_config.hpp"
#include "confvis/runtime/tracker.hpp"
#include "confvis/runtime/tracker_packets.hpp"

namespace confvis CONFVIS_API {

enum class TrackerProtocol { DTrack, JsonLines };

// Thread-safety: latest() and status() may be called from any number of threads at once
// (a short lock; the receiver thread is the tracker's own); construction and destruction from
// one thread.
class UdpTracker : public Tracker {
 public:
  // Binds UDP `port` on every interface (0: an ephemeral port, see port()) and starts the
  // receiver. Error(InvalidInput) for a port outside 0..65535; Error(IoFailure) naming the port
  // when the socket cannot be bound (e.g. in use).
  UdpTracker(TrackerProtocol protocol, int port, TrackingConfig tracking);
  // Stops the receiver within about one poll interval (kPollInterval) and closes the socket.
  ~UdpTracker() override;
  UdpTracker(const UdpTracker&) = delete;
  UdpTracker& operator=(const UdpTracker&) = delete;

  // The newest accepted pose in the room frame (metres); its seconds are the sender's timestamp
  // (DTrack "ts", JSON "t") or else the receive time since construction. A lost tracker keeps
  // returning its last pose.
  std::optional<TrackedPose> latest() override;
  // packetsReceived: accepted poses (DTrack frames with the head body, JSON lines);
  // packetsDropped: everything else (malformed, oversized, head body missing or untracked);
  // lost: no pose accepted for the config's timeout_seconds (counted from construction).
  TrackerStatus status() const override;

  int port() const { return port_; }  // the bound port

  static constexpr std::chrono::milliseconds kPollInterval{20};

 private:
  using Clock = std::chrono::steady_clock;
  void receiveLoop();
  void accept(const std::optional<RawTrackerPose>& raw);
  double secondsSinceStart() const;

  TrackerProtocol protocol_;
  TrackingConfig tracking_;
  double metresPerUnit_;
  int socket_ = -1;
  int port_ = 0;
  Clock::time_point start_;

  mutable std::mutex mutex_;  // guards the four below
  std::optional<TrackedPose> latest_;
  Clock::time_point lastAccepted_;
  std::uint64_t received_ = 0, dropped_ = 0;

  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace confvis
