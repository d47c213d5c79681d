#pragma once
// Head tracking. A Tracker hands out the newest head pose without ever blocking, so a render loop
// can poll it once per frame. confvis ships a recorded-path player (tests, demos, offline
// renders); a live tracker (VRPN, OpenXR, a lab's own protocol) implements the same interface in
// the application. Debian 12 packages no VRPN, so confvis has no VRPN client (README).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct TrackedPose {
  HeadPose head;
  double seconds = 0.0;  // when the pose was measured, on the tracker's clock
};

// What a tracker has seen, for overlays and logs (view.json). A recorded path never loses track.
struct TrackerStatus {
  std::uint64_t packetsReceived = 0;  // accepted poses
  std::uint64_t packetsDropped = 0;   // malformed packets, or packets without the head body
  bool lost = false;                  // no pose for a while: latest() keeps the last one
};

// Thread-safety: latest() and status() never block; an implementation must allow them to be called
// from the render thread while its own thread (a network listener) receives poses.
class Tracker {
 public:
  virtual ~Tracker() = default;
  // The newest pose, or nullopt before the first one arrives. Never blocks.
  virtual std::optional<TrackedPose> latest() = 0;
  // Thread-safe; never blocks.
  virtual TrackerStatus status() const { return {}; }
};

// One sample of a recorded head path.
struct PathKey {
  double seconds = 0.0;
  HeadPose head;
};

// A head path: keys at strictly increasing times, positions interpolated linearly and
// orientations by spherical linear interpolation (shortest arc).
//
// File format (CSV, one key per line; blank lines and lines starting with '#' are ignored):
//   seconds,x,y,z,qw,qx,qy,qz
//   0.0,0,0,0,1,0,0,0
//   ...
// Positions in metres in the display's physical frame; (qw,qx,qy,qz) a rotation quaternion
// (normalised on reading; identity looks down -z with +y up). Sample: configs/paths/.
// Thread-safety: immutable once made; at() may be called from any number of threads at once.
class RecordedPath {
 public:
  // Throws Error(InvalidInput) naming `sourceName` and the key for an empty path, times that do
  // not increase, non-finite values or a zero quaternion.
  explicit RecordedPath(std::vector<PathKey> keys, const std::string& sourceName = "path");

  // Error(FileNotFound) naming the path; Error(InvalidInput) naming file and line.
  static RecordedPath load(const std::filesystem::path& path);
  static RecordedPath parse(const std::string& text, const std::string& sourceName);

  // The pose at time `seconds`. loop: the path repeats with period duration() (from its first
  // key's time), so a closed path (last key = first key) loops seamlessly; otherwise times
  // outside the keys clamp to the first or last key.
  HeadPose at(double seconds, bool loop) const;
  double duration() const { return keys_.back().seconds - keys_.front().seconds; }
  const std::vector<PathKey>& keys() const { return keys_; }

 private:
  std::vector<PathKey> keys_;
};

// Plays a RecordedPath against a clock. The default clock is real time since construction; tests
// and offline renders pass their own (e.g. frame number / frame rate).
// Thread-safety: latest() and status() may be called from any thread, if the clock may.
class RecordedPathTracker : public Tracker {
 public:
  using Clock = std::function<double()>;  // seconds
  explicit RecordedPathTracker(RecordedPath path, bool loop = true, Clock clock = {});
  std::optional<TrackedPose> latest() override;

 private:
  RecordedPath path_;
  bool loop_;
  Clock clock_;
};

}  // namespace confvis
