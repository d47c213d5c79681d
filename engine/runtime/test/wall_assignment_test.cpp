#include "confvis/runtime/wall_assignment.hpp"

#include <gtest/gtest.h>

#include "confvis/base/error.hpp"

namespace confvis {
namespace {

using Walls = std::vector<std::vector<std::string>>;

DisplayConfig fiveWalls() {
  DisplayConfig display;
  display.name = "cave5";
  for (const char* name : {"front", "left", "right", "floor", "back"}) {
    Wall wall;
    wall.name = name;
    display.walls.push_back(wall);
  }
  return display;
}

TEST(WallAssignment, WallsWithoutNodesAreDealtInConfigOrder) {
  const DisplayConfig display = fiveWalls();
  EXPECT_EQ(assignWalls(display, {{"a"}, {"a"}, {"a"}, {"a"}, {"a"}}),
            (Walls{{"front"}, {"left"}, {"right"}, {"floor"}, {"back"}}));
  EXPECT_EQ(assignWalls(display, {{"a"}, {"a"}}),
            (Walls{{"front", "right", "back"}, {"left", "floor"}}));
  // More ranks than walls: the last rank draws nothing (a head node).
  EXPECT_EQ(assignWalls(display, std::vector<std::vector<std::string>>(6, {"a"})),
            (Walls{{"front"}, {"left"}, {"right"}, {"floor"}, {"back"}, {}}));
}

TEST(WallAssignment, NodesNameRanksOrHosts) {
  DisplayConfig display = fiveWalls();
  display.walls[0].node = "2";        // front on rank 2
  display.walls[1].node = "render-b";  // left and right on render-b's ranks, in order
  display.walls[2].node = "render-b";
  display.walls[3].node = "render-b";  // a third wall on render-b goes back to its first rank
  display.walls[4].node = "10.0.0.3";  // SGCT names nodes by address
  const Walls walls = assignWalls(
      display, {{"head"}, {"render-b", "10.0.0.2"}, {"render-c", "10.0.0.3"}, {"render-b"}});
  EXPECT_EQ(walls, (Walls{{}, {"left", "floor"}, {"front", "back"}, {"right"}}));
}

TEST(WallAssignment, UnknownRankOrHostNamesTheWall) {
  DisplayConfig display = fiveWalls();
  display.walls[2].node = "7";
  try {
    assignWalls(display, {{"a"}, {"b"}});
    FAIL() << "rank 7 of 2 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wall 'right'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("2 ranks"), std::string::npos) << e.what();
  }
  display.walls[2].node = "projector-9";
  try {
    assignWalls(display, {{"b"}, {"a"}, {"b"}});
    FAIL() << "unknown host accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'projector-9'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hosts: a, b"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace confvis
