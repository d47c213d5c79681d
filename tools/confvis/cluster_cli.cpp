#include "cluster_cli.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <thread>

#include "command.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#ifdef CONFVIS_HAVE_CLUSTER
#include "confvis/runtime/cluster.hpp"
#endif

namespace confvis::cli {

void addClusterOptions(CLI::App& sub, ClusterCliOptions& options) {
  sub.add_flag("--cluster", options.enabled,
               "Run as one rank of an MPI job (mpirun -np N confvis ...): the walls are dealt to "
               "the ranks (a wall's \"node\" picks its rank or host), rank 0 writes the outputs");
  sub.add_option("--cluster-timeout", options.timeoutSeconds,
                 "Seconds a rank waits for another before ending the job with an error naming it")
      ->check(kPositiveNumber)
      ->capture_default_str();
  sub.add_flag("--cluster-ignore-nodes", options.ignoreNodes,
               "Deal the walls to the ranks in config order, whatever host their \"node\" names "
               "(a lab's cluster config tried on one machine)");
}

void addFrameGroupOption(CLI::App& sub, ClusterCliOptions& options) {
  options.frameGroups = 0;  // chosen from the ranks and walls unless given
  sub.add_option("--frame-groups", options.frameGroups,
                 "--cluster: split the ranks into N groups that take turns at frames (group g "
                 "renders frames g, g+N, ...), each dealing the walls over its ranks; default: "
                 "ranks / walls when there are more ranks than walls and no wall names its node")
      ->check(CLI::Range(1, 1 << 20));
}

namespace {
bool clusterFailed = false;  // a CliCluster was left by an exception
}  // namespace

void lingerAfterClusterError() {
  if (clusterFailed) std::this_thread::sleep_for(std::chrono::seconds(1));
}

#ifdef CONFVIS_HAVE_CLUSTER

CliCluster::CliCluster(const DisplayConfig& display, const ClusterCliOptions& options) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;  // only this thread talks to MPI; bakes run on threads of their own
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  }
  DisplayConfig dealt = display;  // same hash on every rank: only the dealing changes
  if (options.ignoreNodes)
    for (Wall& wall : dealt.walls) wall.node.clear();
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &worldRank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int walls = static_cast<int>(dealt.walls.size());
  const bool nodesNamed = std::any_of(dealt.walls.begin(), dealt.walls.end(),
                                      [](const Wall& w) { return !w.node.empty(); });
  groups_ = options.frameGroups > 0 ? std::min(options.frameGroups, size)
            : (size > walls && !nodesNamed) ? size / walls
                                            : 1;
  if (groups_ == 1) {
    cluster_ = std::make_unique<Cluster>(MPI_COMM_WORLD, dealt,
                                         ClusterOptions{.timeoutSeconds = options.timeoutSeconds});
    return;
  }
  // Every rank against rank 0 of the job (version, config hash; the messages name job ranks),
  // before the groups check their ranks against their own roots. The dealing of these two
  // checks does not matter: the walls without nodes.
  DisplayConfig undealt = dealt;
  for (Wall& wall : undealt.walls) wall.node.clear();
  const ClusterOptions clusterOptions{.timeoutSeconds = options.timeoutSeconds};
  { const Cluster everyRank(MPI_COMM_WORLD, undealt, clusterOptions); }
  // Group g: ranks g, g + G, ...; rank g is its root. The Clusters keep duplicates.
  group_ = worldRank_ % groups_;
  MPI_Comm groupComm = MPI_COMM_NULL, rootsComm = MPI_COMM_NULL;
  MPI_Comm_split(MPI_COMM_WORLD, group_, worldRank_, &groupComm);
  MPI_Comm_split(MPI_COMM_WORLD, worldRank_ < groups_ ? 0 : MPI_UNDEFINED, worldRank_, &rootsComm);
  cluster_ = std::make_unique<Cluster>(groupComm, dealt, clusterOptions);
  MPI_Comm_free(&groupComm);
  if (rootsComm != MPI_COMM_NULL) {
    roots_ = std::make_unique<Cluster>(rootsComm, undealt, clusterOptions);
    MPI_Comm_free(&rootsComm);
  }
}

CliCluster::~CliCluster() {
  if (std::uncaught_exceptions() > 0) {  // see the class comment
    clusterFailed = true;
    return;
  }
  roots_.reset();
  cluster_.reset();
  MPI_Finalize();
}

bool CliCluster::isRoot() const { return cluster_->isRoot(); }
bool CliCluster::isWorldRoot() const { return worldRank_ == 0; }
Cluster& CliCluster::cluster() { return *cluster_; }
int CliCluster::rank() const { return worldRank_; }
int CliCluster::frameGroups() const { return groups_; }
int CliCluster::frameGroup() const { return group_; }
const std::vector<std::string>& CliCluster::walls() const { return cluster_->walls(); }
void CliCluster::exchangeFrame(ClusterFrameState& state, double patienceSeconds) {
  cluster_->exchangeFrame(state, patienceSeconds);
}
void CliCluster::shareFrameMap(std::shared_ptr<const RetargetMap> map, std::uint64_t generation) {
  cluster_->shareMapNow(std::move(map), generation);
}

namespace {
// Rank 0's decision as the group roots receive it: the frame's state, and whether the map of
// its generation follows (the state names the map the roots hold, so nothing is swapped early).
struct Decision : ClusterFrameState {
  std::uint64_t generation = 0;
  bool newMap = false;
};
}  // namespace

std::shared_ptr<const RetargetMap> CliCluster::shareDecision(
    ClusterFrameState& state, std::shared_ptr<const RetargetMap> map, double patienceSeconds) {
  if (!roots_) return map;
  Decision decision;
  static_cast<ClusterFrameState&>(decision) = state;
  decision.generation = state.mapGeneration;
  decision.newMap = !roots_->map() || roots_->mapGeneration() != state.mapGeneration;
  decision.mapGeneration = roots_->mapGeneration();
  roots_->exchangeFrame(decision, patienceSeconds);
  if (decision.newMap) {
    // The other roots may still be rendering their last frame: all of them meet first, then
    // the map goes out in chunks while every root waits for it.
    roots_->swapLock(patienceSeconds);
    roots_->shareMapNow(std::move(map), decision.generation, patienceSeconds);
  }
  state = decision;
  state.mapGeneration = decision.generation;
  return roots_->map();
}
std::shared_ptr<const RetargetMap> CliCluster::map() const { return cluster_->map(); }

const RetargetMap* CliCluster::shareMap(const RetargetMap* rootMap, double patienceSeconds) {
  std::shared_ptr<const RetargetMap> copy;
  if (isRoot() && rootMap) copy = std::make_shared<RetargetMap>(*rootMap);
  // Every rank learns from the root whether there is a map at all (plain mode has none).
  ClusterFrameState state;
  state.mapGeneration = copy ? 1 : 0;
  cluster_->exchangeFrame(state, patienceSeconds);
  if (state.mapGeneration == 0) return nullptr;
  cluster_->shareMapNow(std::move(copy), 1);
  return cluster_->map().get();
}

std::optional<RenderResult> CliCluster::render(RenderBackend& backend,
                                               const DisplayConfig& display,
                                               const RetargetMap* map,
                                               const RenderSettings& settings) {
  RenderSettings mine = settings;
  mine.walls.clear();
  for (const std::string& wall : cluster_->walls())
    if (settings.walls.empty() ||
        std::find(settings.walls.begin(), settings.walls.end(), wall) != settings.walls.end())
      mine.walls.push_back(wall);
  const auto start = SteadyClock::now();
  RenderResult result;  // a rank without walls renders nothing (empty walls would mean all)
  if (!mine.walls.empty()) result = backend.render(display, map, mine);
  const double seconds = secondsSince(start);
  // Other ranks may draw more than this one: wait a few times this rank's own time for them.
  // The swap lock first: a rank that stopped answering is named to every rank there.
  const double patience = 4.0 * seconds + 1.0;
  cluster_->swapLock(patience);
  RenderResult all = cluster_->gatherImages(result, display, settings.eyes, patience);
  if (!isRoot()) return std::nullopt;
  return all;
}

nlohmann::json CliCluster::report() const {
  nlohmann::json ranks = nlohmann::json::array();
  for (int r = 0; r < cluster_->size(); ++r)  // group rank r is job rank group + r * groups
    ranks.push_back({{"rank", group_ + r * groups_},
                     {"host", cluster_->host(r)},
                     {"walls", cluster_->wallsOf(r)}});
  return {{"ranks", ranks}, {"frame_groups", groups_}};
}

#else

CliCluster::CliCluster(const DisplayConfig&, const ClusterCliOptions&) {
  throw Error(ErrorCode::InvalidInput,
              "--cluster: this confvis was built without MPI (install libopenmpi-dev and "
              "rebuild with CONFVIS_CLUSTER=ON)");
}
CliCluster::~CliCluster() = default;
bool CliCluster::isRoot() const { return true; }
bool CliCluster::isWorldRoot() const { return true; }
Cluster& CliCluster::cluster() {
  throw Error(ErrorCode::InvalidInput, "--cluster: this confvis was built without MPI");
}
int CliCluster::rank() const { return 0; }
int CliCluster::frameGroups() const { return 1; }
int CliCluster::frameGroup() const { return 0; }
const std::vector<std::string>& CliCluster::walls() const {
  static const std::vector<std::string> none;
  return none;
}
void CliCluster::exchangeFrame(ClusterFrameState&, double) {}
void CliCluster::shareFrameMap(std::shared_ptr<const RetargetMap>, std::uint64_t) {}
std::shared_ptr<const RetargetMap> CliCluster::shareDecision(ClusterFrameState&,
                                                             std::shared_ptr<const RetargetMap> map,
                                                             double) {
  return map;
}
std::shared_ptr<const RetargetMap> CliCluster::map() const { return nullptr; }
const RetargetMap* CliCluster::shareMap(const RetargetMap* map, double) { return map; }
std::optional<RenderResult> CliCluster::render(RenderBackend& backend, const DisplayConfig& d,
                                               const RetargetMap* map, const RenderSettings& s) {
  return backend.render(d, map, s);
}
nlohmann::json CliCluster::report() const { return nullptr; }

#endif

}  // namespace confvis::cli
