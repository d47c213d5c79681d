#include "confvis/engine/display_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "confvis/base/error.hpp"
#include "display_checks.hpp"

namespace confvis {
namespace {

using detail::kLengthTolerance;

// Corners of one wall in the plane frame of another: s along its right(), t along its up(),
// measured from its lower-left corner.
struct PlaneBox {
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
  bool contains(const PlaneBox& o) const {
    return o.s0 >= s0 - kLengthTolerance && o.s1 <= s1 + kLengthTolerance &&
           o.t0 >= t0 - kLengthTolerance && o.t1 <= t1 + kLengthTolerance;
  }
};

PlaneBox boxIn(const Wall& frame, const Wall& w) {
  const glm::dvec3 r = frame.right(), u = frame.up();
  PlaneBox box{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const glm::dvec3& p : w.corners()) {
    const double s = glm::dot(p - frame.lowerLeft, r), t = glm::dot(p - frame.lowerLeft, u);
    box.s0 = std::min(box.s0, s), box.s1 = std::max(box.s1, s);
    box.t0 = std::min(box.t0, t), box.t1 = std::max(box.t1, t);
  }
  return box;
}

bool samePlane(const Wall& a, const Wall& b) {
  return glm::dot(a.normal(), b.normal()) > 1.0 - 1e-9 &&
         std::abs(glm::dot(a.normal(), b.lowerLeft - a.lowerLeft)) <= kLengthTolerance;
}

// Same plane, facing the same way, sides parallel (right along right): the projectors of one
// screen as SGCT describes them.
bool sameFrame(const Wall& a, const Wall& b) {
  return samePlane(a, b) && glm::dot(a.right(), b.right()) > 1.0 - 1e-9;
}

bool hasBezel(const Wall& w) {
  return w.bezel.left > 0 || w.bezel.right > 0 || w.bezel.bottom > 0 || w.bezel.top > 0;
}

std::string quoted(const std::string& name) { return "'" + name + "'"; }

[[noreturn]] void fail(const std::string& sourceName, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, sourceName + ": " + what);
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Whether the boxes fill their bounding box: every cell of the grid of their edges is covered.
bool fillBoundingBox(const std::vector<PlaneBox>& boxes, const PlaneBox& bound) {
  std::vector<double> ss, ts;
  for (const PlaneBox& b : boxes) {
    ss.insert(ss.end(), {b.s0, b.s1});
    ts.insert(ts.end(), {b.t0, b.t1});
  }
  std::sort(ss.begin(), ss.end());
  std::sort(ts.begin(), ts.end());
  for (std::size_t i = 0; i + 1 < ss.size(); ++i)
    for (std::size_t j = 0; j + 1 < ts.size(); ++j) {
      if (ss[i + 1] - ss[i] <= kLengthTolerance || ts[j + 1] - ts[j] <= kLengthTolerance) continue;
      const double s = 0.5 * (ss[i] + ss[i + 1]), t = 0.5 * (ts[j] + ts[j + 1]);
      if (s < bound.s0 || s > bound.s1 || t < bound.t0 || t > bound.t1) continue;
      const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const PlaneBox& b) {
        return s > b.s0 && s < b.s1 && t > b.t0 && t < b.t1;
      });
      if (!covered) return false;
    }
  return true;
}

// The union rectangle of a group of overlapping walls (sameFrame with the first).
Wall unionRectangle(const DisplayConfig& config, const std::vector<int>& group,
                    const std::string& sourceName) {
  const Wall& first = config.walls[group.front()];
  std::vector<PlaneBox> boxes;
  PlaneBox bound = boxIn(first, first);
  std::string names;
  for (int index : group) {
    boxes.push_back(boxIn(first, config.walls[index]));
    bound.s0 = std::min(bound.s0, boxes.back().s0), bound.s1 = std::max(bound.s1, boxes.back().s1);
    bound.t0 = std::min(bound.t0, boxes.back().t0), bound.t1 = std::max(bound.t1, boxes.back().t1);
    names += (names.empty() ? "" : "+") + config.walls[index].name;
  }
  if (!fillBoundingBox(boxes, bound)) {
    std::string list;
    for (int index : group) list += (list.empty() ? "" : ", ") + quoted(config.walls[index].name);
    fail(sourceName, "walls " + list +
                         " overlap on one plane (projectors with blend zones) but together do "
                         "not fill a rectangle, so they form no display surface; fix their "
                         "corners so their union is a rectangle");
  }
  Wall surface;
  surface.name = names;
  const glm::dvec3 r = first.right(), u = first.up();
  surface.lowerLeft = first.lowerLeft + bound.s0 * r + bound.t0 * u;
  surface.lowerRight = first.lowerLeft + bound.s1 * r + bound.t0 * u;
  surface.upperLeft = first.lowerLeft + bound.s0 * r + bound.t1 * u;
  // The first wall's pixel density over the whole surface (the map ignores it; tools that show
  // a surface get a sensible size).
  const double perMetre = first.width / first.widthMetres();
  surface.width = std::clamp(static_cast<int>(std::lround(perMetre * (bound.s1 - bound.s0))), 1, 65536);
  surface.height = std::clamp(static_cast<int>(std::lround(perMetre * (bound.t1 - bound.t0))), 1, 65536);
  return surface;
}

// Overlapping pairs of non-preview walls, checked and joined into groups.
std::vector<std::vector<int>> overlapGroups(const DisplayConfig& config,
                                            const std::string& sourceName) {
  const auto& walls = config.walls;
  const int n = static_cast<int>(walls.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (walls[i].preview || walls[j].preview || !detail::wallsOverlap(walls[i], walls[j]))
        continue;
      const std::string pair = "walls " + quoted(walls[i].name) + " and " + quoted(walls[j].name);
      if (!sameFrame(walls[i], walls[j]))
        fail(sourceName, pair + " overlap (they may share only an edge; walls that overlap as "
                                "projectors do must lie in one plane with parallel sides)");
      if (hasBezel(walls[i]) || hasBezel(walls[j]))
        fail(sourceName, pair + " overlap, and overlapping projector walls have no bezels");
      const PlaneBox a = boxIn(walls[i], walls[i]), b = boxIn(walls[i], walls[j]);
      if (a.contains(b) || b.contains(a)) {
        const Wall& outer = a.contains(b) ? walls[i] : walls[j];
        const Wall& inner = a.contains(b) ? walls[j] : walls[i];
        fail(sourceName, pair + " overlap: " + quoted(outer.name) + " covers " +
                             quoted(inner.name) +
                             " on the same plane; if it is a preview window showing the walls "
                             "again, mark it \"preview\": true (import: --skip-window " +
                             outer.name + " drops it); otherwise fix the corners");
      }
      parent[findRoot(parent, j)] = findRoot(parent, i);
    }
  std::vector<std::vector<int>> groups;
  std::vector<int> groupOfRoot(n, -1);
  for (int i = 0; i < n; ++i) {
    if (walls[i].preview) continue;
    const int root = findRoot(parent, i);
    if (groupOfRoot[root] < 0) groupOfRoot[root] = static_cast<int>(groups.size()), groups.emplace_back();
    groups[groupOfRoot[root]].push_back(i);
  }
  return groups;
}

const DisplaySurface* surfaceOf(const std::vector<DisplaySurface>& surfaces, int wall) {
  for (const DisplaySurface& s : surfaces)
    if (std::find(s.walls.begin(), s.walls.end(), wall) != s.walls.end()) return &s;
  return nullptr;
}

}  // namespace

namespace detail {

bool wallCovers(const Wall& outer, const Wall& inner) {
  return samePlane(outer, inner) && boxIn(outer, outer).contains(boxIn(outer, inner));
}

std::vector<DisplaySurface> groupSurfaces(const DisplayConfig& config,
                                          const std::string& sourceName) {
  std::vector<DisplaySurface> surfaces;
  for (const std::vector<int>& group : overlapGroups(config, sourceName)) {
    DisplaySurface surface;
    surface.walls = group;
    surface.rectangle = group.size() == 1 ? config.walls[group.front()]
                                          : unionRectangle(config, group, sourceName);
    surfaces.push_back(std::move(surface));
  }
  if (surfaces.empty())
    fail(sourceName, "every wall is a preview, so the display has no surface; a preview window "
                     "repeats walls that must be in the config too");
  for (const Wall& preview : config.walls) {
    if (!preview.preview) continue;
    const bool inside = std::any_of(surfaces.begin(), surfaces.end(), [&](const DisplaySurface& s) {
      return samePlane(s.rectangle, preview) &&
             boxIn(s.rectangle, s.rectangle).contains(boxIn(s.rectangle, preview));
    });
    if (!inside)
      fail(sourceName, "preview wall " + quoted(preview.name) +
                           " lies inside no display surface: a preview shows part of the walls "
                           "again, so it must lie on their plane, within their outline");
  }
  return surfaces;
}

}  // namespace detail

std::vector<DisplaySurface> displaySurfaces(const DisplayConfig& config) {
  return detail::groupSurfaces(config, config.name);
}

DisplayConfig surfaceConfig(const DisplayConfig& config) {
  const bool plain = std::none_of(config.walls.begin(), config.walls.end(),
                                  [](const Wall& w) { return w.preview; });
  std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  if (plain && surfaces.size() == config.walls.size()) return config;
  DisplayConfig result = config;
  result.walls.clear();
  for (DisplaySurface& s : surfaces) result.walls.push_back(std::move(s.rectangle));
  return result;
}

double edgeBlendWeight(const DisplayConfig& config, const std::vector<DisplaySurface>& surfaces,
                       int wall, const glm::dvec3& point) {
  const Wall& self = config.walls.at(wall);
  const DisplaySurface* surface = surfaceOf(surfaces, wall);
  if (!surface || surface->walls.size() < 2) return 1.0;  // a preview, or a lone wall
  const Wall& frame = surface->rectangle;
  const PlaneBox outline = boxIn(frame, frame);
  const double s = glm::dot(point - frame.lowerLeft, frame.right());
  const double t = glm::dot(point - frame.lowerLeft, frame.up());
  // Distance from (s, t) to the nearest edge of `box` that lies inside the outline; negative
  // outside the box, +infinity for a box whose every edge is on the outline.
  auto innerDistance = [&](const PlaneBox& box) {
    if (s < box.s0 || s > box.s1 || t < box.t0 || t > box.t1) return -1.0;
    double d = std::numeric_limits<double>::infinity();
    if (box.s0 > outline.s0 + kLengthTolerance) d = std::min(d, s - box.s0);
    if (box.s1 < outline.s1 - kLengthTolerance) d = std::min(d, box.s1 - s);
    if (box.t0 > outline.t0 + kLengthTolerance) d = std::min(d, t - box.t0);
    if (box.t1 < outline.t1 - kLengthTolerance) d = std::min(d, box.t1 - t);
    return d;
  };
  const double own = innerDistance(boxIn(frame, self));
  if (own < 0.0) return 0.0;
  double total = 0.0;
  int covering = 0;
  for (int other : surface->walls) {
    const double d = innerDistance(boxIn(frame, config.walls[other]));
    if (d < 0.0) continue;
    total += d;
    ++covering;
  }
  if (covering <= 1) return 1.0;
  if (!(total > 0.0)) return 1.0 / covering;  // on the inner edges of all of them at once
  return own / total;
}

std::vector<float> edgeBlendSignal(const DisplayConfig& config, int wall, int width, int height) {
  if (!config.edgeBlend.enabled || width <= 0 || height <= 0) return {};
  const std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  const DisplaySurface* surface = surfaceOf(surfaces, wall);
  if (!surface || surface->walls.size() < 2) return {};
  Wall w = config.walls.at(wall);
  w.width = width, w.height = height;  // pixel centres of the image's own size
  std::vector<float> mask(static_cast<std::size_t>(width) * height);
  const double exponent = 1.0 / config.edgeBlend.gamma;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      mask[static_cast<std::size_t>(y) * width + x] = static_cast<float>(
          std::pow(edgeBlendWeight(config, surfaces, wall, w.pixelCenter(x, y)), exponent));
  return mask;
}

}  // namespace confvis
