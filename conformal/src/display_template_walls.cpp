// The target template's walls and the checks of the visible region that only the template can
// make (engine/src/engine/display_checks.cpp already rejects degenerate, overlapping and
// back-facing walls and a reference point behind any wall).
#include <algorithm>
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

std::array<glm::dvec3, 4> corners(const Wall& w) {
  return {w.lowerLeft, w.lowerRight, w.upperRight(), w.upperLeft};
}

// Whether a plane through the reference separates the two walls' viewing cones, as the best
// smallest angular clearance (a sine) over the planes tried: positive when separated, about 0
// when they touch, negative when one hides part of the other. If any separating plane exists,
// one through two corner rays (an extreme ray of the cone of separating normals) does, so those
// decide feasibility exactly; a clearance above 0 may need a search.
struct ConeSeparation {
  std::vector<glm::dvec3> rays;  // a's rays, then b's rays negated: want n . ray >= margin
  ConeSeparation(const Wall& a, const Wall& b, const glm::dvec3& c) {
    for (const glm::dvec3& p : corners(a)) rays.push_back(glm::normalize(p - c));
    for (const glm::dvec3& p : corners(b)) rays.push_back(-glm::normalize(p - c));
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
    for (const auto& [x, y0, d] : {std::tuple{p0, q0, d2}, {p1, q0, d2}, {q0, p0, d1}, {q1, p0, d1}}) {
      const double u = std::clamp(glm::dot(x - y0, d) / glm::dot(d, d), 0.0, 1.0);
      best = std::min(best, glm::length(x - (y0 + u * d)));
    }
  return best;
}

double wallDistance(const Wall& a, const Wall& b) {
  double best = 1e300;
  const auto ca = corners(a), cb = corners(b);
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

std::vector<FanCell> wallCells(const DisplayConfig& config) {
  std::vector<FanCell> cells;
  for (int index = 0; index < static_cast<int>(config.walls.size()); ++index) {
    const Wall& w = config.walls[index];
    const double width = w.widthMetres(), height = w.heightMetres();
    const std::array<double, 4> s{0.0, w.bezel.left, width - w.bezel.right, width};
    const std::array<double, 4> t{0.0, w.bezel.bottom, height - w.bezel.top, height};
    auto at = [&](double si, double ti) { return w.lowerLeft + si * w.right() + ti * w.up(); };
    // The reference point's projection onto the wall, in wall coordinates.
    const glm::dvec3 foot =
        config.reference - glm::dot(config.reference - w.lowerLeft, w.normal()) * w.normal();
    const double footS = glm::dot(foot - w.lowerLeft, w.right());
    const double footT = glm::dot(foot - w.lowerLeft, w.up());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double s0 = s[i], s1 = s[i + 1], t0 = t[j], t1 = t[j + 1];
        if (s1 - s0 < kTemplateTolerance || t1 - t0 < kTemplateTolerance) continue;
        FanCell cell;
        cell.polygon = {at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1)};
        cell.lit = i == 1 && j == 1;
        cell.wall = index;
        cell.centre = at(0.5 * (s0 + s1), 0.5 * (t0 + t1));
        // The dissertation's "green sphere": fan the lit area from the foot of the reference
        // point where that keeps the fan well shaped (a quarter of the size from each side).
        const double ms = 0.25 * (s1 - s0), mt = 0.25 * (t1 - t0);
        if (cell.lit && footS > s0 + ms && footS < s1 - ms && footT > t0 + mt && footT < t1 - mt)
          cell.centre = foot;
        cells.push_back(std::move(cell));
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

CoarseDisplay assembleDisplay(const DisplayConfig& config) {
  if (config.walls.empty())
    throw Error(ErrorCode::InvalidInput, config.name + ": display has no walls");
  checkWallPairs(config);
  CoarseDisplay display;
  display.mesh = assembleCells(wallCells(config), config.reference);
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

void checkVisibleRegion(const DisplayConfig& config) { detail::assembleDisplay(config); }

}  // namespace confvis
