#include "image_based_retarget.hpp"

#include <cmath>

#include <tbb/parallel_for.h>

#include "confvis/base/stopwatch.hpp"

namespace confvis::bench {

DisplayConfig cubeFaceDisplay(int faceSize, const glm::dvec3& reference) {
  DisplayConfig cube;
  cube.name = "cube-map";
  cube.reference = reference;
  for (CubeFace face : kCubeFaces) {
    // Texel (x, y) lies along normal + c(x) right + c(y) down (cube_map.hpp): the wall's
    // lower-left corner is normal - right + down, its upper-left normal - right - down.
    const glm::dvec3 n = texelDirection(face, faceSize / 2, faceSize / 2, faceSize);
    const glm::dvec3 centre(std::round(n.x), std::round(n.y), std::round(n.z));
    const glm::dvec3 right = glm::normalize(texelDirection(face, faceSize - 1, 0, faceSize) -
                                            texelDirection(face, 0, 0, faceSize));
    const glm::dvec3 down = glm::normalize(texelDirection(face, 0, faceSize - 1, faceSize) -
                                           texelDirection(face, 0, 0, faceSize));
    Wall wall;
    wall.name = toString(face);
    wall.lowerLeft = reference + centre - right + down;
    wall.lowerRight = reference + centre + right + down;
    wall.upperLeft = reference + centre - right - down;
    wall.width = wall.height = faceSize;
    cube.walls.push_back(wall);
  }
  return cube;
}

std::vector<WallMapGrid> wallGrids(const DisplayConfig& config, const ConformalWarp& warp,
                                   double scale) {
  std::vector<WallMapGrid> grids;
  for (const Wall& wall : config.walls)
    grids.emplace_back(warp, wall,
                       WallMapGrid::spacingFor(wall, config.reference, warp.map().resolution(), scale));
  return grids;
}

std::vector<WallImage> renderImageBased(RenderBackend& backend, const DisplayConfig& config,
                                        const std::vector<WallMapGrid>& grids, int faceSize,
                                        double scale, ImageBasedTimings& timings) {
  const DisplayConfig cubeDisplay = cubeFaceDisplay(faceSize, config.reference);
  RenderSettings cubeSettings;
  cubeSettings.mode = RenderMode::Plain;
  cubeSettings.head.position = config.reference;
  cubeSettings.camera.position = config.reference;
  auto start = SteadyClock::now();
  const RenderResult faces = backend.render(cubeDisplay, nullptr, cubeSettings);
  CubeMap cube(faceSize);
  for (std::size_t f = 0; f < 6; ++f) cube.faces[f] = faces.images[f].image;
  timings.cubeSeconds = secondsSince(start);

  start = SteadyClock::now();
  std::vector<WallImage> images;
  for (std::size_t w = 0; w < config.walls.size(); ++w) {
    const Wall& wall = config.walls[w];
    const WallMapGrid& grid = grids[w];
    const int width = std::max(1, static_cast<int>(std::lround(wall.width * scale)));
    const int height = std::max(1, static_cast<int>(std::lround(wall.height * scale)));
    WallImage out{wall.name, Eye::Center, ImageRGBA(width, height, 0.0f)};
    const double sx = static_cast<double>(wall.width) / width;
    const double sy = static_cast<double>(wall.height) / height;
    tbb::parallel_for(0, height, [&](int y) {
      for (int x = 0; x < width; ++x) {
        const WallMapGrid::Sample v = grid.at(static_cast<float>((x + 0.5) * sx),
                                              static_cast<float>((y + 0.5) * sy));
        if (v.alpha < 0.5f) continue;
        const std::array<float, 4> c =
            sampleBilinear(cube, Vec3d{v.direction.x, v.direction.y, v.direction.z});
        std::copy(c.begin(), c.end(), out.image.at(x, y));
      }
    });
    images.push_back(std::move(out));
  }
  timings.resampleSeconds = secondsSince(start);
  return images;
}

}  // namespace confvis::bench
