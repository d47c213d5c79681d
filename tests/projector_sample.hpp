#pragma once
// configs/imported/sgct-projectors2.xml (two overlapping projectors and a preview window)
// imported for the live-view tests: windows tiled rather than fullscreen, a quick map.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "confvis/base/atomic_file.hpp"

namespace confvis::testing {

// The sample's light weight of the left projector at `column` of its `width`: it spans x in
// [-2.2, 0.2], the overlap is x in [-0.2, 0.2], where the weight falls linearly to 0.
inline double leftProjectorWeight(int column, int width) {
  const double x = -2.2 + (column + 0.5) * 2.4 / width;
  return x <= -0.2 ? 1.0 : (0.2 - x) / 0.4;
}

// `importOptions`: e.g. " --edge-blend 2.2".
inline std::filesystem::path importedProjectorConfig(const std::string& name,
                                                     const std::string& importOptions) {
  const std::filesystem::path sample =
      std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs/imported/sgct-projectors2.xml";
  const std::filesystem::path file = scratch(name + ".json");
  const CliRun imported =
      runCli("import " + sample.string() + importOptions + " -o " + file.string());
  EXPECT_EQ(imported.exitCode, 0) << imported.output;
  nlohmann::json json = nlohmann::json::parse(readTextFile(file));
  for (nlohmann::json& wall : json.at("walls")) wall.erase("window");
  json["edge_length"] = 0.3;
  std::ofstream(file) << json.dump(2);
  return file;
}

}  // namespace confvis::testing
