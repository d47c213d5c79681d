#pragma once
// `confvis view --cluster`: the live view (runLiveView) frame-locked over the ranks of an MPI
// job through ClusterFrameSync. Every rank opens the windows of its own walls only; rank 0 owns
// tracking, navigation (its windows' keys and mouse), the map follower and the end of the run,
// and sends one frame state to every rank each frame (frame number, time, head, camera, map
// generation, conformal or plain). A new map travels in chunks while frames go on and every rank
// swaps to it on the same frame; a swap lock before present makes every window show the same
// frame. Each rank gets what the single view has: the GPU frame path for Vulkan, screenshots of
// its walls, window titles, validation counts.
#include <nlohmann/json.hpp>

#include "cluster_cli.hpp"
#include "confvis/runtime/live_view.hpp"

namespace confvis::cli {

struct ClusterViewResult {
  nlohmann::json report;  // what runLiveView reports for this rank; rank 0's with "cluster"
  nlohmann::json frames = nlohmann::json::array();  // every rank: the frame states it rendered
};

// `follower` and `tracker` on rank 0 only (null elsewhere; the tracker may be null on rank 0
// too). Error(InvalidInput) when confvis was built without MPI.
ClusterViewResult runClusterView(CliCluster& cluster, const DisplayConfig& config,
                                 const LiveBackendFactory& makeBackend, MapFollower* follower,
                                 Tracker* tracker, LiveViewOptions options);

}  // namespace confvis::cli
