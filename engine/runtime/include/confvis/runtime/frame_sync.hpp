#pragma once
// How the live view's one frame loop (live_view.hpp) keeps step with other processes that show
// the same display. One process decides every frame (tracking, navigation, the map follower,
// the end of the run); the others receive its decision. A new map reaches every process before
// any renders with it, and every window presents the same frame. LocalFrameSync is the single
// process: nothing to exchange. The MPI one is ClusterFrameSync (confvis/runtime/cluster.hpp,
// the cluster component). MPI-free.
#include <memory>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/runtime/frame_state.hpp"
#include "confvis/runtime/map_follower.hpp"

namespace confvis CONFVIS_API {

// One frame of the live view as the deciding process decides it.
struct LiveFrameState : ClusterFrameState {
  bool conformal = true;  // conformal or plain (C toggles)
  bool stop = false;      // Esc or a closed window: every process leaves before rendering it
};

// The map a frame renders with, and whether it is newer than the previous frame's.
struct SyncedMap {
  std::shared_ptr<const RetargetMap> map;
  bool swapped = false;
};

// Thread-safety: not thread-safe: the frame loop's thread makes every call.
class FrameSync {
 public:
  virtual ~FrameSync() = default;
  // Whether this process decides the frames (and so needs the follower, tracker and input).
  virtual bool decides() const = 0;
  // Once, after this process opened its windows and before its first frame.
  virtual void windowsOpen() {}
  // Every frame. On the deciding process `state` holds its decision (mapGeneration aside) and
  // `frame` the follower's frame; elsewhere `frame` is null and `state` is overwritten with the
  // decision. Returns the map of the frame, whose generation is then state.mapGeneration.
  virtual SyncedMap exchange(LiveFrameState& state, const FollowerFrame* frame) = 0;
  // After rendering, before presenting: returns once every process may present this frame.
  // `renderSeconds`: this process's render time (how long to be patient with slower ones).
  virtual void beforePresent(double renderSeconds) { (void)renderSeconds; }
};

// One process: it decides, the follower's map is the frame's map.
// Thread-safety: as FrameSync.
class LocalFrameSync final : public FrameSync {
 public:
  bool decides() const override { return true; }
  SyncedMap exchange(LiveFrameState& state, const FollowerFrame* frame) override {
    state.mapGeneration = frame->generation;
    return {frame->map, frame->swapped};
  }
};

}  // namespace confvis
