#include "confvis/runtime/cluster.hpp"

namespace confvis {

ClusterFrameSync::ClusterFrameSync(Cluster& cluster, double firstFrameSeconds)
    : cluster_(cluster), firstFrameSeconds_(firstFrameSeconds) {}

bool ClusterFrameSync::decides() const { return cluster_.isRoot(); }

void ClusterFrameSync::windowsOpen() { cluster_.swapLock(firstFrameSeconds_); }

SyncedMap ClusterFrameSync::exchange(LiveFrameState& state, const FollowerFrame* frame) {
  if (cluster_.isRoot()) {
    if (first_) {  // every rank holds the first map before the first frame
      cluster_.shareMapNow(frame->map, frame->generation);
      sharedGeneration_ = frame->generation;
    } else if (frame->generation != sharedGeneration_ &&
               !(pending_ && pendingGeneration_ == frame->generation)) {
      cluster_.shareMap(frame->map, frame->generation);  // travels while frames go on
      pending_ = true;
      pendingGeneration_ = frame->generation;
    }
    if (cluster_.progressMaps() && pending_) {  // reached every rank: swap it in now
      sharedGeneration_ = pendingGeneration_;
      pending_ = false;
    }
    state.mapGeneration = sharedGeneration_;
  } else {
    cluster_.progressMaps();  // chunks of a new map arrive between frames
  }
  const std::uint64_t generationBefore = cluster_.mapGeneration();
  cluster_.exchangeFrame(state, first_ ? firstFrameSeconds_ : 0.0);
  const bool swapped = !first_ && cluster_.mapGeneration() != generationBefore;
  first_ = false;
  return {cluster_.map(), swapped};
}

void ClusterFrameSync::beforePresent(double renderSeconds) {
  cluster_.swapLock(4.0 * renderSeconds + 1.0);
}

}  // namespace confvis
