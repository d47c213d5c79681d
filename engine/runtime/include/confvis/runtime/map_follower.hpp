#pragma once
// The map that follows the head. A RetargetMap is baked around one reference point c; as the
// tracked head walks away from c the map's directions drift from what the viewer sees. The
// follower re-bakes around the head in the background once the head is more than `radius` from
// the current map's reference, and swaps the new map in at a frame boundary: beginFrame() hands
// out one map for the whole frame and never waits for a bake.
//
// example: map_follower_loop (compiled and run by the test suite, tests/examples/)
//   MapFollower follower(config, bake);  // the first bake runs on this thread
//   while (running()) {
//     const std::optional<TrackedPose> pose = tracker.latest();  // empty before the first pose
//     const HeadPose head = pose ? pose->head : HeadPose{config.reference};
//     const FollowerFrame frame = follower.beginFrame(head);  // never waits for a bake
//     settings.head = head;
//     settings.camera.position = frame.display->reference;  // the world stays put as c moves
//     backend.renderInto(*frame.display, frame.map.get(), settings, images);
//     for (const std::string& error : follower.takeErrors()) log(error);
//   }
//
// frame.display is the follower's display with its reference moved to the map's: the pair a
// RenderBackend accepts (it refuses a map baked around another point than the display's
// reference). The bake is injected: the real one is confvis::bakeDisplay
// (conformal/bake_display.hpp), wired as
// [](const DisplayConfig& c, const glm::dvec3&) { return bakeDisplay(c, {.useCache = false}).map; },
// since the config handed to it already has its reference moved to the head.
//
// Thread-safety: not thread-safe; call a MapFollower from one thread (the render thread). The
// bakes run on their own thread, one at a time. A FollowerFrame's map and display are immutable
// and may be shared with other threads for as long as they are held.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// Bakes `config` (whose reference is already `reference`) into a map around `reference`.
using BakeFunction =
    std::function<RetargetMap(const DisplayConfig& config, const glm::dvec3& reference)>;

struct MapFollowerOptions {
  // Metres the head may stray from the current map's reference before a re-bake starts. After a
  // failed bake, the next try waits until the head is this far from where that bake was asked.
  double radius = 0.10;
};

// Thread-safety: a value; its map and display are immutable and may be shared with other
// threads for as long as they are held.
struct FollowerFrame {
  std::shared_ptr<const RetargetMap> map;  // never null; stays valid while the frame holds it
  // The follower's display with its reference at map->reference (never null): render `map`
  // with this display, not the one the follower was made with, once a re-bake has swapped in.
  std::shared_ptr<const DisplayConfig> display;
  std::uint64_t generation = 0;            // 0: the initial map; +1 at every swap
  bool swapped = false;                    // this frame is the first to use `map`
  bool baking = false;                     // a re-bake is running in the background
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct MapFollowerStats {
  int bakesStarted = 0;    // background re-bakes only, not the initial map
  int bakesSucceeded = 0;  // swapped in
  int bakesFailed = 0;     // reported through takeErrors(); the old map stays
};

// `config` with its reference moved to `reference`, validated again (the reference must stay in
// front of every wall) and re-hashed. Throws Error(InvalidInput) naming the wall otherwise.
DisplayConfig withReference(const DisplayConfig& config, const glm::dvec3& reference);

// Thread-safety: not thread-safe: one thread (the render thread) makes every call; the bakes
// run on the follower's own thread (see above).
class MapFollower {
 public:
  // Bakes the first map around config.reference on the calling thread (start-up may wait;
  // frames never do). Errors of that bake propagate.
  MapFollower(DisplayConfig config, BakeFunction bake, MapFollowerOptions options = {});
  // Starts from a map made elsewhere (loaded from disk, baked earlier) around initial.reference.
  MapFollower(DisplayConfig config, RetargetMap initial, BakeFunction bake,
              MapFollowerOptions options = {});
  // Waits for a running bake to end: bakes cannot be cancelled.
  ~MapFollower();
  MapFollower(const MapFollower&) = delete;
  MapFollower& operator=(const MapFollower&) = delete;

  // Call once per frame before rendering: swaps in a finished bake, starts a re-bake if the head
  // strayed beyond the radius and none is running, returns the map for this frame. Never waits
  // for a bake. A head position that is not finite is ignored (no re-bake).
  FollowerFrame beginFrame(const HeadPose& head);

  // Messages of failed bakes since the last call, oldest first.
  std::vector<std::string> takeErrors();
  MapFollowerStats stats() const { return stats_; }
  const DisplayConfig& config() const { return config_; }
  // Reference point of the map beginFrame currently hands out.
  glm::dvec3 reference() const { return reference_; }
  // Blocks until no bake is running; the next beginFrame swaps its result in. For offline
  // renders that want every frame's map settled, and for tests; never call it in a live loop.
  void waitForBake();

 private:
  struct Shared;  // state the bake thread writes, behind a mutex

  void startBake(const glm::dvec3& reference);
  void collectFinishedBake(FollowerFrame& frame);

  DisplayConfig config_;
  BakeFunction bake_;
  MapFollowerOptions options_;
  std::shared_ptr<const RetargetMap> current_;
  std::shared_ptr<const DisplayConfig> currentDisplay_;  // config_ with current_'s reference
  glm::dvec3 reference_{0.0};
  std::uint64_t generation_ = 0;
  std::optional<glm::dvec3> failedReference_;
  std::vector<std::string> errors_;
  MapFollowerStats stats_;
  std::shared_ptr<Shared> shared_;
  std::thread worker_;
};

}  // namespace confvis
