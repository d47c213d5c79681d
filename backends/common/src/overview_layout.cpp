// overviewImage: the vertical-cross unfolding of CAVE walls, or a grid for tiled walls.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "confvis/backends/render_output.hpp"

namespace confvis {

namespace {

struct Placement {
  const ImageRGBA* image = nullptr;
  int quarterTurns = 0;       // counter-clockwise turns applied before pasting
  int cellX = 0, cellY = 0;   // top-left corner of the cell, pixels
  int cellW = 0, cellH = 0;
};

int turnedWidth(const ImageRGBA& image, int turns) { return turns % 2 ? image.height : image.width; }
int turnedHeight(const ImageRGBA& image, int turns) { return turns % 2 ? image.width : image.height; }

// Pastes `image`, turned counter-clockwise by quarterTurns, centred in its cell.
void paste(ImageRGBA& canvas, const Placement& p) {
  const ImageRGBA& src = *p.image;
  const int w = turnedWidth(src, p.quarterTurns), h = turnedHeight(src, p.quarterTurns);
  const int x0 = p.cellX + (p.cellW - w) / 2, y0 = p.cellY + (p.cellH - h) / 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int sx = x, sy = y;  // source pixel shown at (x, y) of the turned image
      switch (p.quarterTurns % 4) {
        case 1: sx = src.width - 1 - y; sy = x; break;
        case 2: sx = src.width - 1 - x; sy = src.height - 1 - y; break;
        case 3: sx = y; sy = src.height - 1 - x; break;
        default: break;
      }
      std::copy_n(src.at(sx, sy), 4, canvas.at(x0 + x, y0 + y));
    }
}

// Counter-clockwise quarter turns that bring the wall's up axis closest to `cellUp`: after k
// turns the image's up points along up, right, -up, -right for k = 0..3.
int turnsFor(const Wall& wall, const glm::dvec3& cellUp) {
  const std::array<glm::dvec3, 4> ups = {wall.up(), wall.right(), -wall.up(), -wall.right()};
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (glm::dot(ups[k], cellUp) > glm::dot(ups[best], cellUp)) best = k;
  return best;
}

glm::dvec3 wallCentre(const Wall& wall) { return wall.pointAt(0.5, 0.5); }

// The vertical cross, or nullopt when the walls are not one per cube face around c.
std::optional<std::vector<Placement>> crossLayout(const DisplayConfig& config,
                                                  const std::vector<const ImageRGBA*>& images,
                                                  int& canvasW, int& canvasH) {
  struct Cell {
    glm::dvec3 axis;  // direction from c to the wall
    int column, row;
    glm::dvec3 up;    // 3D direction that points up in the cross
  };
  static const std::array<Cell, 6> cells = {{
      {{0, 0, -1}, 1, 1, {0, 1, 0}},   // front
      {{-1, 0, 0}, 0, 1, {0, 1, 0}},   // left
      {{1, 0, 0}, 2, 1, {0, 1, 0}},    // right
      {{0, 1, 0}, 1, 0, {0, 0, 1}},    // ceiling
      {{0, -1, 0}, 1, 2, {0, 0, -1}},  // floor
      {{0, 0, 1}, 1, 3, {0, -1, 0}},   // back, continuing below the floor
  }};
  std::array<int, 6> owner;
  owner.fill(-1);
  int side = 1;
  std::vector<int> cellOf(config.walls.size(), -1);
  for (std::size_t i = 0; i < config.walls.size(); ++i) {
    const Wall& wall = config.walls[i];
    const glm::dvec3 towards = glm::normalize(wallCentre(wall) - config.reference);
    int best = 0;
    for (int c = 1; c < 6; ++c)
      if (glm::dot(towards, cells[c].axis) > glm::dot(towards, cells[best].axis)) best = c;
    // The wall must face c along that axis (normal pointing back at the viewer).
    if (glm::dot(wall.normal(), -cells[best].axis) < 0.95 || owner[best] >= 0) return std::nullopt;
    owner[best] = static_cast<int>(i);
    cellOf[i] = best;
    if (images[i]) side = std::max({side, images[i]->width, images[i]->height});
  }
  canvasW = 3 * side;
  canvasH = 4 * side;
  std::vector<Placement> placements;
  for (std::size_t i = 0; i < config.walls.size(); ++i) {
    if (!images[i]) continue;
    const Cell& cell = cells[cellOf[i]];
    placements.push_back({images[i], turnsFor(config.walls[i], cell.up), cell.column * side,
                          cell.row * side, side, side});
  }
  return placements;
}

// Indices of `values` grouped into clusters no wider than `tolerance`, sorted ascending.
std::vector<int> clusterIndex(const std::vector<double>& values, double tolerance) {
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> starts;
  for (double v : sorted)
    if (starts.empty() || v - starts.back() > tolerance) starts.push_back(v);
  std::vector<int> index;
  for (double v : values) {
    const auto it = std::upper_bound(starts.begin(), starts.end(), v);
    index.push_back(static_cast<int>(it - starts.begin()) - 1);
  }
  return index;
}

// Columns by azimuth (left to right), rows by elevation (top to bottom); one row in config
// order if two walls fall into one cell.
std::vector<Placement> gridLayout(const DisplayConfig& config,
                                  const std::vector<const ImageRGBA*>& images, int& canvasW,
                                  int& canvasH) {
  const std::size_t n = config.walls.size();
  std::vector<double> azimuth, elevation;
  for (const Wall& wall : config.walls) {
    const glm::dvec3 d = wallCentre(wall) - config.reference;
    azimuth.push_back(std::atan2(d.x, -d.z));
    elevation.push_back(-std::atan2(d.y, std::hypot(d.x, d.z)));  // top row first
  }
  std::vector<int> column = clusterIndex(azimuth, 0.1), row = clusterIndex(elevation, 0.1);
  std::map<std::pair<int, int>, int> occupied;
  for (std::size_t i = 0; i < n; ++i)
    if (!occupied.emplace(std::pair{column[i], row[i]}, static_cast<int>(i)).second) {
      for (std::size_t j = 0; j < n; ++j) {
        column[j] = static_cast<int>(j);
        row[j] = 0;
      }
      break;
    }
  const int columns = *std::max_element(column.begin(), column.end()) + 1;
  const int rows = *std::max_element(row.begin(), row.end()) + 1;
  std::vector<int> widths(columns, 1), heights(rows, 1);
  for (std::size_t i = 0; i < n; ++i)
    if (images[i]) {
      widths[column[i]] = std::max(widths[column[i]], images[i]->width);
      heights[row[i]] = std::max(heights[row[i]], images[i]->height);
    }
  std::vector<int> xs(columns + 1, 0), ys(rows + 1, 0);
  for (int c = 0; c < columns; ++c) xs[c + 1] = xs[c] + widths[c];
  for (int r = 0; r < rows; ++r) ys[r + 1] = ys[r] + heights[r];
  canvasW = xs[columns];
  canvasH = ys[rows];
  std::vector<Placement> placements;
  for (std::size_t i = 0; i < n; ++i)
    if (images[i])
      placements.push_back({images[i], 0, xs[column[i]], ys[row[i]], widths[column[i]],
                            heights[row[i]]});
  return placements;
}

}  // namespace

ImageRGBA overviewImage(const DisplayConfig& config, const std::vector<WallImage>& images,
                        Eye eye) {
  std::vector<const ImageRGBA*> byWall(config.walls.size(), nullptr);
  for (const WallImage& image : images)
    if (image.eye == eye && !image.image.empty())
      for (std::size_t i = 0; i < config.walls.size(); ++i)
        if (config.walls[i].name == image.wall) byWall[i] = &image.image;
  int width = 0, height = 0;
  std::optional<std::vector<Placement>> placements =
      crossLayout(config, byWall, width, height);
  if (!placements) placements = gridLayout(config, byWall, width, height);
  ImageRGBA canvas(width, height, 0.0f);
  for (const Placement& p : *placements) paste(canvas, p);
  return canvas;
}

}  // namespace confvis
