// Render output: the overview's unfolding (vertical cross for CAVEs, azimuth/elevation grid for
// tiled walls) checked by continuity of the 3D positions the pixels show, and the files
// writeRenderOutput produces for each eye combination.
#include <gtest/gtest.h>

#include <unistd.h>

#include "confvis/backends/render_output.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"

namespace confvis {
namespace {

DisplayConfig shipped(const std::string& name, int pixels) {
  DisplayConfig config =
      loadDisplayConfig(std::string(CONFVIS_SOURCE_DIR) + "/configs/" + name + ".json");
  for (Wall& wall : config.walls) wall.width = wall.height = pixels;
  return config;
}

// Each wall image shows, in RGB, the physical position of its pixel centres mapped to [0, 1].
std::vector<WallImage> positionImages(const DisplayConfig& config, Eye eye) {
  std::vector<WallImage> images;
  for (const Wall& wall : config.walls) {
    WallImage image{wall.name, eye, ImageRGBA(wall.width, wall.height, 1.0f)};
    for (int y = 0; y < wall.height; ++y)
      for (int x = 0; x < wall.width; ++x) {
        const glm::dvec3 p = (wall.pixelCenter(x, y) + 2.0) / 4.0;
        float* pixel = image.image.at(x, y);
        for (int c = 0; c < 3; ++c) pixel[c] = static_cast<float>(p[c]);
      }
    images.push_back(std::move(image));
  }
  return images;
}

glm::dvec3 positionAt(const ImageRGBA& image, int x, int y) {
  const float* p = image.at(x, y);
  return 4.0 * glm::dvec3(p[0], p[1], p[2]) - 2.0;
}

// Largest 3D distance between the positions shown by neighbouring drawn pixels.
double largestNeighbourJump(const ImageRGBA& overview) {
  double worst = 0;
  for (int y = 0; y < overview.height; ++y)
    for (int x = 0; x < overview.width; ++x) {
      if (overview.at(x, y)[3] == 0.0f) continue;
      for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= overview.width || y + dy >= overview.height) continue;
        if (overview.at(x + dx, y + dy)[3] == 0.0f) continue;
        worst = std::max(worst, glm::length(positionAt(overview, x, y) -
                                            positionAt(overview, x + dx, y + dy)));
      }
    }
  return worst;
}

TEST(RenderOutput, CaveOverviewIsAContinuousVerticalCross) {
  const DisplayConfig config = shipped("cave6", 8);
  const ImageRGBA overview = overviewImage(config, positionImages(config, Eye::Center), Eye::Center);
  ASSERT_EQ(overview.width, 24);
  ASSERT_EQ(overview.height, 32);
  // Neighbouring pixels within a wall are 3/8 m apart; across a cube edge 0.27 m.
  EXPECT_LT(largestNeighbourJump(overview), 0.38);
  // Which wall sits in which cell: the centre of each cell shows that wall's side of the cube.
  auto centreOfCell = [&](int column, int row) {
    return positionAt(overview, column * 8 + 4, row * 8 + 4);
  };
  EXPECT_NEAR(centreOfCell(1, 0).y, 1.5, 1e-6);   // ceiling
  EXPECT_NEAR(centreOfCell(0, 1).x, -1.5, 1e-6);  // left
  EXPECT_NEAR(centreOfCell(1, 1).z, -1.5, 1e-6);  // front
  EXPECT_NEAR(centreOfCell(2, 1).x, 1.5, 1e-6);   // right
  EXPECT_NEAR(centreOfCell(1, 2).y, -1.5, 1e-6);  // floor
  EXPECT_NEAR(centreOfCell(1, 3).z, 1.5, 1e-6);   // back
  EXPECT_EQ(overview.at(2, 2)[3], 0.0f);          // unused corner cell
  // Front wall upright: its top row is the higher one.
  EXPECT_GT(positionAt(overview, 12, 8).y, positionAt(overview, 12, 15).y);

  // A wall that is stored sideways (corners given in another order) is turned back upright.
  DisplayConfig sideways = config;
  Wall& front = sideways.walls[0];
  const Wall original = front;
  front.lowerLeft = original.lowerRight;
  front.lowerRight = original.upperRight();
  front.upperLeft = original.lowerLeft;
  const ImageRGBA turned =
      overviewImage(sideways, positionImages(sideways, Eye::Center), Eye::Center);
  EXPECT_LT(largestNeighbourJump(turned), 0.38);
}

TEST(RenderOutput, FiveSidedCaveLeavesTheCeilingCellEmpty) {
  const DisplayConfig config = shipped("cave5", 8);
  const ImageRGBA overview = overviewImage(config, positionImages(config, Eye::Center), Eye::Center);
  ASSERT_EQ(overview.width, 24);
  EXPECT_EQ(overview.at(12, 4)[3], 0.0f);
  EXPECT_LT(largestNeighbourJump(overview), 0.38);
}

TEST(RenderOutput, TiledWallOverviewIsAGridAsSeenFromTheViewer) {
  const DisplayConfig config = shipped("md230x6", 4);
  const ImageRGBA overview = overviewImage(config, positionImages(config, Eye::Center), Eye::Center);
  ASSERT_EQ(overview.width, 12);
  ASSERT_EQ(overview.height, 8);
  // Left to right the x of the shown positions grows; top to bottom y falls.
  EXPECT_LT(positionAt(overview, 1, 1).x, positionAt(overview, 5, 1).x);
  EXPECT_LT(positionAt(overview, 5, 1).x, positionAt(overview, 9, 1).x);
  EXPECT_GT(positionAt(overview, 5, 1).y, positionAt(overview, 5, 5).y);
  EXPECT_GT(positionAt(overview, 5, 1).y, 0.0);  // the top row holds the "top-*" monitors
}

std::filesystem::path freshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("confvis_output_" + name + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(RenderOutput, FilesPerEyeCombinationAndReport) {
  const DisplayConfig config = shipped("cave6", 4);
  RenderSettings settings;
  settings.eyes = {Eye::Left, Eye::Center, Eye::Right};
  RenderResult result;
  for (Eye eye : settings.eyes)
    for (WallImage& image : positionImages(config, eye))
      if (image.wall == "front") result.images.push_back(std::move(image));
  result.images[1].image.at(0, 0)[0] = 0.25f;  // tell the centre eye from the others
  result.stats.backend = "test";
  result.stats.embree.emplace().raysPerSecond = 123.0;
  const auto dir = freshDir("eyes");
  const nlohmann::json report =
      writeRenderOutput(dir, config, settings, result, {{"scene", {{"name", "s"}}}});
  EXPECT_TRUE(std::filesystem::exists(dir / "front.exr"));  // the stereo pair
  EXPECT_TRUE(std::filesystem::exists(dir / "front.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "front-center.exr"));
  EXPECT_TRUE(std::filesystem::exists(dir / "front-center.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "overview.png"));
  EXPECT_FLOAT_EQ(readExr(dir / "front-center.exr").at(0, 0)[0], 0.25f);
  const auto [left, right] = readStereoExr(dir / "front.exr");
  EXPECT_EQ(left.pixels, result.images[0].image.pixels);
  EXPECT_EQ(right.pixels, result.images[2].image.pixels);
  const nlohmann::json written = nlohmann::json::parse(readTextFile(dir / "render.json"));
  EXPECT_EQ(written, report);
  EXPECT_EQ(written["scene"]["name"], "s");
  EXPECT_EQ(written["backend"]["rays_per_second"], 123.0);
  EXPECT_EQ(written["overview_eye"], "center");
  EXPECT_EQ(written["files"].size(), 5u);
  // No stray temporaries from the atomic writes.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 6);
  std::filesystem::remove_all(dir);
  EXPECT_THROW(writeRenderOutput(dir, config, settings, RenderResult{}), Error);
}

}  // namespace
}  // namespace confvis
