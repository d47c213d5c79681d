// The target template's walls and the checks of the visible region that only the template can
// make (engine/core/src/engine/display_checks.cpp already rejects degenerate, overlapping and
// back-facing walls and a reference point behind any wall).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

#include "confvis/base/error.hpp"
#include "confvis/conformal/display_template.hpp"
#include "display_template_parts.hpp"

namespace confvis::detail {
namespace {

// Angular tolerance (radians) for cones touching as seen from the reference point.
constexpr double kTouchTolerance = 1e-9;

std::string quoted(const std::string& name) { return "'" + name + "'"; }

std::string pointText(const glm::dvec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
  return buffer;
}

// Whether a plane through the reference separates the two walls' viewing cones, as the best
// smallest angular clearance (a sine) over the planes tried: positive when separated, about 0
// when they touch, negative when one hides part of the other. If any separating plane exists,
// one through two corner rays (an extreme ray of the cone of separating normals) does, so those
// decide feasibility exactly; a clearance above 0 may need a search.
struct ConeSeparation {
  std::vector<glm::dvec3> rays;  // a's rays, then b's rays negated: want n . ray >= margin
  ConeSeparation(const Wall& a, const Wall& b, const glm::dvec3& c) {
    for (const glm::dvec3& p : a.corners()) rays.push_back(glm::normalize(p - c));
    for (const glm::dvec3& p : b.corners()) rays.push_back(-glm::normalize(p - c));
  }
  double margin(const glm::dvec3& n) const {
    double m = 2;
    for (const glm::dvec3& r : rays) m = std::min(m, glm::dot(n, r));
    return m;
  }
  double throughCornerRays() const {
    double best = -2;
    for (std::size_t i = 0; i < rays.size(); ++i)
      for (std::size_t j = i + 1; j < rays.size(); ++j) {
        const glm::dvec3 n = glm::cross(rays[i], rays[j]);
        if (glm::length(n) < 1e-12) continue;
        best = std::max({best, margin(glm::normalize(n)), margin(-glm::normalize(n))});
      }
    return best;
  }
  double searched() const { return kernelCentre(rays, 500).second; }
};

double pointRectangleDistance(const glm::dvec3& p, const Wall& w) {
  const double s = std::clamp(glm::dot(p - w.lowerLeft, w.right()), 0.0, w.widthMetres());
  const double t = std::clamp(glm::dot(p - w.lowerLeft, w.up()), 0.0, w.heightMetres());
  return glm::length(p - (w.lowerLeft + s * w.right() + t * w.up()));
}

// Closest distance between segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection
// 5.1.9, with its parallel and degenerate cases).
double segmentDistance(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                       const glm::dvec3& q1) {
  const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  const double c = glm::dot(d1, r), b = glm::dot(d1, d2), denom = a * e - b * b;
  double s = denom > 1e-15 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  double best = glm::length(p0 + s * d1 - (q0 + t * d2));
  // Parallel segments: the endpoint projections cover the remaining cases.
  if (!(denom > 1e-15 * a * e))
    for (const auto& [x, y0, d] :
         {std::tuple{p0, q0, d2}, {p1, q0, d2}, {q0, p0, d1}, {q1, p0, d1}}) {
      const double u = std::clamp(glm::dot(x - y0, d) / glm::dot(d, d), 0.0, 1.0);
      best = std::min(best, glm::length(x - (y0 + u * d)));
    }
  return best;
}

double wallDistance(const Wall& a, const Wall& b) {
  double best = 1e300;
  const auto ca = a.corners(), cb = b.corners();
  for (int i = 0; i < 4; ++i) {
    best = std::min({best, pointRectangleDistance(ca[i], b), pointRectangleDistance(cb[i], a)});
    for (int j = 0; j < 4; ++j)
      best = std::min(best, segmentDistance(ca[i], ca[(i + 1) % 4], cb[j], cb[(j + 1) % 4]));
  }
  return best;
}

void checkWallPairs(const DisplayConfig& config) {
  const auto& walls = config.walls;
  for (std::size_t i = 0; i < walls.size(); ++i)
    for (std::size_t j = i + 1; j < walls.size(); ++j) {
      const ConeSeparation cones(walls[i], walls[j], config.reference);
      const double separation = cones.throughCornerRays();
      if (separation > kTouchTolerance) continue;
      const std::string pair = "walls " + quoted(walls[i].name) + " and " + quoted(walls[j].name);
      if (separation < -kTouchTolerance)
        throw Error(ErrorCode::InvalidInput,
                    config.name + ": " + pair + " overlap as seen from the reference point " +
                        pointText(config.reference) + " (one hides part of the other)");
      if (wallDistance(walls[i], walls[j]) <= kTemplateTolerance) continue;  // touch in space
      if (cones.searched() > kTouchTolerance) continue;
      throw Error(ErrorCode::InvalidInput,
                  config.name + ": " + pair + " touch as seen from the reference point " +
                      pointText(config.reference) +
                      " but not in space (one lies behind the other's edge), so the visible "
                      "region folds; move them to share the edge");
    }
}

}  // namespace

bool hasBezel(const Wall& w) {
  const Bezel& b = w.bezel;
  return std::max({b.left, b.right, b.bottom, b.top}) >= kTemplateTolerance;
}

glm::dvec3 LitGrid::point(int i, int j) const {
  const Bezel& b = wall.bezel;
  const double s = b.left + (wall.widthMetres() - b.left - b.right) * i / n;
  const double t = b.bottom + (wall.heightMetres() - b.bottom - b.top) * j / m;
  return wall.lowerLeft + s * wall.right() + t * wall.up();
}

LitGrid litGrid(const Wall& w, double maxEdge) {
  // At least 2 x 2, so that a closed display's cut star has a grid vertex inside the lit area.
  return {w, std::max(2, static_cast<int>(std::ceil(w.widthMetres() / maxEdge - 1e-9))),
          std::max(2, static_cast<int>(std::ceil(w.heightMetres() / maxEdge - 1e-9)))};
}

std::vector<FanCell> wallCells(const DisplayConfig& config, double maxEdge) {
  std::vector<FanCell> cells;
  for (int index = 0; index < static_cast<int>(config.walls.size()); ++index) {
    const Wall& w = config.walls[index];
    const double W = w.widthMetres(), H = w.heightMetres();
    const Bezel& b = w.bezel;
    auto at = [&](double s, double t) { return w.lowerLeft + s * w.right() + t * w.up(); };
    auto quad = [&](const std::array<glm::dvec3, 4>& corners, bool lit) {
      FanCell cell;
      cell.lit = lit;
      cell.wall = index;
      // The diagonal runs through the corner nearest the reference point, so a mirror through
      // the reference point maps the split to the split (a display's symmetry survives into its
      // mesh and map). Where two neighbouring corners are equally near (a quad the mirror plane
      // halves) either diagonal would break the symmetry: fan from the centre instead.
      std::array<double, 4> distance;
      for (int k = 0; k < 4; ++k) distance[k] = glm::length(corners[k] - config.reference);
      const int nearest = static_cast<int>(
          std::min_element(distance.begin(), distance.end()) - distance.begin());
      const double tie = 1e-9 * distance[nearest];
      cell.fanFromFirstCorner = distance[(nearest + 1) % 4] - distance[nearest] > tie &&
                                distance[(nearest + 3) % 4] - distance[nearest] > tie;
      for (int k = 0; k < 4; ++k) cell.polygon.push_back(corners[(nearest + k) % 4]);
      for (const glm::dvec3& p : corners) cell.centre += p / 4.0;
      cells.push_back(std::move(cell));
    };
    if (!hasBezel(w)) {
      // One fan from the foot of the reference point (the dissertation's "green sphere") where
      // that keeps the fan well shaped (a quarter of the size from each side), else the centre.
      FanCell lit;
      lit.polygon = {at(0, 0), at(W, 0), at(W, H), at(0, H)};
      lit.wall = index;
      lit.centre = at(0.5 * W, 0.5 * H);
      const glm::dvec3 foot =
          config.reference - glm::dot(config.reference - w.lowerLeft, w.normal()) * w.normal();
      const double footS = glm::dot(foot - w.lowerLeft, w.right());
      const double footT = glm::dot(foot - w.lowerLeft, w.up());
      if (footS > 0.25 * W && footS < 0.75 * W && footT > 0.25 * H && footT < 0.75 * H)
        lit.centre = foot;
      cells.push_back(lit);
      continue;
    }
    // With bezels: an n x m grid of quads split by a diagonal, the lit area inside and four
    // mitred bezel strips around it cut at the same grid lines. Thin strips then consist of
    // right triangles, never of needles from a fan centre (whose bisection leaves obtuse slivers
    // the flow cannot flatten), and the wall's outline has no vertices near its corners.
    const LitGrid grid = litGrid(w, maxEdge);
    const int n = grid.n, m = grid.m;
    auto litPoint = [&](int i, int j) { return grid.point(i, j); };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j)
        quad({litPoint(i, j), litPoint(i + 1, j), litPoint(i + 1, j + 1), litPoint(i, j + 1)},
             true);
    auto outer = [&](double fs, double ft) { return at(fs * W, ft * H); };
    // A strip piece from outer edge o0 -> o1 to the lit border i1 <- i0, cut further into quads
    // at most 4 bezel widths long: right triangles with angles above 14 degrees, which the flow
    // flattens without Delaunay flips (flips could fold the thin triangles in the result). The
    // lit grid's border quads pick up the extra points and fan from their centres.
    auto strip = [&](glm::dvec3 o0, glm::dvec3 o1, glm::dvec3 i1, glm::dvec3 i0, double width) {
      if (width < kTemplateTolerance) return;
      const double longest = std::max(glm::length(o1 - o0), glm::length(i1 - i0));
      const int pieces = std::max(1, static_cast<int>(std::ceil(longest / (4 * width) - 1e-9)));
      for (int k = 0; k < pieces; ++k) {
        const double a = double(k) / pieces, z = double(k + 1) / pieces;
        quad({glm::mix(o0, o1, a), glm::mix(o0, o1, z), glm::mix(i0, i1, z), glm::mix(i0, i1, a)},
             false);
      }
    };
    for (int i = 0; i < n; ++i) {
      const double a = double(i) / n, z = double(i + 1) / n;
      strip(outer(a, 0), outer(z, 0), litPoint(i + 1, 0), litPoint(i, 0), b.bottom);
      strip(outer(z, 1), outer(a, 1), litPoint(i, m), litPoint(i + 1, m), b.top);
    }
    for (int j = 0; j < m; ++j) {
      const double a = double(j) / m, z = double(j + 1) / m;
      strip(outer(1, a), outer(1, z), litPoint(n, j + 1), litPoint(n, j), b.right);
      strip(outer(0, z), outer(0, a), litPoint(0, j), litPoint(0, j + 1), b.left);
    }
  }
  return cells;
}

std::string wallsAround(const DisplayConfig& config, const TemplateBuild& mesh, int v) {
  std::set<int> walls;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[t][k] == v && mesh.wall[t] >= 0) walls.insert(mesh.wall[t]);
  std::string names;
  for (int w : walls) names += (names.empty() ? "" : ", ") + quoted(config.walls[w].name);
  return names;
}

CoarseDisplay assembleDisplay(const DisplayConfig& config, double maxEdge) {
  if (config.walls.empty())
    throw Error(ErrorCode::InvalidInput, config.name + ": display has no walls");
  // Loading a config checks this too, but callers may move the reference afterwards (a tracked
  // head, `--reference`).
  for (const Wall& w : config.walls)
    if (glm::dot(w.normal(), config.reference - w.lowerLeft) <= kTemplateTolerance)
      throw Error(ErrorCode::InvalidInput,
                  config.name + ": the reference point " + pointText(config.reference) +
                      " is not in front of wall " + quoted(w.name) +
                      " (it must lie inside the display, on the lit side of every wall)");
  checkWallPairs(config);
  CoarseDisplay display;
  display.cells = wallCells(config, maxEdge);
  display.mesh = assembleCells(display.cells, config.reference);
  const TemplateBuild& mesh = display.mesh;
  display.topology = analyzeTriangles(mesh);
  const TriangleTopology& topo = display.topology;
  if (!topo.nonManifoldEdges.empty()) {
    const int v = topo.nonManifoldEdges.front().first;
    throw Error(ErrorCode::InvalidInput, config.name + ": walls " + wallsAround(config, mesh, v) +
                                             " meet in one edge at " + pointText(mesh.points[v]) +
                                             ": the visible region is not a surface");
  }
  if (!topo.nonManifoldVertices.empty()) {
    const int v = topo.nonManifoldVertices.front();
    throw Error(ErrorCode::InvalidInput,
                config.name + ": walls " + wallsAround(config, mesh, v) +
                    " meet only at the point " + pointText(mesh.points[v]) +
                    ", so the visible region pinches there and is not a topological disk");
  }
  if (topo.components > 1) {
    // Name the walls of one piece against the others.
    std::vector<int> piece(config.walls.size(), 0);
    std::vector<char> reached(mesh.points.size(), 0);
    reached[mesh.triangles.front()[0]] = 1;
    for (bool grew = true; grew;) {
      grew = false;
      for (const auto& t : mesh.triangles)
        if ((reached[t[0]] || reached[t[1]] || reached[t[2]]) &&
            !(reached[t[0]] && reached[t[1]] && reached[t[2]])) {
          reached[t[0]] = reached[t[1]] = reached[t[2]] = 1;
          grew = true;
        }
    }
    std::string inside, outside;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      piece[mesh.wall[t]] = reached[mesh.triangles[t][0]] ? 1 : 2;
    for (std::size_t w = 0; w < config.walls.size(); ++w) {
      std::string& list = piece[w] == 1 ? inside : outside;
      list += (list.empty() ? "" : ", ") + quoted(config.walls[w].name);
    }
    throw Error(ErrorCode::InvalidInput,
                config.name + ": the visible region is not connected (walls " + inside +
                    " share no edge with walls " + outside + "), so it is not a topological disk");
  }
  if (topo.boundaryLoops.size() > 1)
    throw Error(ErrorCode::InvalidInput,
                config.name + ": the visible region has " +
                    std::to_string(topo.boundaryLoops.size()) +
                    " boundary loops (it surrounds a hole, like a ring of walls without floor and "
                    "ceiling), so it is not a topological disk");
  const int expected = topo.boundaryLoops.empty() ? 2 : 1;
  if (topo.eulerCharacteristic() != expected)
    throw Error(ErrorCode::InvalidInput, config.name +
                                             ": the visible region has Euler characteristic " +
                                             std::to_string(topo.eulerCharacteristic()) +
                                             ", not that of a topological disk");
  return display;
}

}  // namespace confvis::detail

namespace confvis {

void checkVisibleRegion(const DisplayConfig& config) {
  detail::assembleDisplay(config, config.edgeLength);
}

}  // namespace confvis
