// End-to-end cluster runs under mpirun (Open MPI, all ranks on this machine): the outputs of a
// cluster equal one process's byte for byte, every rank sees the same frames and maps, a
// mismatched config is refused at start, and a rank that stops answering ends every rank within
// the timeout with a message naming it. Own binary and CTest label: ctest -L mpi.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <set>
#include <thread>
#include <vector>

#include "../cli_test_support.hpp"
#include "../projector_sample.hpp"
#include "../screenshot_compare.hpp"
#include "confvis/base/stopwatch.hpp"

namespace fs = std::filesystem;
using confvis::secondsSince;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

// Root may run mpirun only with these; harmless otherwise.
const std::string kMpiEnvironment =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1";

// Everything a command started with popen prints, and its exit status, once it ended.
CliRun finish(FILE* pipe) {
  std::string output;
  char buffer[4096];
  while (pipe && fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// `ranks` copies of `confvis args` under mpirun.
CliRun runMpi(int ranks, const std::string& args) {
  const std::string command = kMpiEnvironment + " " + CONFVIS_MPIEXEC + " --oversubscribe -np " +
                              std::to_string(ranks) + " " + CONFVIS_CLI_PATH + " " + args +
                              " 2>&1";
  return finish(popen(command.c_str(), "r"));
}

std::string bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every image file under `dir` (EXR, PNG), relative paths: the reports hold timings and differ.
std::set<fs::path> images(const fs::path& dir) {
  std::set<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() &&
        (entry.path().extension() == ".exr" || entry.path().extension() == ".png"))
      files.insert(fs::relative(entry.path(), dir));
  return files;
}

void expectSameImages(const fs::path& single, const fs::path& cluster) {
  const std::set<fs::path> expected = images(single);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(images(cluster), expected);
  for (const fs::path& file : expected)
    EXPECT_TRUE(bytes(single / file) == bytes(cluster / file)) << file << " differs";
}

nlohmann::json readJson(const fs::path& file) {
  nlohmann::json j;
  std::ifstream(file) >> j;
  return j;
}

TEST(ClusterCli, RenderOnThreeRanksEqualsOneProcessByteForByte) {
  const std::string common = "render --scale 0.04 -q --scene checker-sphere ";
  const fs::path single = scratch("render-single"), cluster = scratch("render-cluster");
  const CliRun one = runCli(common + "-o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runMpi(3, common + "--cluster -o " + cluster.string());
  ASSERT_EQ(many.exitCode, 0) << many.output;
  expectSameImages(single, cluster);
  // cave5's five walls dealt in config order over three ranks.
  const nlohmann::json ranks = readJson(cluster / "render.json").at("cluster").at("ranks");
  ASSERT_EQ(ranks.size(), 3u);
  EXPECT_EQ(ranks[0].at("walls").size(), 2u);
  EXPECT_EQ(ranks[1].at("walls").size(), 2u);
  EXPECT_EQ(ranks[2].at("walls").size(), 1u);
}

TEST(ClusterCli, PlainStereoOnSixRanksWithAnIdleHeadNodeEqualsOneProcess) {
  const std::string common = "render --scale 0.03 -q --mode plain --eyes stereo ";
  const fs::path single = scratch("plain-single"), cluster = scratch("plain-cluster");
  ASSERT_EQ(runCli(common + "-o " + single.string()).exitCode, 0);
  const CliRun many = runMpi(6, common + "--cluster -o " + cluster.string());
  ASSERT_EQ(many.exitCode, 0) << many.output;
  expectSameImages(single, cluster);
  EXPECT_TRUE(readJson(cluster / "render.json")["cluster"]["ranks"][5]["walls"].empty());
}

TEST(ClusterCli, WalkOnFiveRanksEqualsOneProcessAndSwapsMapsOnTheSameFrame) {
  // The head leaves the 5 cm radius at frame 12; --wait-for-bakes swaps the new map in at the
  // next frame in both runs, whatever the bake costs.
  const std::string common = "walk --frames 16 --fps 8 --scale 0.02 --radius 0.05 "
                             "--bake-resolution 32 --no-pacing --wait-for-bakes -q ";
  const fs::path single = scratch("walk-single"), cluster = scratch("walk-cluster");
  const CliRun one = runCli(common + "-o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runMpi(5, common + "--cluster -o " + cluster.string());
  ASSERT_EQ(many.exitCode, 0) << many.output;
  expectSameImages(single, cluster);

  const nlohmann::json rank0 = readJson(cluster / "cluster-rank-0.json");
  ASSERT_EQ(rank0.at("frames").size(), 16u);
  std::set<std::string> walls;
  for (int r = 0; r < 5; ++r) {
    const nlohmann::json log = readJson(cluster / ("cluster-rank-" + std::to_string(r) + ".json"));
    EXPECT_EQ(log.at("frames"), rank0.at("frames")) << "rank " << r << " saw other frames";
    for (const auto& w : log.at("walls")) walls.insert(w.get<std::string>());
  }
  EXPECT_EQ(walls.size(), 5u);  // every wall drawn by some rank
  // The re-bake happened and was swapped in on one frame number for all ranks.
  const nlohmann::json& frames = rank0.at("frames");
  EXPECT_EQ(frames.front().at("map_generation"), 0);
  EXPECT_GE(frames.back().at("map_generation").get<int>(), 1);
  const nlohmann::json walk = readJson(single / "walk.json");
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(frames[i].at("map_generation"), walk["frames"][i]["map"]["generation"]) << i;
}

TEST(ClusterCli, AMismatchedConfigIsRefusedAtStartNamingTheRank) {
  const fs::path other = scratch("cave5-other.json");
  nlohmann::json config = readJson(fs::path(CONFVIS_SOURCE_DIR) / "configs/cave5.json");
  config["edge_length"] = 0.25;
  std::ofstream(other) << config.dump();
  const std::string base = std::string(CONFVIS_CLI_PATH) + " render --scale 0.02 -q --cluster ";
  const std::string command = kMpiEnvironment + " " + CONFVIS_MPIEXEC +
                              " --oversubscribe -np 1 " + base + "-o " +
                              scratch("mismatch").string() + " : -np 1 " + base + other.string() +
                              " -o " + scratch("mismatch").string() + " 2>&1";
  const CliRun run = finish(popen(command.c_str(), "r"));
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("rank 1 (host"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("config hash"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(scratch("mismatch") / "render.json"));
}

// With frame groups every rank is checked against rank 0 of the job, not only against its
// group's root, and named by its rank in the job: rank 3 is the second rank of group 1.
TEST(ClusterCli, AMismatchedConfigInAnotherFrameGroupIsRefusedNamingItsJobRank) {
  const fs::path other = scratch("cave5-other-group.json");
  nlohmann::json config = readJson(fs::path(CONFVIS_SOURCE_DIR) / "configs/cave5.json");
  config["edge_length"] = 0.25;
  std::ofstream(other) << config.dump();
  const fs::path out = scratch("mismatch-group");
  const std::string base = std::string(CONFVIS_CLI_PATH) +
                           " walk --frames 2 --scale 0.02 --bake-resolution 32 --no-pacing -q "
                           "--cluster --frame-groups 2 -o " + out.string() + " ";
  const std::string command = kMpiEnvironment + " " + CONFVIS_MPIEXEC +
                              " --oversubscribe -np 3 " + base + " : -np 1 " + base +
                              other.string() + " 2>&1";
  const CliRun run = finish(popen(command.c_str(), "r"));
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("rank 3 (host"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("config hash"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out / "walk.json"));
}

// A 3-rank walk long enough to be interrupted; each rank records its pid (exec keeps it), so a
// test can stop or kill one mid-walk as a hung or crashed machine would.
struct RunningWalk {
  FILE* pipe = nullptr;
  fs::path out, pids;

  RunningWalk(const std::string& name, const std::string& options) {
    out = scratch(name);
    pids = scratch(name + "-pids");
    // scratch() is per process id, and ids come round again: a frame or pid file left by an
    // earlier run under the same id would be taken for this walk's (a dead rank's pid).
    fs::remove_all(out);
    fs::remove_all(pids);
    fs::create_directories(pids);
    const std::string walk = std::string(CONFVIS_CLI_PATH) +
                             " walk --frames 400 --fps 8 --scale 0.02 --bake-resolution 32 -q "
                             "--cluster " + options + " -o " + out.string();
    const std::string command = kMpiEnvironment + " " + CONFVIS_MPIEXEC +
                                " --oversubscribe -np 3 sh -c 'echo $$ > " + pids.string() +
                                "/$OMPI_COMM_WORLD_RANK; exec " + walk + "' 2>&1";
    pipe = popen(command.c_str(), "r");
  }
  // Waits until frames flow (rank 0 writes them); the pid of `rank`, 0 if it never started.
  int pidOnceRunning(int rank) const {
    const auto start = std::chrono::steady_clock::now();
    while (!fs::exists(out / "frame-0004") &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    int pid = 0;
    if (fs::exists(out / "frame-0004")) std::ifstream(pids / std::to_string(rank)) >> pid;
    return pid;
  }
  // Everything mpirun and the ranks print, and the exit status, once the job ended.
  CliRun finish() { return ::finish(pipe); }
};

TEST(ClusterCli, ARankThatStopsAnsweringEndsEveryRankWithinTheTimeout) {
  RunningWalk walk("stall", "--cluster-timeout 1");
  ASSERT_NE(walk.pipe, nullptr);
  const int pid = walk.pidOnceRunning(2);
  ASSERT_GT(pid, 0);
  const auto stopped = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(pid, SIGSTOP), 0);
  const CliRun run = walk.finish();
  const double seconds = secondsSince(stopped);
  kill(pid, SIGKILL);  // in case mpirun left it stopped
  EXPECT_NE(run.exitCode, 0) << run.output;
  // 1 s timeout: rank 0 names rank 2 after 1 s, the others leave at once; mpirun then ends the
  // stopped one. Generous bound for a loaded 2-core machine.
  EXPECT_LT(seconds, 15.0) << run.output;
  // Rank 0 finds rank 2 missing at the swap lock and tells rank 1: both name it.
  EXPECT_NE(run.output.find("rank 0: lost rank 2 (host"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("rank 1: lost rank 2 (host"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("no answer within 1 s"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(walk.out / "frame-0399"));
}

TEST(ClusterCli, ARankThatDiesEndsEveryRankAtOnce) {
  RunningWalk walk("killed", "");
  ASSERT_NE(walk.pipe, nullptr);
  const int pid = walk.pidOnceRunning(1);
  ASSERT_GT(pid, 0);
  const auto killed = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  const CliRun run = walk.finish();  // returns only once every rank has ended
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_LT(secondsSince(killed), 15.0) << run.output;  // mpirun itself ends the job
  EXPECT_NE(run.output.find("rank 1"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(walk.out / "frame-0399"));
}

}  // namespace

// Frames split too: two groups of two ranks take turns at frames, each dealing cave5's walls
// over its ranks; the follower decides every frame in each group's root, so the re-bake (head
// out of the 5 cm radius at t = 1.5 s, frame 6) swaps in on the same frame as in one process.
TEST(ClusterCli, WalkSplitOverTwoFrameGroupsEqualsOneProcess) {
  const std::string common = "walk --frames 8 --fps 4 --scale 0.02 --radius 0.05 "
                             "--bake-resolution 32 --no-pacing --wait-for-bakes -q ";
  const fs::path single = scratch("groups-single"), cluster = scratch("groups-cluster");
  const CliRun one = runCli(common + "-o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runMpi(4, common + "--cluster --frame-groups 2 -o " + cluster.string());
  ASSERT_EQ(many.exitCode, 0) << many.output;
  expectSameImages(single, cluster);

  const nlohmann::json walk = readJson(cluster / "walk.json");
  const nlohmann::json reference = readJson(single / "walk.json");
  EXPECT_EQ(walk.at("cluster").at("frame_groups"), 2);
  ASSERT_EQ(walk.at("frames").size(), 8u);
  for (std::size_t i = 0; i < 8; ++i)
    EXPECT_EQ(walk["frames"][i]["map"], reference["frames"][i]["map"]) << i;
  EXPECT_GE(walk["frames"][7]["map"]["generation"].get<int>(), 1);  // the re-bake swapped in
  // Group g (ranks g and g + 2) saw exactly frames g, g + 2, ... and both its ranks the same.
  for (int group = 0; group < 2; ++group) {
    const nlohmann::json a = readJson(cluster / ("cluster-rank-" + std::to_string(group) + ".json"));
    const nlohmann::json b =
        readJson(cluster / ("cluster-rank-" + std::to_string(group + 2) + ".json"));
    EXPECT_EQ(a.at("frames"), b.at("frames")) << "group " << group;
    ASSERT_EQ(a.at("frames").size(), 4u);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a["frames"][k]["frame"], group + 2 * k);
    EXPECT_EQ(a.at("walls").size() + b.at("walls").size(), 5u);  // the walls split too
    // The maps are baked once, on rank 0: no other group's root runs a follower.
    EXPECT_EQ(a.at("runs_follower"), group == 0);
    EXPECT_EQ(b.at("runs_follower"), false);
  }
}

// More ranks than walls: a one-wall display on two ranks splits the frames by default.
TEST(ClusterCli, WalkWithMoreRanksThanWallsSplitsFramesByDefault) {
  const std::string common = "walk " + std::string(CONFVIS_SOURCE_DIR) +
                             "/configs/flat-wall.json --frames 4 --fps 4 --scale 0.02 "
                             "--radius 1 --bake-resolution 32 --no-pacing -q ";
  const fs::path single = scratch("split-single"), cluster = scratch("split-cluster");
  const CliRun one = runCli(common + "-o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runMpi(2, common + "--cluster -o " + cluster.string());
  ASSERT_EQ(many.exitCode, 0) << many.output;
  expectSameImages(single, cluster);
  EXPECT_EQ(readJson(cluster / "walk.json").at("cluster").at("frame_groups"), 2);
  EXPECT_EQ(readJson(cluster / "cluster-rank-1.json").at("frames").size(), 2u);
}

// `confvis view --cluster` under xvfb-run: three ranks show cave5's five walls live, rank 0
// tracking a recorded head path; every rank's frame log holds the same frame states (head,
// camera, map generation), and the last one ends every rank.
TEST(ClusterCli, LiveViewOnThreeRanksShowsTheSameFrameStatesOnEveryRank) {
  if (::access("/usr/bin/xvfb-run", X_OK) != 0) GTEST_SKIP() << "no xvfb-run (Debian: xvfb)";
  const fs::path out = scratch("view-cluster");
  const std::string command =
      "xvfb-run -a env " + kMpiEnvironment + " " + CONFVIS_MPIEXEC + " --oversubscribe -np 3 " +
      CONFVIS_CLI_PATH + " view --cluster --frames 6 --scale 0.05 --bake-resolution 32 " +
      "--no-vsync -q --tracker path:" + CONFVIS_SOURCE_DIR + "/configs/paths/cave-walk.csv -o " +
      out.string() + " 2>&1";
  const CliRun run = finish(popen(command.c_str(), "r"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json rank0 = readJson(out / "cluster-rank-0.json");
  const nlohmann::json& frames = rank0.at("frames");
  ASSERT_EQ(frames.size(), 6u);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].at("frame"), i);
    EXPECT_EQ(frames[i].at("quit"), i + 1 == frames.size());
  }
  // Rank 0's clock went on: the states are not all the same default.
  for (std::size_t i = 1; i < frames.size(); ++i)
    EXPECT_GT(frames[i].at("seconds").get<double>(), frames[i - 1].at("seconds").get<double>());
  std::set<std::string> walls;
  for (int r = 0; r < 3; ++r) {
    const nlohmann::json log = readJson(out / ("cluster-rank-" + std::to_string(r) + ".json"));
    EXPECT_EQ(log.at("frames"), frames) << "rank " << r << " showed other frames";
    for (const auto& w : log.at("walls")) walls.insert(w.get<std::string>());
  }
  EXPECT_EQ(walls.size(), 5u);  // every wall shown by some rank
  EXPECT_EQ(readJson(out / "view.json").at("frame_count"), 6);
}

namespace {

// `confvis ARGS` under xvfb-run: one process, or `ranks` of them under mpirun.
CliRun runViewOnDisplay(const std::string& args, int ranks = 0) {
  const std::string launcher =
      ranks == 0 ? std::string()
                 : "env " + kMpiEnvironment + " " + CONFVIS_MPIEXEC + " --oversubscribe -np " +
                       std::to_string(ranks) + " ";
  return finish(popen(("xvfb-run -a " + launcher + CONFVIS_CLI_PATH + " " + args + " 2>&1").c_str(),
                      "r"));
}

// Rank r's view report: rank 0 writes view.json, the others view-rank-R.json.
nlohmann::json viewReport(const fs::path& out, int rank) {
  return readJson(out / (rank == 0 ? "view.json" : "view-rank-" + std::to_string(rank) + ".json"));
}

}  // namespace

// The cluster view is the live view with a frame sync: on three ranks the Vulkan frames stay on
// each rank's GPU, each rank screenshots its own walls and reports its own validation counts,
// and every wall's screenshot equals the single-process view's of the same wall.
TEST(ClusterCli, LiveViewScreenshotsOnThreeRanksEqualTheSingleProcessView) {
  if (::access("/usr/bin/xvfb-run", X_OK) != 0) GTEST_SKIP() << "no xvfb-run (Debian: xvfb)";
  const std::string common = "view --backend vulkan --frames 2 --scale 0.05 --bake-resolution 32 "
                             "--no-vsync --validate -q ";
  const fs::path single = scratch("view-shots-single"), cluster = scratch("view-shots-cluster");
  const CliRun one = runViewOnDisplay(common + "--screenshot-dir " + (single / "shots").string() +
                                      " -o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runViewOnDisplay(common + "--cluster --screenshot-dir " +
                                           (cluster / "shots").string() + " -o " +
                                           cluster.string(),
                                       3);
  ASSERT_EQ(many.exitCode, 0) << many.output;

  std::vector<std::string> walls;
  for (int rank = 0; rank < 3; ++rank) {
    SCOPED_TRACE("rank " + std::to_string(rank));
    const nlohmann::json report = viewReport(cluster, rank);
    EXPECT_EQ(report.at("frame_count"), 2);
    EXPECT_EQ(report.at("frame_path"), "gpu");  // rendered on the presenting device
    EXPECT_EQ(report.at("validation").at("enabled"), true);
    EXPECT_EQ(report.at("validation").at("errors"), 0) << report["validation"].dump();
    const nlohmann::json mine =
        readJson(cluster / ("cluster-rank-" + std::to_string(rank) + ".json")).at("walls");
    ASSERT_EQ(report.at("windows").size(), mine.size());  // its own walls' windows only
    for (const nlohmann::json& window : report.at("windows")) {
      EXPECT_NE(std::find(mine.begin(), mine.end(), window.at("wall")), mine.end());
      EXPECT_EQ(window.at("screenshot"), window.at("wall").get<std::string>() + ".png");
      walls.push_back(window.at("wall"));
    }
  }
  ASSERT_EQ(walls.size(), 5u);  // cave5: every wall on some rank
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const std::string file = walls[w] + ".png";
    EXPECT_LE(confvis::testing::badPixelFraction(single / "shots" / file, cluster / "shots" / file),
              confvis::testing::kScreenshotBadBudget)
        << file;
    // Broken on purpose: another wall's picture must fail the same check.
    const std::string other = walls[(w + 1) % walls.size()] + ".png";
    EXPECT_GT(confvis::testing::badPixelFraction(single / "shots" / other, cluster / "shots" / file),
              confvis::testing::kScreenshotBadBudget)
        << file << " against " << other;
  }
}

// Edge blending in the cluster view: a blended projection wall on two ranks (the sample's nodes
// ignored) presents every window as the single-process view does, blend included.
TEST(ClusterCli, BlendedProjectorWallOnTwoRanksEqualsTheSingleProcessView) {
  if (::access("/usr/bin/xvfb-run", X_OK) != 0) GTEST_SKIP() << "no xvfb-run (Debian: xvfb)";
  const fs::path config =
      confvis::testing::importedProjectorConfig("cluster-projectors", " --edge-blend 2.2");
  const std::string common = "view " + config.string() +
                             " --frames 2 --scale 0.05 --bake-resolution 32 --no-vsync -q ";
  const fs::path single = scratch("blend-single"), cluster = scratch("blend-cluster");
  const CliRun one = runViewOnDisplay(common + "--screenshot-dir " + (single / "shots").string() +
                                      " -o " + single.string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CliRun many = runViewOnDisplay(common + "--cluster --cluster-ignore-nodes --screenshot-dir " +
                                           (cluster / "shots").string() + " -o " +
                                           cluster.string(),
                                       2);
  ASSERT_EQ(many.exitCode, 0) << many.output;
  for (int rank = 0; rank < 2; ++rank) EXPECT_EQ(viewReport(cluster, rank).at("edge_blend"), true);
  for (const char* wall : {"preview", "projector-left", "projector-right"}) {
    const std::string file = std::string(wall) + ".png";
    EXPECT_LE(confvis::testing::badPixelFraction(single / "shots" / file, cluster / "shots" / file),
              confvis::testing::kScreenshotBadBudget)
        << file;
  }
  // Broken on purpose: the plain (unblended) projector is not what the cluster presented.
  const fs::path plainConfig = confvis::testing::importedProjectorConfig("cluster-projectors-plain", "");
  const fs::path plain = scratch("blend-plain");
  ASSERT_EQ(runViewOnDisplay("view " + plainConfig.string() +
                             " --frames 2 --scale 0.05 --bake-resolution 32 --no-vsync -q "
                             "--screenshot-dir " + (plain / "shots").string() + " -o " +
                             plain.string())
                .exitCode,
            0);
  EXPECT_GT(confvis::testing::badPixelFraction(plain / "shots/projector-left.png",
                                               cluster / "shots/projector-left.png"),
            confvis::testing::kScreenshotBadBudget);
}

// A rank without walls (a head node) runs the same loop without a device or windows: it gets
// every frame state, renders nothing and ends with rank 0.
TEST(ClusterCli, LiveViewRankWithoutWallsOpensNothingAndFollowsTheFrames) {
  if (::access("/usr/bin/xvfb-run", X_OK) != 0) GTEST_SKIP() << "no xvfb-run (Debian: xvfb)";
  const fs::path out = scratch("view-head-node");
  const CliRun run = runViewOnDisplay("view " + std::string(CONFVIS_SOURCE_DIR) +
                                          "/configs/flat-wall.json --cluster --frames 3 "
                                          "--scale 0.05 --bake-resolution 32 --no-vsync -q -o " +
                                          out.string(),
                                      2);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json head = viewReport(out, 1);
  EXPECT_EQ(head.at("windows").size(), 0u);
  EXPECT_EQ(head.at("present_device"), "none");
  EXPECT_EQ(head.at("frame_count"), 3);
  EXPECT_EQ(viewReport(out, 0).at("windows").size(), 1u);
  EXPECT_EQ(readJson(out / "cluster-rank-1.json").at("frames"),
            readJson(out / "cluster-rank-0.json").at("frames"));
}
