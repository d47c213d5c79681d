// End-to-end tests of `confvis devices`: the list names lavapipe (which CI has), marks exactly
// the device `--device auto` renders on, and without any Vulkan driver gives one clear error
// and a non-zero exit.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

#include "cli_test_support.hpp"
#include "confvis/base/atomic_file.hpp"

namespace {

using confvis::testing::runCli;

TEST(CliDevices, ListsLavapipeAndMarksTheDeviceAutoRendersOn) {
  const auto text = runCli("devices");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("llvmpipe"), std::string::npos) << text.output;
  std::istringstream lines(text.output);
  int marked = 0;
  for (std::string line; std::getline(lines, line);) marked += line.rfind("* ", 0) == 0;
  EXPECT_EQ(marked, 1) << text.output;

  const auto json = runCli("devices --json");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  const nlohmann::json list = nlohmann::json::parse(json.output);
  ASSERT_TRUE(list.is_array());
  std::string automatic;
  for (const auto& device : list)
    if (device.at("automatic").get<bool>()) {
      EXPECT_TRUE(automatic.empty()) << "two devices marked";
      automatic = device.at("name").get<std::string>();
      EXPECT_TRUE(device.at("missing").empty());
    }
  ASSERT_FALSE(automatic.empty()) << json.output;
  // The marked device is the one a render with --device auto reports in its stats.
  const auto dir = confvis::testing::scratch("devices-render");
  const auto render = runCli("render --backend vulkan --device auto --mode plain --scale 0.02 "
                             "--quiet -o " + dir.string());
  ASSERT_EQ(render.exitCode, 0) << render.output;
  const nlohmann::json report =
      nlohmann::json::parse(confvis::readTextFile(dir / "render.json"));
  EXPECT_EQ(report.at("backend").at("device").get<std::string>(), automatic);
}

TEST(CliDevices, WithoutAVulkanDriverFailsWithOneClearError) {
  const auto run = runCli("devices", "VK_DRIVER_FILES=/nonexistent/icd.json "
                                     "VK_ICD_FILENAMES=/nonexistent/icd.json");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("no Vulkan driver"), std::string::npos) << run.output;
}

}  // namespace
