// Source caps (display_template.hpp): the missing faces of a box display with the
// dissertation's cut tree, the generic cone cap, the half cube of a hemisphere source, and the
// star cut of a closed display.
#include "display_template_sources.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

#include "confvis/base/error.hpp"

namespace confvis::detail {
namespace {

constexpr double kAxisTolerance = 1e-9;

struct BoxFrame {
  std::array<glm::dvec3, 3> axis;
  std::array<double, 3> lo, hi;
  glm::dvec3 point(const std::array<double, 3>& x) const {
    return x[0] * axis[0] + x[1] * axis[1] + x[2] * axis[2];
  }
  double coord(const glm::dvec3& p, int k) const { return glm::dot(p, axis[k]); }
};

int axisIndex(const BoxFrame& frame, const glm::dvec3& d) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(glm::dot(d, frame.axis[k])) > 1 - kAxisTolerance) return k;
  return -1;
}

struct BoxFace {
  int axis, side;  // side 0: at lo[axis], 1: at hi[axis]
};

// The box of a display whose walls all lie on faces of their bounding box (in the frame of the
// first wall) with the reference strictly inside; nullopt otherwise.
std::optional<BoxFrame> findBox(const DisplayConfig& config) {
  const Wall& first = config.walls.front();
  BoxFrame frame{{first.right(), first.up(), first.normal()}, {}, {}};
  frame.lo.fill(1e300);
  frame.hi.fill(-1e300);
  for (const Wall& w : config.walls) {
    if (axisIndex(frame, w.right()) < 0 || axisIndex(frame, w.up()) < 0) return std::nullopt;
    for (const glm::dvec3& p : w.corners())
      for (int k = 0; k < 3; ++k) {
        frame.lo[k] = std::min(frame.lo[k], frame.coord(p, k));
        frame.hi[k] = std::max(frame.hi[k], frame.coord(p, k));
      }
  }
  for (int k = 0; k < 3; ++k) {
    const double c = frame.coord(config.reference, k);
    if (!(c > frame.lo[k] + kTemplateTolerance && c < frame.hi[k] - kTemplateTolerance))
      return std::nullopt;
  }
  for (const Wall& w : config.walls) {
    const int k = axisIndex(frame, w.normal());
    const double x = frame.coord(w.lowerLeft, k);
    if (std::abs(x - frame.lo[k]) > kTemplateTolerance &&
        std::abs(x - frame.hi[k]) > kTemplateTolerance)
      return std::nullopt;
  }
  return frame;
}

std::array<int, 2> otherAxes(int k) { return {(k + 1) % 3, (k + 2) % 3}; }

double faceCoord(const BoxFrame& frame, const BoxFace& f) {
  return f.side ? frame.hi[f.axis] : frame.lo[f.axis];
}

// 1 covered, 0 empty, -1 partly covered.
int faceCoverage(const DisplayConfig& config, const BoxFrame& frame, const BoxFace& f) {
  const auto [i, j] = otherAxes(f.axis);
  const double area = (frame.hi[i] - frame.lo[i]) * (frame.hi[j] - frame.lo[j]);
  double covered = 0;
  for (const Wall& w : config.walls)
    if (axisIndex(frame, w.normal()) == f.axis &&
        std::abs(frame.coord(w.lowerLeft, f.axis) - faceCoord(frame, f)) <= kTemplateTolerance)
      covered += w.widthMetres() * w.heightMetres();
  if (covered < kTemplateTolerance * kTemplateTolerance) return 0;
  return std::abs(covered - area) <= 1e-9 * area ? 1 : -1;
}

// Clamps x into [lo, hi] shrunk by `fraction` of its length at both ends.
double clampInside(double x, double lo, double hi, double fraction) {
  const double margin = fraction * (hi - lo);
  return std::clamp(x, lo + margin, hi - margin);
}

glm::dvec3 faceFoot(const BoxFrame& frame, const BoxFace& f, const glm::dvec3& reference) {
  std::array<double, 3> x{};
  x[f.axis] = faceCoord(frame, f);
  for (int k : otherAxes(f.axis))
    x[k] = clampInside(frame.coord(reference, k), frame.lo[k], frame.hi[k], 0.1);
  return frame.point(x);
}

}  // namespace

std::optional<SourceCap> boxCap(const DisplayConfig& config, const CoarseDisplay& display) {
  const auto found = findBox(config);
  if (!found) return std::nullopt;
  const BoxFrame& frame = *found;
  const glm::dvec3 c = config.reference;
  std::vector<BoxFace> missing;
  std::array<std::array<int, 2>, 3> covered{};
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      const int coverage = faceCoverage(config, frame, {k, side});
      if (coverage < 0) return std::nullopt;  // partly covered: the generic cap handles it
      covered[k][side] = coverage;
      if (!coverage) missing.push_back({k, side});
    }
  if (missing.empty() || display.closed()) return std::nullopt;
  SourceCap cap;
  cap.kind = SourceKind::Box;
  std::vector<glm::dvec3> feet;
  for (const BoxFace& f : missing) {
    FanCell cell;
    const auto [i, j] = otherAxes(f.axis);
    for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
      std::array<double, 3> x{};
      x[f.axis] = faceCoord(frame, f);
      x[i] = a ? frame.hi[i] : frame.lo[i];
      x[j] = b ? frame.hi[j] : frame.lo[j];
      cell.polygon.push_back(frame.point(x));
    }
    cell.centre = faceFoot(frame, f, c);
    cell.lit = false;
    cell.covered = false;
    feet.push_back(cell.centre);
    cap.centres.push_back(cell.centre);
    cap.cells.push_back(std::move(cell));
  }
  // Spanning tree of the missing faces (breadth first), joined through their shared edges.
  std::vector<char> inTree(missing.size(), 0);
  std::vector<std::size_t> order{0};
  inTree[0] = 1;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const BoxFace& f = missing[order[n]];
    for (std::size_t g = 0; g < missing.size(); ++g) {
      if (inTree[g] || missing[g].axis == f.axis) continue;
      const int along = 3 - f.axis - missing[g].axis;
      std::array<double, 3> x{};
      x[f.axis] = faceCoord(frame, f);
      x[missing[g].axis] = faceCoord(frame, missing[g]);
      x[along] = clampInside(frame.coord(c, along), frame.lo[along], frame.hi[along], 0.1);
      const glm::dvec3 joint = frame.point(x);
      cap.extraPoints.push_back(joint);
      cap.centres.push_back(joint);
      cap.cutEdges.push_back({feet[order[n]], joint});
      cap.cutEdges.push_back({feet[g], joint});
      inTree[g] = 1;
      order.push_back(g);
    }
  }
  // Leaves: missing-face corners on the display boundary where the uncovered region is convex
  // (two covered faces meet there); with fewer than three, every missing-face corner on it.
  for (int coveredFacesWanted : {2, 1}) {
    for (int corner = 0; corner < 8; ++corner) {
      std::array<double, 3> x{};
      int coveredFaces = 0, firstMissing = -1;
      for (int k = 0; k < 3; ++k) {
        const int side = (corner >> k) & 1;
        x[k] = side ? frame.hi[k] : frame.lo[k];
        coveredFaces += covered[k][side];
      }
      for (std::size_t m = 0; m < missing.size() && firstMissing < 0; ++m)
        if (((corner >> missing[m].axis) & 1) == missing[m].side)
          firstMissing = static_cast<int>(m);
      if (coveredFaces != coveredFacesWanted || firstMissing < 0) continue;
      cap.leaves.push_back(frame.point(x));
      cap.cutEdges.push_back({feet[firstMissing], frame.point(x)});
    }
    if (cap.leaves.size() >= 3) break;
  }
  return cap;
}

std::vector<int> boundaryCorners(const glm::dvec3& reference, const TemplateBuild& mesh,
                                 const std::vector<int>& loop, bool reflexOnly) {
  std::vector<int> corners;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double angle =
        sphericalBoundaryAngle(reference, mesh.points[loop[(i + n - 1) % n]], mesh.points[loop[i]],
                               mesh.points[loop[(i + 1) % n]]);
    if (reflexOnly ? angle > std::numbers::pi + 1e-6 : std::abs(angle - std::numbers::pi) > 1e-6)
      corners.push_back(loop[i]);
  }
  return corners;
}

SourceCap coneCap(const DisplayConfig& config, const CoarseDisplay& display, double maxEdge) {
  const glm::dvec3 c = config.reference;
  const TemplateBuild& mesh = display.mesh;
  const std::vector<int>& loop = display.topology.boundaryLoops.front();
  std::vector<glm::dvec3> normals;
  double radius = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec3 a = mesh.points[loop[i]], b = mesh.points[loop[(i + 1) % loop.size()]];
    normals.push_back(glm::normalize(glm::cross(a - c, b - c)));  // points away from the display
    radius += glm::length(a - c) / double(loop.size());
  }
  // Not a structured binding: lambdas below capture q, which clang 14 (the fuzz build) rejects.
  const std::pair<glm::dvec3, double> kernel = kernelCentre(normals, 4000);
  const glm::dvec3 q = kernel.first;
  const double margin = kernel.second;
  // sin(1°): below it the cap's triangles next to some boundary edge degenerate.
  if (margin < 0.0175)
    throw Error(ErrorCode::InvalidInput,
                config.name +
                    ": sphere source: no direction from the reference point sees the whole "
                    "boundary of the uncovered region (it is not star-shaped), so the "
                    "sphere cannot be cut open generally for this display; use a "
                    "hemisphere source (\"source\": {\"field\": \"hemisphere\"})");
  // The rim: the display boundary at spacing <= maxEdge, so that the cap can be built at its
  // final density; bisecting a coarse fan would leave obtuse slivers next to short boundary
  // edges.
  std::vector<glm::dvec3> rim;
  std::vector<int> rimOfLoop;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec3 a = mesh.points[loop[i]], b = mesh.points[loop[(i + 1) % loop.size()]];
    const int pieces =
        std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / maxEdge - 1e-9)));
    rimOfLoop.push_back(static_cast<int>(rim.size()));
    for (int j = 0; j < pieces; ++j) rim.push_back(glm::mix(a, b, double(j) / pieces));
  }
  // Polar grid around q: spokes from q to every rim point, rings at equal fractions of each
  // spoke's angle (slerp, radius interpolated), ring spacing <= maxEdge.
  double widest = 0;
  for (const glm::dvec3& p : rim)
    widest = std::max(widest, std::acos(std::clamp(glm::dot(q, glm::normalize(p - c)), -1.0, 1.0)));
  const int rings = std::max(1, static_cast<int>(std::ceil(widest * radius / maxEdge)));
  auto along = [&](const glm::dvec3& p, int ring) {
    if (ring == rings) return p;
    const double f = double(ring) / rings;
    const glm::dvec3 d = glm::normalize(p - c);
    const double angle = std::acos(std::clamp(glm::dot(q, d), -1.0, 1.0));
    const glm::dvec3 dir =
        angle < 1e-12 ? q
                      : (std::sin((1 - f) * angle) * q + std::sin(f * angle) * d) / std::sin(angle);
    return c + glm::mix(radius, glm::length(p - c), f) * dir;
  };
  SourceCap cap;
  cap.kind = SourceKind::Cone;
  const glm::dvec3 centre = c + radius * q;
  cap.centres.push_back(centre);
  auto addCell = [&](std::vector<glm::dvec3> polygon) {
    FanCell cell;
    cell.polygon = std::move(polygon);
    for (const glm::dvec3& p : cell.polygon) cell.centre += p / double(cell.polygon.size());
    cell.lit = false;
    cell.covered = false;
    cell.spherical = true;
    cell.fanFromFirstCorner = true;
    cap.cells.push_back(std::move(cell));
  };
  // The rim runs counter-clockwise around the display, so around the cap it runs clockwise.
  for (std::size_t i = 0; i < rim.size(); ++i) {
    const glm::dvec3& a = rim[i];
    const glm::dvec3& b = rim[(i + 1) % rim.size()];
    addCell({centre, along(b, 1), along(a, 1)});
    for (int r = 1; r < rings; ++r)
      addCell({along(a, r), along(b, r), along(b, r + 1), along(a, r + 1)});
  }
  std::vector<int> leaves = boundaryCorners(c, mesh, loop, true);
  if (leaves.size() < 3) leaves = boundaryCorners(c, mesh, loop, false);
  if (leaves.size() < 3) leaves = loop;
  for (int v : leaves) {
    const glm::dvec3 leaf = mesh.points[v];
    cap.leaves.push_back(leaf);
    cap.cutEdges.push_back({centre, along(leaf, 1)});
    for (int r = 1; r < rings; ++r) cap.cutEdges.push_back({along(leaf, r), along(leaf, r + 1)});
  }
  return cap;
}

StarCut closedDisplayStar(const DisplayConfig& config, const CoarseDisplay& display,
                          double maxEdge) {
  // The ceiling-most wall: its normal (towards the viewer) points most downwards.
  int best = 0;
  for (int w = 1; w < static_cast<int>(config.walls.size()); ++w)
    if (config.walls[w].normal().y < config.walls[best].normal().y) best = w;
  const Wall& wall = config.walls[best];
  StarCut star;
  if (!hasBezel(wall)) {
    for (const FanCell& cell : display.cells)  // the wall's single fan (see wallCells)
      if (cell.wall == best) star.centre = cell.centre;
    const std::array<glm::dvec3, 4> corners = wall.corners();
    star.leaves.assign(corners.begin(), corners.end());
    for (const glm::dvec3& leaf : star.leaves) star.edges.push_back({star.centre, leaf});
    return star;
  }
  // A cross along the lit grid from the grid vertex nearest the reference's foot.
  const LitGrid grid = litGrid(wall, maxEdge);
  const Wall lit = wall.litRectangle();
  const glm::dvec3 d = config.reference - lit.lowerLeft;
  const int i0 = std::clamp(
      static_cast<int>(std::lround(glm::dot(d, lit.right()) / lit.widthMetres() * grid.n)), 1,
      grid.n - 1);
  const int j0 =
      std::clamp(static_cast<int>(std::lround(glm::dot(d, lit.up()) / lit.heightMetres() * grid.m)),
                 1, grid.m - 1);
  star.centre = grid.point(i0, j0);
  for (const auto& [di, dj, steps] :
       {std::tuple{-1, 0, i0}, {1, 0, grid.n - i0}, {0, -1, j0}, {0, 1, grid.m - j0}}) {
    for (int k = 0; k < steps; ++k)
      star.edges.push_back(
          {grid.point(i0 + k * di, j0 + k * dj), grid.point(i0 + (k + 1) * di, j0 + (k + 1) * dj)});
    star.leaves.push_back(grid.point(i0 + steps * di, j0 + steps * dj));
  }
  return star;
}

HalfCube hemisphereHalfCube(const DisplayConfig& config, double radius,
                            const std::vector<glm::dvec3>& markerDirections) {
  const glm::dvec3 c = config.reference;
  const glm::dvec3 a = glm::normalize(config.hemisphereAxis);
  const glm::dvec3 upHint = std::abs(a.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, -1);
  const glm::dvec3 u = glm::normalize(upHint - glm::dot(upHint, a) * a);
  const glm::dvec3 r = glm::cross(u, a);
  HalfCube cube;
  const double R = radius;
  FanCell front;
  front.polygon = {c + R * (a - r - u), c + R * (a + r - u), c + R * (a + r + u),
                   c + R * (a - r + u)};
  front.centre = c + R * a;
  front.covered = false;
  cube.cells.push_back(front);
  for (const auto& [e, side] : {std::pair{r, u}, {u, -r}, {-r, -u}, {-u, r}}) {
    FanCell half;
    half.polygon = {c + R * (e - side), c + R * (e + side), c + R * (e + side + a),
                    c + R * (e - side + a)};
    half.centre = c + R * (e + 0.5 * a);
    half.covered = false;
    cube.cells.push_back(half);
  }
  for (const glm::dvec3& d : markerDirections) {
    const double x = glm::dot(d, r), y = glm::dot(d, u);
    const double scale = R / std::max(std::abs(x), std::abs(y));
    cube.rimPoints.push_back(c + scale * (x * r + y * u));
  }
  return cube;
}

}  // namespace confvis::detail
