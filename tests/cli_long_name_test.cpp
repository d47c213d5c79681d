// File names longer than the file system allows (a component over NAME_MAX, 255 bytes on Linux)
// on the command line: std::filesystem's throwing exists()/is_regular_file() overloads turned
// them into a filesystem_error ("unexpected error", exit 3) instead of confvis::Error naming the
// file. Each reader now asks with an error_code and refuses the name as a missing file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

// 300 characters: over NAME_MAX in one component, so stat() fails with ENAMETOOLONG.
std::string tooLong(const std::string& extension) {
  return scratch(std::string(300 - extension.size(), 'n') + extension).string();
}

std::string shipped(const std::string& name) {
  return (fs::path(CONFVIS_SOURCE_DIR) / "configs" / name).string();
}

// Exit 2 (a confvis::Error), the whole name in one error line, never "unexpected error".
void expectRefusedNaming(const CliRun& run, const std::string& name) {
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(name), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("error: "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("unexpected error"), std::string::npos) << run.output;
}

}  // namespace

TEST(CliLongName, SceneNameTooLongForTheFileSystemIsRefusedNamingIt) {
  for (const std::string extension : {"", ".obj", ".glb"}) {
    const std::string scene = tooLong(extension);
    expectRefusedNaming(runCli("render " + shipped("flat-wall.json") + " --scene " + scene +
                               " -q -o " + scratch("long-scene-out").string()),
                        scene);
  }
}

TEST(CliLongName, MeshNameTooLongForTheFileSystemIsRefusedNamingIt) {
  const std::string mesh = tooLong(".obj");
  expectRefusedNaming(runCli("flow " + mesh + " -o " + scratch("long-mesh-out.obj").string()), mesh);
}

TEST(CliLongName, MapDirectoryNameTooLongForTheFileSystemIsRefusedNamingIt) {
  const std::string map = tooLong("");
  expectRefusedNaming(runCli("render " + shipped("flat-wall.json") + " --map " + map + " -q -o " +
                             scratch("long-map-out").string()),
                      map);
}

TEST(CliLongName, ConfigNameTooLongForTheFileSystemIsRefusedNamingIt) {
  const std::string config = tooLong(".json");
  expectRefusedNaming(runCli("bake " + config + " -q -o " + scratch("long-bake-out").string()),
                      config);
}

TEST(CliLongName, ImportOutputNameTooLongForTheFileSystemIsRefusedNamingIt) {
  const std::string output = tooLong(".json");
  const std::string input =
      (fs::path(CONFVIS_SOURCE_DIR) / "configs" / "imported" / "sgct-cave4.json").string();
  expectRefusedNaming(runCli("import " + input + " -o " + output), output);
}
