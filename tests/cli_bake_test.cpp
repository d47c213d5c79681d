// End-to-end tests of `confvis bake`: the files it writes, the cache (hit, --no-cache, rebuild of
// a corrupt entry), and one clear error with a non-zero exit for bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_test_support.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;

namespace {

// This file's scratch folder, removed when the test binary exits (bakes are megabytes).
fs::path bakeScratch() { return confvis::testing::scratch("bake"); }
const struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ec;
    fs::remove_all(bakeScratch(), ec);
  }
} scratchCleanup;

// Runs confvis with its bake cache in the scratch folder (never the user's).
CliRun runCli(const std::string& args) {
  return confvis::testing::runCli(args + " --cache-dir " + (bakeScratch() / "cache").string());
}

std::string config(const std::string& name) {
  return (fs::path(CONFVIS_SOURCE_DIR) / "configs" / name).string();
}

// The fast preset: a sixth of the accurate one's bake time (four bakes, ~25 s under ASan
// before); the accurate preset's own files and cache entries: PresetsAreRecorded... below.
TEST(CliBake, WritesMapsSidecarMeshesAndPreviewsThenHitsTheCache) {
  const std::string settings = " --resolution 32 --preset fast -q";
  const fs::path out = bakeScratch() / "cave5";
  const CliRun first = runCli("bake " + config("cave5.json") + " -o " + out.string() + settings);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  for (const char* file : {"ray.exr", "geom.exr", "bake.json", "source.obj", "target.obj",
                           "ray.png", "geom.png", "ray-checker.png", "geom-checker.png",
                           "source-disk.png", "target-disk.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const confvis::LoadedBake loaded = confvis::loadBakeDirectory(out);
  EXPECT_EQ(loaded.map.resolution(), 32);
  EXPECT_EQ(loaded.sidecar["config_name"], "cave5");
  EXPECT_EQ(loaded.sidecar["resolution"], 32);
  for (const char* stage : {"template", "flow", "alignment"})
    EXPECT_TRUE(loaded.sidecar["timings"]["display_map"].contains(stage)) << stage;
  EXPECT_EQ(first.output.find("from the cache"), std::string::npos) << first.output;

  const fs::path again = bakeScratch() / "cave5-again";
  const CliRun second = runCli("bake " + config("cave5.json") + " -o " + again.string() + settings);
  ASSERT_EQ(second.exitCode, 0) << second.output;
  EXPECT_NE(second.output.find("from the cache"), std::string::npos) << second.output;
  EXPECT_EQ(confvis::loadBakeDirectory(again).sidecar, loaded.sidecar);

  // --no-cache recomputes; a different override is a different entry.
  const CliRun uncached = runCli("bake " + config("cave5.json") + " -o " + again.string() +
                                 settings + " --no-cache");
  ASSERT_EQ(uncached.exitCode, 0) << uncached.output;
  EXPECT_EQ(uncached.output.find("from the cache"), std::string::npos) << uncached.output;
  const CliRun moved = runCli("bake " + config("cave5.json") + " -o " + again.string() +
                              settings + " --reference 0.1,0,0.2");
  ASSERT_EQ(moved.exitCode, 0) << moved.output;
  EXPECT_EQ(moved.output.find("from the cache"), std::string::npos) << moved.output;
  EXPECT_EQ(confvis::loadBakeDirectory(again).sidecar["reference"],
            nlohmann::json({0.1, 0.0, 0.2}));
}

TEST(CliBake, CorruptCacheEntryIsRebuilt) {
  const fs::path out = bakeScratch() / "cave6";
  ASSERT_EQ(runCli("bake " + config("cave6.json") + " -o " + out.string() + " --resolution 16 -q")
                .exitCode,
            0);
  // Truncate the cached ray map: the next bake notices, says so, and rebuilds.
  for (const auto& item : fs::recursive_directory_iterator(bakeScratch() / "cache"))
    if (item.path().filename() == "ray.exr" &&
        confvis::loadBakeDirectory(item.path().parent_path()).sidecar["config_name"] == "cave6")
      fs::resize_file(item.path(), 64);
  const CliRun rebuilt =
      runCli("bake " + config("cave6.json") + " -o " + out.string() + " --resolution 16 -q");
  ASSERT_EQ(rebuilt.exitCode, 0) << rebuilt.output;
  EXPECT_NE(rebuilt.output.find("ray.exr"), std::string::npos) << rebuilt.output;
  EXPECT_EQ(rebuilt.output.find("from the cache"), std::string::npos) << rebuilt.output;
  EXPECT_NO_THROW(confvis::loadBakeDirectory(out));
}

// Runs `confvis bake ARGS` and expects a failure (exit code `exitCode`, or any non-zero exit for
// -1) whose output mentions `fragment`.
void expectFailure(const std::string& args, int exitCode, const std::string& fragment) {
  const CliRun run = runCli("bake " + args);
  if (exitCode >= 0) EXPECT_EQ(run.exitCode, exitCode) << args;
  else EXPECT_NE(run.exitCode, 0) << args;
  EXPECT_NE(run.output.find(fragment), std::string::npos) << args << ": " << run.output;
}

// --preset: accurate (the default) halves the config's edges unless --edge-length is given,
// grades the mesh and blends per-vertex Möbius maps (--interpolation overrides that); fast and
// accurate bakes of one config never share a cache entry.
TEST(CliBake, PresetsAreRecordedAndKeepTheirOwnCacheEntries) {
  const fs::path out = bakeScratch() / "presets";
  auto bake = [&](const std::string& extra) {
    const CliRun run = runCli("bake " + config("cave5.json") + " -o " + out.string() +
                              " --resolution 16 --edge-length 0.5 -q" + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return std::make_pair(run, confvis::loadBakeDirectory(out).sidecar);
  };
  const auto [fast, fastSidecar] = bake(" --preset fast");
  EXPECT_EQ(fastSidecar["map_settings"]["grading"], "uniform");
  const auto [accurate, accurateSidecar] = bake("");
  EXPECT_EQ(accurate.output.find("from the cache"), std::string::npos) << accurate.output;
  EXPECT_EQ(accurateSidecar["map_settings"]["grading"]["radius_degrees"], 30.0);
  EXPECT_EQ(fastSidecar["map_settings"]["interpolation"], "linear");
  EXPECT_EQ(accurateSidecar["map_settings"]["interpolation"], "mobius");
  EXPECT_GT(accurateSidecar["meshes"]["target"]["vertices"].get<int>(),
            fastSidecar["meshes"]["target"]["vertices"].get<int>());
  const auto [again, againSidecar] = bake(" --preset fast");
  EXPECT_NE(again.output.find("from the cache"), std::string::npos) << again.output;
  EXPECT_EQ(againSidecar, fastSidecar);
  const auto [linear, linearSidecar] = bake(" --interpolation linear");
  EXPECT_EQ(linear.output.find("from the cache"), std::string::npos) << linear.output;
  EXPECT_EQ(linearSidecar["map_settings"]["interpolation"], "linear");
  EXPECT_EQ(linearSidecar["map_settings"]["grading"], accurateSidecar["map_settings"]["grading"]);
}

TEST(CliBake, BadInputGivesOneClearErrorAndNonZeroExit) {
  expectFailure("/no/such/display.json", 2, "/no/such/display.json");
  // Option checks (CLI11's exit code) name the option.
  expectFailure(config("cave5.json") + " --resolution 4", -1, "--resolution");
  expectFailure(config("cave5.json") + " --resolution many", -1, "--resolution");
  expectFailure(config("cave5.json") + " --edge-length -0.1", -1, "--edge-length");
  expectFailure(config("cave5.json") + " --reference 1,2", -1, "--reference");
  expectFailure(config("cave5.json") + " --reference 1,2,z", -1, "--reference");
  expectFailure(config("cave5.json") + " --preset best", -1, "--preset");
  expectFailure(config("cave5.json") + " --interpolation cubic", -1, "--interpolation");
  // Behind the front wall: the config validation names the wall.
  expectFailure(config("cave5.json") + " --reference 0,0,-2 -q", 2, "front");
  const fs::path garbage = bakeScratch() / "garbage.json";
  std::ofstream(garbage) << "{\"name\": ";
  expectFailure(garbage.string(), 2, "garbage.json");
}

TEST(CliBake, HasHelp) {
  const CliRun run = runCli("bake --help");
  EXPECT_EQ(run.exitCode, 0);
  for (const char* option : {"--output", "--resolution", "--edge-length", "--reference",
                             "--no-cache", "--cache-dir", "--quiet", "--preset", "--interpolation"})
    EXPECT_NE(run.output.find(option), std::string::npos) << option;
}

}  // namespace
