#pragma once
// `--cluster` for the offline commands (render, walk): run under mpirun, every rank renders its
// share of the walls and rank 0 writes the outputs, byte for byte those of one process.
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "confvis/backends/render_backend.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/runtime/frame_state.hpp"

namespace confvis {
class Cluster;
}

namespace confvis::cli {

struct ClusterCliOptions {
  bool enabled = false;
  double timeoutSeconds = 5.0;
  bool ignoreNodes = false;  // deal every wall in config order (trying a lab's config on one host)
  // Walks: the ranks split into this many groups, group g rendering frames g, g + G, ... (its
  // walls dealt over its ranks). 0: one group per full set of walls when there are more ranks
  // than walls and no wall names its node, else 1 (addFrameGroupOption makes 0 the default).
  int frameGroups = 1;
};
void addClusterOptions(CLI::App& sub, ClusterCliOptions& options);
// --frame-groups, for the commands that render frames (walk).
void addFrameGroupOption(CLI::App& sub, ClusterCliOptions& options);

// After an error in a --cluster run: waits a moment before the process exits, because the first
// rank to exit makes mpirun end the others, which may not have printed their own message yet.
// Does nothing when no cluster failed.
void lingerAfterClusterError();

// MPI and a Cluster for one command. MPI_Finalize at the end of a successful run only: after an
// error a lost rank could keep MPI_Finalize waiting forever, so the process just exits non-zero
// (mpirun then ends the others).
class CliCluster {
 public:
  // Error(InvalidInput) when confvis was built without MPI. With frame groups (walks), the
  // Cluster spans this rank's group: its root writes the group's frames, decided by rank 0
  // (shareDecision). Every rank's version and config hash is checked against rank 0's.
  CliCluster(const DisplayConfig& display, const ClusterCliOptions& options);
  ~CliCluster();
  CliCluster(const CliCluster&) = delete;
  CliCluster& operator=(const CliCluster&) = delete;

  bool isRoot() const;       // root of this rank's group (of the job without frame groups)
  bool isWorldRoot() const;  // rank 0 of the job: writes the run's report
  int rank() const;          // in the job (MPI_COMM_WORLD)
  int frameGroups() const;   // 1 without frame groups
  int frameGroup() const;    // this rank's group: it renders frames i with i % frameGroups() == it
  const std::vector<std::string>& walls() const;  // this rank's
  // Rank 0's state to every rank; the map of state.mapGeneration is then map().
  void exchangeFrame(ClusterFrameState& state, double patienceSeconds);
  // Frame groups: rank 0's decision for a frame (`state`, and `map` of its generation) to the
  // root of every group, so the follower runs and bakes on rank 0 alone. Collective over the
  // group roots, once per frame in order; returns the map of state.mapGeneration. Without
  // frame groups: returns `map`. `patienceSeconds`: how long rank 0 may still take (bakes).
  std::shared_ptr<const RetargetMap> shareDecision(ClusterFrameState& state,
                                                   std::shared_ptr<const RetargetMap> map,
                                                   double patienceSeconds);
  // Rank 0: `map` to every rank as `generation`, before the frame that names it.
  void shareFrameMap(std::shared_ptr<const RetargetMap> map, std::uint64_t generation);
  std::shared_ptr<const RetargetMap> map() const;
  // The root's map (null on the other ranks, or in plain mode) shared with every rank; returns
  // the map this rank renders with. `patienceSeconds`: how long the root may still bake.
  const RetargetMap* shareMap(const RetargetMap* rootMap, double patienceSeconds);
  // `settings` rendered on this rank's walls; the root gets back every rank's images in the
  // order one process would render them, the other ranks nullopt.
  std::optional<RenderResult> render(RenderBackend& backend, const DisplayConfig& display,
                                     const RetargetMap* map, const RenderSettings& settings);
  // The Cluster itself, for loops of their own (view --cluster); Error(InvalidInput) without MPI.
  Cluster& cluster();
  // A summary for the report: the frame groups and the ranks of this rank's group, their walls.
  nlohmann::json report() const;

 private:
  std::unique_ptr<Cluster> cluster_;
  std::unique_ptr<Cluster> roots_;  // frame groups: the groups' roots (job ranks 0 .. groups - 1)
  int worldRank_ = 0, groups_ = 1, group_ = 0;
};

}  // namespace confvis::cli
