#include "cluster_view.hpp"

#include <string>

#include "confvis/base/error.hpp"
#ifdef CONFVIS_HAVE_CLUSTER
#include "confvis/runtime/cluster.hpp"
#endif

namespace confvis::cli {

#ifdef CONFVIS_HAVE_CLUSTER

namespace {

nlohmann::json stateJson(const LiveFrameState& s) {
  auto vec = [](const glm::dvec3& v) { return nlohmann::json{v.x, v.y, v.z}; };
  return {{"frame", s.frame},
          {"seconds", s.seconds},
          {"head", {{"position", vec(s.head.position)},
                    {"orientation", {s.head.orientation.w, s.head.orientation.x,
                                     s.head.orientation.y, s.head.orientation.z}}}},
          {"camera", {{"position", vec(s.camera.position)}, {"yaw", s.camera.yawDegrees},
                      {"pitch", s.camera.pitchDegrees}}},
          {"map_generation", s.mapGeneration},
          {"conformal", s.conformal},
          {"quit", s.quit}};
}

// The cluster's frame sync, keeping every frame state this rank rendered (cluster-rank-N.json).
class LoggedFrameSync final : public ClusterFrameSync {
 public:
  using ClusterFrameSync::ClusterFrameSync;
  SyncedMap exchange(LiveFrameState& state, const FollowerFrame* frame) override {
    SyncedMap map = ClusterFrameSync::exchange(state, frame);
    if (!state.stop) frames.push_back(stateJson(state));  // a stopping frame is not rendered
    return map;
  }
  nlohmann::json frames = nlohmann::json::array();
};

}  // namespace

ClusterViewResult runClusterView(CliCluster& cli, const DisplayConfig& config,
                                 const LiveBackendFactory& makeBackend, MapFollower* follower,
                                 Tracker* tracker, LiveViewOptions options) {
  Cluster& cluster = cli.cluster();
  if (cluster.isRoot() && !follower)
    throw Error(ErrorCode::Internal, "view --cluster: rank 0 needs the follower");
  options.walls = cluster.walls();
  options.windowTitle += " (rank " + std::to_string(cli.rank()) + ")";
  options.showProgress = options.showProgress && cluster.isRoot();
  LoggedFrameSync sync(cluster);
  ClusterViewResult result;
  result.report = runLiveView(config, makeBackend, follower, tracker, options, sync);
  result.report["cluster"] = cli.report();
  result.frames = std::move(sync.frames);
  return result;
}

#else

ClusterViewResult runClusterView(CliCluster&, const DisplayConfig&, const LiveBackendFactory&,
                                 MapFollower*, Tracker*, LiveViewOptions) {
  throw Error(ErrorCode::InvalidInput,
              "--cluster: this confvis was built without MPI (install libopenmpi-dev and "
              "rebuild with CONFVIS_CLUSTER=ON)");
}

#endif

}  // namespace confvis::cli
