// `confvis import` turns the shipped SGCT and ParaView samples into confvis configs that load to
// the same displays, and reports bad input with one clear error and a non-zero exit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_test_support.hpp"
#include "confvis/engine/display_config.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

fs::path source(const std::string& relative) { return fs::path(CONFVIS_SOURCE_DIR) / relative; }

TEST(CliImport, PvxBecomesAConfigThatLoadsAsCave3) {
  const fs::path out = scratch("cave3-from-pvx.json");
  const CliRun run = runCli("import " + source("configs/imported/paraview-cave3.pvx").string() +
                            " --name cave3 -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("ParaView .pvx display 'cave3', 3 walls"), std::string::npos) << run.output;
  EXPECT_EQ(confvis::loadDisplayConfig(out).hash,
            confvis::loadDisplayConfig(source("configs/cave3.json")).hash);
}

TEST(CliImport, SgctOptionsMoveTheReferenceAndNotesAreShown) {
  const fs::path out = scratch("sgct.json");
  const CliRun run = runCli("import " + source("configs/imported/sgct-cave4.json").string() +
                            " --reference 0,1.2,0.3 -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("note: "), std::string::npos) << run.output;  // the GUI window
  const confvis::DisplayConfig config = confvis::loadDisplayConfig(out);
  EXPECT_EQ(config.name, "sgct-cave4");
  EXPECT_EQ(config.walls.size(), 4u);
  EXPECT_DOUBLE_EQ(config.reference.y, 1.2);
  EXPECT_DOUBLE_EQ(config.reference.z, 0.3);
}

TEST(CliImport, BadInputGivesOneClearErrorAndNonZeroExit) {
  const fs::path broken = scratch("broken.pvx");
  std::ofstream(broken) << "<pvx>\n<Machine Name=\"front\" Geometry=\"1x1+0+0\"\n"
                           "  LowerLeft=\"-1 -1 -1\" UpperRight=\"1 1 -1\"/>\n</pvx>\n";
  const CliRun missingCorner = runCli("import " + broken.string());
  EXPECT_EQ(missingCorner.exitCode, 2);
  EXPECT_NE(missingCorner.output.find("broken.pvx:2: <Machine Name=\"front\">"), std::string::npos)
      << missingCorner.output;
  EXPECT_NE(missingCorner.output.find("LowerRight"), std::string::npos) << missingCorner.output;

  const CliRun badResolution = runCli("import " + broken.string() + " --resolution 12by4");
  EXPECT_EQ(badResolution.exitCode, 2);
  EXPECT_NE(badResolution.output.find("--resolution"), std::string::npos) << badResolution.output;

  EXPECT_NE(runCli("import /no/such/cave.pvx").exitCode, 0);
  const CliRun help = runCli("import --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.output.find("--reference"), std::string::npos);
}

}  // namespace
