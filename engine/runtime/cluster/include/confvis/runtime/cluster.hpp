#pragma once
// Cluster rendering on MPI: one process per wall (or per projector pair), frame-locked, one map
// for all. Rank 0 (the root) owns tracking, navigation, time and the bake; every frame it sends
// one frame state to every rank, each rank renders only its walls, and a swap lock before present
// makes every wall show the same frame. A new map travels in chunks while frames go on and is
// swapped in on the same frame number everywhere.
//
// Built on a communicator the application passes in, so an MPI application keeps its own
// MPI_Init. Every call is collective over that communicator and comes with a deadline
// (ClusterOptions::timeoutSeconds): a rank that dies or stops answering makes every other rank
// throw ClusterError naming the lost rank, its host and its walls, instead of hanging in a
// barrier. After a ClusterError the communicator is unusable: report it and leave the process
// (std::_Exit or MPI_Abort; MPI_Finalize may wait for the lost rank forever).
//
//   confvis::Cluster cluster(MPI_COMM_WORLD, display);
//   for (;;) {
//     confvis::ClusterFrameState state;
//     if (cluster.isRoot()) state = ...;            // head pose, camera, time
//     cluster.exchangeFrame(state);                 // now equal on every rank
//     render(cluster.walls(), state, *cluster.map());
//     cluster.swapLock();                           // then present
//   }
//
// Not thread-safe: one thread per process calls it (MPI_THREAD_FUNNELED is enough).
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <mpi.h>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/viewer.hpp"
#include "confvis/runtime/frame_state.hpp"

namespace confvis CONFVIS_API {

// A rank lost or refused (config mismatch); the message names rank, host and walls.
// Thread-safety: an immutable value, as Error.
class ClusterError : public Error {
 public:
  using Error::Error;
};

struct ClusterOptions {
  double timeoutSeconds = 5.0;  // the most any rank waits for another before giving up
  std::size_t mapChunkBytes = std::size_t{1} << 20;  // a new map travels in pieces of this size
};

// Thread-safety: not thread-safe: one thread per process makes every call (see above).
class Cluster {
 public:
  // Collective. Checks that every rank runs the same confvis version on a display with the same
  // config as the root, every field included (ClusterError naming the first rank and host that
  // differs), learns
  // every rank's host name and deals the walls (wall_assignment.hpp). Sets MPI_ERRORS_RETURN on
  // a duplicate of `comm`, which the Cluster owns.
  Cluster(MPI_Comm comm, const DisplayConfig& display, ClusterOptions options = {});
  ~Cluster();
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  int rank() const { return rank_; }
  int size() const { return static_cast<int>(hosts_.size()); }
  bool isRoot() const { return rank_ == 0; }
  const std::string& host(int rank) const { return hosts_.at(rank); }
  const std::vector<std::string>& walls() const { return walls_.at(rank_); }  // this rank's
  const std::vector<std::string>& wallsOf(int rank) const { return walls_.at(rank); }
  // "rank 3 (host render-2, walls left, right)": how messages name a rank.
  std::string describe(int rank) const;

  // The root's `state` to every rank (the root's copy is unchanged). Before returning, swaps in
  // the map of state.mapGeneration (shared earlier by shareMap) so map() matches the state.
  // The other ranks wait `patienceSeconds` beyond the timeout: work the root does first.
  template <class State>
  void exchangeFrame(State& state, double patienceSeconds = 0.0) {
    static_assert(std::is_base_of_v<ClusterFrameState, State> &&
                      std::is_trivially_copyable_v<State>,
                  "a frame state derives from ClusterFrameState and is trivially copyable");
    exchangeFrameBytes(&state, sizeof(State), patienceSeconds);
    adoptMap(state.mapGeneration);
  }
  // Returns once every rank reached it, so all present the same frame. A rank that does not
  // arrive within the timeout (plus `patienceSeconds`, for offline frames that take long to
  // render) ends every rank with ClusterError naming it.
  void swapLock(double patienceSeconds = 0.0);

  // The map of the newest generation swapped in (null before the first one is shared).
  std::shared_ptr<const RetargetMap> map() const { return map_; }
  std::uint64_t mapGeneration() const { return mapGeneration_; }

  // Root: starts sending `map` as generation `generation` to every rank, in chunks, without
  // waiting. Every rank (root included) must then call progressMaps() once per frame; when it
  // returns true on the root, every rank holds the map and the root may put `generation` into the
  // next frame state. A share still in flight is replaced by the newer one only after it ends.
  void shareMap(std::shared_ptr<const RetargetMap> map, std::uint64_t generation);
  // Moves pending map transfers on (never blocks). Root: true once the latest share has reached
  // every rank. Other ranks: true when a map arrived this call.
  bool progressMaps();
  // Root and ranks: shareMap (root) and progressMaps until every rank has the map, within the
  // timeout; then the map is adopted on every rank. For start-up and offline runs. The other
  // ranks wait `patienceSeconds` longer: what the root may still spend baking the map.
  void shareMapNow(std::shared_ptr<const RetargetMap> map, std::uint64_t generation,
                   double patienceSeconds = 0.0);

  // Offline: every rank's wall images to the root, which returns all of them in config order of
  // `display` walls and `eyes` order (other ranks get back an empty result).
  // The root waits the timeout plus `renderSeconds` (what the slowest rank may still need).
  RenderResult gatherImages(const RenderResult& mine, const DisplayConfig& display,
                            const std::vector<Eye>& eyes, double renderSeconds);

 private:
  struct MapTransfer;
  void exchangeFrameBytes(void* data, std::size_t bytes, double patienceSeconds);
  void adoptMap(std::uint64_t generation);
  [[noreturn]] void lost(int rank, const std::string& during);

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  ClusterOptions options_;
  std::vector<std::string> hosts_;
  std::vector<std::vector<std::string>> walls_;
  std::shared_ptr<const RetargetMap> map_;
  std::uint64_t mapGeneration_ = 0;
  std::unique_ptr<MapTransfer> transfer_;
  bool failed_ = false;  // a rank was lost: the communicator is not freed
};

}  // namespace confvis

#include "confvis/runtime/frame_sync.hpp"

namespace confvis CONFVIS_API {

// The live view (runLiveView with a FrameSync, live_view.hpp) frame-locked over a Cluster: the
// root decides every frame and sends it to every rank; a new map of the root's follower travels
// in chunks while frames go on (shareMap / progressMaps) and every rank swaps to it on the frame
// whose state names it; the swap lock before present makes every window show the same frame.
// Thread-safety: as Cluster: one thread per process makes every call.
class ClusterFrameSync : public FrameSync {
 public:
  // `firstFrameSeconds`: how long the other ranks wait for the root's first frame and map (the
  // root may still be opening windows or baking).
  explicit ClusterFrameSync(Cluster& cluster, double firstFrameSeconds = 600.0);

  bool decides() const override;
  // Every rank has its windows before the root starts sending the map (opening them may take
  // longer on a loaded machine than the map's broadcast allows).
  void windowsOpen() override;
  SyncedMap exchange(LiveFrameState& state, const FollowerFrame* frame) override;
  // Slower ranks get a few times this rank's render time before they count as lost.
  void beforePresent(double renderSeconds) override;

 private:
  Cluster& cluster_;
  double firstFrameSeconds_;
  // Plain numbers with flags, not optionals: GCC 12 warns of optional compares.
  bool first_ = true, pending_ = false;
  std::uint64_t sharedGeneration_ = 0, pendingGeneration_ = 0;
};

}  // namespace confvis
