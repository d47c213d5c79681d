// Never a silently broken map: judgeBake finds flipped triangles and missing coverage, and the
// default edge length follows the walls' sizes. What bakeDisplay does with a bake that fails
// (repair or refuse) is tested end to end in tests/cli_never_silent_test.cpp.
#include "confvis/conformal/bake_verdict.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/default_edge_length.hpp"
#include "display_test_configs.hpp"

using namespace confvis;
using namespace confvis::testing;

namespace {

RetargetMap bake(const DisplayMap& map, int resolution = 32) {
  return bakeRetargetMap(map, resolution);
}

DisplayMap cave5Map() {
  DisplayMapOptions options;
  options.edgeLength = 0.5;
  return computeDisplayMap(shipped("cave5"), options);
}

DisplayConfig desktopRig() {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / "imported" /
                           "sgct-desktop4.json");
}

}  // namespace

TEST(BakeVerdict, ACorrectMapPasses) {
  const DisplayMap map = cave5Map();
  const BakeVerdict verdict = judgeBake(map, bake(map));
  EXPECT_TRUE(verdict.ok()) << verdict.summary();
  EXPECT_EQ(verdict.flippedTriangles, 0u);
  EXPECT_GE(verdict.coverage, kMinCoverage);
}

TEST(BakeVerdict, FoldedDisksAndShrunkImagesAreCaught) {
  const DisplayMap good = cave5Map();
  // Fold: a vertex of the target disk moved across the opposite side of one of its triangles.
  DisplayMap folded = good;
  const auto& t = folded.target.triangles[folded.target.triangles.size() / 2];
  auto& z = folded.target.disk[t[0]];
  z = folded.target.disk[t[1]] + folded.target.disk[t[2]] - z;
  const BakeVerdict foldedVerdict = judgeBake(folded, bake(folded));
  EXPECT_GT(foldedVerdict.flippedTriangles, 0u);
  EXPECT_FALSE(foldedVerdict.ok());
  EXPECT_NE(foldedVerdict.summary().find("flipped"), std::string::npos);
  // Shrunk: the target disk scaled by 0.7, so the display shows only the middle of the source.
  DisplayMap shrunk = good;
  for (auto& w : shrunk.target.disk) w *= 0.7;
  const BakeVerdict shrunkVerdict = judgeBake(shrunk, bake(shrunk));
  EXPECT_LT(shrunkVerdict.coverage, kMinCoverage);
  EXPECT_NE(shrunkVerdict.summary().find("shows only"), std::string::npos);
}

TEST(BakeVerdict, DefaultEdgeLengthFollowsTheWalls) {
  // The imported desktop rig has no edge_length: 0.30 m tall panels, 0.65 m away.
  const DisplayConfig rig = desktopRig();
  EXPECT_NEAR(rig.edgeLength, 0.30 / 4, 1e-9);
  EXPECT_NEAR(defaultEdgeLength(rig.walls, rig.reference), rig.edgeLength, 1e-12);
  // A 3 m CAVE seen from its centre keeps the 20 cm the shipped configs give explicitly.
  const DisplayConfig cave = shipped("cave5");
  EXPECT_NEAR(defaultEdgeLength(cave.walls, cave.reference), 0.2, 1e-9);
  // A CAVE seen from 0.5 m in front of its front wall: edges scale with that distance.
  EXPECT_NEAR(defaultEdgeLength(cave.walls, {0, 0, -1.0}), 0.2 * 0.5 / 1.5, 1e-9);
}

TEST(BakeVerdict, RepairNoteReadsTheSidecar) {
  EXPECT_EQ(repairNote(nlohmann::json::object()), "");
  nlohmann::json sidecar;
  sidecar["timings"]["display_map"]["checks"] = {{"problems", nlohmann::json::array()}};
  EXPECT_EQ(repairNote(sidecar), "");
  sidecar["timings"]["display_map"]["repair"] = {
      {"applied", "edge length 0.1 m"},
      {"failed_attempts", {"edge length 0.2 m: 3 triangles flipped in the disk maps"}}};
  EXPECT_EQ(repairNote(sidecar),
            "repaired with edge length 0.1 m after edge length 0.2 m: 3 triangles flipped in the "
            "disk maps");
}
