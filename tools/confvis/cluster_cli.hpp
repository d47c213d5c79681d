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
};
void addClusterOptions(CLI::App& sub, ClusterCliOptions& options);

// After an error in a --cluster run: waits a moment before the process exits, because the first
// rank to exit makes mpirun end the others, which may not have printed their own message yet.
// Does nothing when no cluster failed.
void lingerAfterClusterError();

// MPI and a Cluster for one command. MPI_Finalize at the end of a successful run only: after an
// error a lost rank could keep MPI_Finalize waiting forever, so the process just exits non-zero
// (mpirun then ends the others).
class CliCluster {
 public:
  // Error(InvalidInput) when confvis was built without MPI.
  CliCluster(const DisplayConfig& display, const ClusterCliOptions& options);
  ~CliCluster();
  CliCluster(const CliCluster&) = delete;
  CliCluster& operator=(const CliCluster&) = delete;

  bool isRoot() const;
  int rank() const;
  const std::vector<std::string>& walls() const;  // this rank's
  // Rank 0's state to every rank; the map of state.mapGeneration is then map().
  void exchangeFrame(ClusterFrameState& state, double patienceSeconds);
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
  // A summary for the report: ranks and their walls.
  nlohmann::json report() const;

 private:
  std::unique_ptr<Cluster> cluster_;
};

}  // namespace confvis::cli
