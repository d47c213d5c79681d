// Hostile and real-world input at the command line (each finding against its own minimal file in
// tests/data/hostile/ or one written here): names that would place files outside the output
// directory, input that crashed or hung, baked maps that rendered garbage with exit 0, and
// failed writes that left truncated files. Every case ends in one clear error naming the
// culprit and exit 2; "unexpected error" (a bug) never appears.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

std::string hostile(const std::string& name) {
  return (fs::path(CONFVIS_SOURCE_DIR) / "tests" / "data" / "hostile" / name).string();
}

std::string shipped(const std::string& name) {
  return (fs::path(CONFVIS_SOURCE_DIR) / "configs" / name).string();
}

// Exit 2 (a confvis::Error) with every fragment in the output, and never "unexpected error".
void expectRefused(const CliRun& run, std::initializer_list<std::string> fragments) {
  EXPECT_EQ(run.exitCode, 2) << run.output;
  for (const std::string& fragment : fragments)
    EXPECT_NE(run.output.find(fragment), std::string::npos) << fragment << " in\n" << run.output;
  EXPECT_EQ(run.output.find("unexpected error"), std::string::npos) << run.output;
}

std::size_t filesUnder(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) n += entry.is_regular_file();
  return n;
}

// A fresh directory with a/b inside; the command runs in a/b.
fs::path nest(const std::string& name) {
  const fs::path root = scratch(name);
  fs::remove_all(root);
  fs::create_directories(root / "a" / "b");
  return root;
}

std::string deepConfig() {
  const fs::path file = scratch("deep.json");
  std::string text = confvis::readTextFile(shipped("flat-wall.json"));
  const std::string key = "\"cube_resolution\": 256";
  text.replace(text.find(key), key.size(),
               "\"cube_resolution\": " + std::string(100000, '[') + std::string(100000, ']'));
  confvis::writeTextAtomically(file, text);
  return file.string();
}

}  // namespace

// A wall named ../../escape made render write two levels above -o.
TEST(CliHostile, WallNameThatLeavesTheOutputDirectoryIsRefused) {
  const fs::path root = nest("wall-escape");
  const CliRun run = runCli("render " + hostile("wall-escape.json") + " --mode plain -q -o out",
                            "cd " + (root / "a" / "b").string() + " &&");
  expectRefused(run, {"wall-escape.json", "wall name '../../escape'", "path separator"});
  EXPECT_EQ(filesUnder(root), 0u);
}

// A display named /abs/x moved bake's default output directory to /abs/x-bake.
TEST(CliHostile, DisplayNamesThatLeaveTheWorkingDirectoryAreRefused) {
  const fs::path root = nest("display-escape");
  const std::string inB = "cd " + (root / "a" / "b").string() + " &&";
  expectRefused(runCli("bake " + hostile("display-absolute.json") + " --no-cache -q", inB),
                {"display name '/abs/x'"});
  expectRefused(runCli("render " + hostile("display-escape.json") + " --mode plain -q", inB),
                {"display name '../../x'"});
  EXPECT_EQ(filesUnder(root), 0u);
  EXPECT_FALSE(fs::exists("/abs/x-bake"));
}

// A NUL in a wall name cut the file name short: the PNG overwrote the EXR, exit 0.
TEST(CliHostile, NulInAWallNameIsRefused) {
  const fs::path root = nest("wall-nul");
  const CliRun run = runCli("render " + hostile("wall-nul.json") + " --mode plain -q -o out",
                            "cd " + (root / "a" / "b").string() + " &&");
  expectRefused(run, {"wall name 'screen\\x00.exr'", "NUL"});
  EXPECT_EQ(filesUnder(root), 0u);
}

// 100 000 nested '[' in a config value: a stack overflow (exit 139) in every command reading one.
TEST(CliHostile, DeeplyNestedConfigIsRefusedByEveryCommand) {
  const std::string deep = deepConfig();
  const std::string out = " -o " + scratch("deep-out").string();
  for (const std::string& command :
       {"render " + deep + " --mode plain -q" + out, "bake " + deep + " --no-cache -q" + out,
        "import " + deep + out + "/c.json", "walk " + deep + " --frames 1 -q" + out})
    expectRefused(runCli(command), {"deep.json", "nested deeper than 64"});
}

// A 1e12 m wall hung the template builder before its size guard.
TEST(CliHostile, HugeWallIsRefusedAtLoad) {
  expectRefused(runCli("bake " + hostile("huge-wall.json") + " --no-cache -q -o " +
                       scratch("huge").string()),
                {"huge-wall.json", "wall 'screen'", "corner coordinate"});
}

// --camera 1.9e18,0,0 aborted on an Embree assertion (exit 134).
TEST(CliHostile, AbsurdNumbersOnTheCommandLineAreRefused) {
  const std::string render = "render " + shipped("cave5.json") + " --mode plain -q -o " +
                             scratch("absurd").string();
  expectRefused(runCli(render + " --camera 1.9e18,0,0"), {"virtual camera position"});
  expectRefused(runCli(render + " --camera 0,0,0,1e300,0"), {"virtual camera yaw"});
  expectRefused(runCli(render + " --scale 1e300"), {"resolution scale"});
  expectRefused(runCli(render + " --scene-scale 1e300"), {"non-finite position"});
}

// Two bare EXRs under --map were used unchecked: swapped ray/geom rendered with exit 0.
TEST(CliHostile, MapDirectoryWithoutBakeJsonIsRefused) {
  const fs::path map = scratch("bare-map");
  fs::remove_all(map);
  confvis::writeRetargetMapDirectory(map, confvis::ceilinglessDilationMap(1.5, 16));
  fs::remove(map / "bake.json");
  expectRefused(runCli("render " + shipped("cave5.json") + " --map " + map.string() + " -q -o " +
                       scratch("bare-out").string()),
                {"has no bake.json"});
}

TEST(CliHostile, SwappedMapsAreRefused) {
  const fs::path map = scratch("swapped-map");
  fs::remove_all(map);
  confvis::writeRetargetMapDirectory(map, confvis::ceilinglessDilationMap(1.5, 16));
  fs::rename(map / "ray.exr", map / "tmp.exr");
  fs::rename(map / "geom.exr", map / "ray.exr");
  fs::rename(map / "tmp.exr", map / "geom.exr");
  const std::string render = "render " + shipped("cave5.json") + " --map " + map.string() +
                             " -q -o " + scratch("swapped-out").string();
  expectRefused(runCli(render), {"swapped-map", "bytes, bake.json says"});
  // Sizes swapped in bake.json too (or maps of equal size): the checksums tell them apart.
  nlohmann::json sidecar = nlohmann::json::parse(confvis::readTextFile(map / "bake.json"));
  std::swap(sidecar["files"]["ray.exr"]["bytes"], sidecar["files"]["geom.exr"]["bytes"]);
  confvis::writeTextAtomically(map / "bake.json", sidecar.dump());
  expectRefused(runCli(render), {"swapped-map", "does not match its checksum"});
}

// One bit of ray.exr's header turns a channel's pixel type from FLOAT (2) into UINT (0); it read
// back converted and rendered wrong images. Caught by the checksum, and with a forged
// checksum still by the pixel type.
TEST(CliHostile, OneBitFlipInAChannelTypeIsRefused) {
  const fs::path map = scratch("flipped-map");
  fs::remove_all(map);
  confvis::writeRetargetMapDirectory(map, confvis::ceilinglessDilationMap(1.5, 16));
  std::string bytes = confvis::readTextFile(map / "ray.exr");
  const std::size_t channel = bytes.find(std::string("R\0", 2), bytes.find("chlist"));
  ASSERT_NE(channel, std::string::npos);
  ASSERT_EQ(bytes[channel + 2], '\x02');  // FLOAT
  bytes[channel + 2] ^= '\x02';           // UINT
  confvis::writeTextAtomically(map / "ray.exr", bytes);
  const std::string render = "render " + shipped("cave5.json") + " --map " + map.string() +
                             " -q -o " + scratch("flipped-out").string();
  expectRefused(runCli(render), {"ray.exr does not match its checksum"});
  nlohmann::json sidecar = nlohmann::json::parse(confvis::readTextFile(map / "bake.json"));
  sidecar["files"]["ray.exr"]["fnv1a64"] = confvis::fileChecksum(map / "ray.exr");
  confvis::writeTextAtomically(map / "bake.json", sidecar.dump());
  expectRefused(runCli(render), {"channel 'R' is not float32"});
}

// A full disk: OpenMesh's writer reported success and a truncated file stayed behind, exit 0.
// The file-size limit (ulimit -f, SIGXFSZ ignored) makes writes fail past 1 KiB.
TEST(CliHostile, MeshWriteFailureExitsNonZeroAndLeavesNoFile) {
  const fs::path dir = scratch("full-disk");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const CliRun run = runCli("mesh hemisphere -n 64 -o " + (dir / "h.obj").string(),
                            "trap '' XFSZ; ulimit -f 1;");
  expectRefused(run, {"h.obj"});
  EXPECT_EQ(filesUnder(dir), 0u);  // no truncated file, no temporary
  expectRefused(runCli("mesh hemisphere -n 8 -o /dev/full"), {"/dev/full"});
}

// Malformed mesh files through `confvis flow`: a crash (139) or std::bad_alloc (exit 3) before.
TEST(CliHostile, MalformedMeshFilesAreRefusedByFlow) {
  for (const char* file : {"face-inf.ply", "elument.ply", "valence-minus-one.off", "nan.stl"})
    expectRefused(runCli(std::string("flow ") + hostile(file) + " -o " + scratch("flow.obj").string()),
                  {file});
}
