// End-to-end tests of the confvis binary: `confvis mesh` + `confvis flow` produce a valid disk
// map and report, and bad input gives one clear error and a non-zero exit.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

TEST(CliFlow, HemisphereMapsIntoTheUnitDiskWithAReport) {
  const fs::path mesh = scratch("hemi.obj"), out = scratch("hemi-disk.obj"),
                 report = scratch("hemi.json");
  ASSERT_EQ(runCli("mesh hemisphere -n 16 -o " + mesh.string()).exitCode, 0);
  const CliRun run = runCli("flow " + mesh.string() + " -o " + out.string() + " --report " +
                         report.string() + " --markers 0,16,288");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(out);
  std::string tag;
  int vertices = 0;
  std::vector<std::complex<double>> uv;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    ls >> tag;
    if (tag == "v") ++vertices;
    if (tag == "vt") {
      double u, v;
      ls >> u >> v;
      uv.emplace_back(u, v);
    }
  }
  EXPECT_EQ(vertices, 17 * 17);
  ASSERT_EQ(uv.size(), 17u * 17u);
  for (const auto& z : uv) EXPECT_LE(std::abs(z), 1 + 1e-8);
  // --markers sends vertices 0, 16 and 288 to 1, i and -1.
  EXPECT_LT(std::abs(uv[0] - 1.0), 1e-9);
  EXPECT_LT(std::abs(uv[16] - std::complex<double>(0, 1)), 1e-9);
  EXPECT_LT(std::abs(uv[288] + 1.0), 1e-9);
  const auto json = nlohmann::json::parse(std::ifstream(report));
  for (const char* key : {"vertices", "faces", "scheme", "geometry", "iterations",
                          "max_curvature_error", "seconds", "distortion"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_LE(json["max_curvature_error"].get<double>(), 1e-10);
  EXPECT_EQ(json["distortion"]["flipped_faces"].get<int>(), 0);
  EXPECT_EQ(json["vertices"].get<int>(), 17 * 17);
}

TEST(CliFlow, BadInputGivesOneClearErrorAndNonZeroExit) {
  const CliRun missing = runCli("flow /no/such/mesh.obj");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("/no/such/mesh.obj"), std::string::npos) << missing.output;

  const fs::path sphere = scratch("sphere.off");
  ASSERT_EQ(runCli("mesh sphere -n 1 -o " + sphere.string()).exitCode, 0);
  const CliRun closed = runCli("flow " + sphere.string());
  EXPECT_EQ(closed.exitCode, 2);
  EXPECT_NE(closed.output.find("Euler characteristic 2"), std::string::npos) << closed.output;
  EXPECT_NE(closed.output.find("0 boundary loops"), std::string::npos) << closed.output;
  const fs::path pants = scratch("pants.obj");
  ASSERT_EQ(runCli("mesh pants -n 8 -o " + pants.string()).exitCode, 0);
  for (const char* route : {"euclidean", "spherical", "hyperbolic"}) {
    const CliRun holes = runCli("flow " + pants.string() + " --geometry " + route);
    EXPECT_EQ(holes.exitCode, 2) << route;
    EXPECT_NE(holes.output.find("Euler characteristic -1"), std::string::npos) << holes.output;
    EXPECT_NE(holes.output.find("3 boundary loops"), std::string::npos) << holes.output;
  }

  const fs::path garbage = scratch("garbage.obj");
  std::ofstream(garbage) << "this is not a mesh\n";
  const CliRun malformed = runCli("flow " + garbage.string());
  EXPECT_EQ(malformed.exitCode, 2);
  EXPECT_NE(malformed.output.find("garbage.obj"), std::string::npos) << malformed.output;

  const fs::path disk = scratch("disk.obj");
  ASSERT_EQ(runCli("mesh disk -n 6 -o " + disk.string()).exitCode, 0);
  const CliRun interiorMarker = runCli("flow " + disk.string() + " --markers 0,1,24");
  EXPECT_EQ(interiorMarker.exitCode, 2);
  EXPECT_NE(interiorMarker.output.find("not on the boundary"), std::string::npos);

  const CliRun badScheme = runCli("flow " + disk.string() + " --scheme circles");
  EXPECT_NE(badScheme.exitCode, 0);
}

TEST(CliFlow, SphericalAndHyperbolicRoutesEndToEnd) {
  const fs::path mesh = scratch("hemi-routes.obj");
  ASSERT_EQ(runCli("mesh hemisphere -n 12 -o " + mesh.string()).exitCode, 0);
  for (const std::string route : {"spherical", "hyperbolic"}) {
    const fs::path out = scratch(route + ".obj"), report = scratch(route + ".json");
    const CliRun run = runCli("flow " + mesh.string() + " --geometry " + route + " -o " +
                              out.string() + " --report " + report.string() +
                              " --markers 0,12,168 -q");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::vector<std::complex<double>> uv;
    std::ifstream in(out);
    for (std::string line; std::getline(in, line);) {
      std::istringstream ls(line);
      std::string tag;
      double u, v;
      if (ls >> tag && tag == "vt" && ls >> u >> v) uv.emplace_back(u, v);
    }
    ASSERT_EQ(uv.size(), 13u * 13u) << route;
    for (const auto& z : uv) EXPECT_LE(std::abs(z), 1 + 1e-8) << route;
    EXPECT_LT(std::abs(uv[12] - std::complex<double>(0, 1)), 1e-9) << route;
    const auto json = nlohmann::json::parse(std::ifstream(report));
    EXPECT_EQ(json["geometry"].get<std::string>(), route);
    EXPECT_LE(json["max_curvature_error"].get<double>(), 1e-9) << route;
    EXPECT_EQ(json["distortion"]["flipped_faces"].get<int>(), 0) << route;
  }
  const CliRun badGeometry = runCli("flow " + mesh.string() + " --geometry elliptic");
  EXPECT_EQ(badGeometry.exitCode, 2) << badGeometry.output;
  EXPECT_NE(badGeometry.output.find("unknown geometry 'elliptic'"), std::string::npos)
      << badGeometry.output;
}

TEST(CliFlow, EveryCommandHasHelp) {
  for (const char* command : {"", "flow ", "mesh "}) {
    const CliRun run = runCli(std::string(command) + "--help");
    EXPECT_EQ(run.exitCode, 0) << command;
    EXPECT_NE(run.output.find("Usage"), std::string::npos) << command;
  }
}

}  // namespace
