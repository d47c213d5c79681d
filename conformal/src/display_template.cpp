// Source and target templates of a display (display_template.hpp): which source construction
// applies, refinement, cutting and the marker correspondence.
#include "confvis/conformal/display_template.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_surfaces.hpp"
#include "display_template_parts.hpp"
#include "display_template_sources.hpp"

namespace confvis {

const char* toString(SourceKind kind) {
  switch (kind) {
    case SourceKind::Hemisphere:
      return "hemisphere";
    case SourceKind::Closed:
      return "closed";
    case SourceKind::Box:
      return "box";
    case SourceKind::Cone:
      return "cone";
  }
  return "?";
}

namespace {
using namespace detail;

double resolveEdgeLength(const DisplayConfig& config, double edgeLength) {
  const double h = edgeLength > 0 ? edgeLength : config.edgeLength;
  if (!(h > 0) || !std::isfinite(h))
    throw Error(ErrorCode::InvalidInput,
                config.name + ": edge length must be a positive number of metres (got " +
                    std::to_string(h) + ")");
  return h;
}

double wallArea(const DisplayConfig& config) {
  double area = 0;
  for (const Wall& w : config.walls) area += w.widthMetres() * w.heightMetres();
  return area;
}

// Refinement leaves triangles of at least about h²/16 (their longest edge exceeds h/2); refuse
// edge lengths that would need more than 20 million of them.
void guardSize(const DisplayConfig& config, double area, double h) {
  const double triangles = area / (h * h / 16);
  if (!(triangles <= 2e7))
    throw Error(ErrorCode::InvalidInput, config.name + ": edge length " + std::to_string(h) +
                                             " m is too small for this display (about " +
                                             (triangles < 1e15 ? std::to_string(static_cast<long long>(triangles))
                                                                 : std::to_string(triangles)) +
                                             " triangles)");
}

// Solid angle of the mesh as seen from the reference (Van Oosterom-Strackee per triangle).
double solidAngle(const TemplateBuild& mesh, const glm::dvec3& c) {
  double total = 0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.points[t[0]] - c, b = mesh.points[t[1]] - c,
                     d = mesh.points[t[2]] - c;
    const double la = glm::length(a), lb = glm::length(b), ld = glm::length(d);
    const double det = glm::dot(a, glm::cross(b, d));
    total += 2 * std::atan2(std::abs(det), la * lb * ld + glm::dot(a, b) * ld +
                                               glm::dot(a, d) * lb + glm::dot(b, d) * la);
  }
  return total;
}

TemplateMesh toTemplateMesh(const TemplateBuild& build, bool withLit, const std::string& what) {
  const TriangleTopology topo = analyzeTriangles(build);
  if (!topo.manifold() || topo.components != 1 || topo.boundaryLoops.size() != 1 ||
      topo.eulerCharacteristic() != 1)
    throw Error(ErrorCode::Internal, "display template: the " + what +
                                         " is not a topological disk (Euler characteristic " +
                                         std::to_string(topo.eulerCharacteristic()) + ", " +
                                         std::to_string(topo.boundaryLoops.size()) +
                                         " boundary loops)");
  TemplateMesh mesh;
  mesh.points = build.points;
  mesh.triangles = build.triangles;
  if (withLit) mesh.lit = build.lit;
  mesh.boundary = topo.boundaryLoops.front();
  return mesh;
}

// Position of each loop vertex along the loop, as arc length on the unit sphere.
std::vector<double> loopArcLength(const glm::dvec3& c, const std::vector<glm::dvec3>& points,
                                  const std::vector<int>& loop) {
  std::vector<double> s(loop.size() + 1, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    s[i + 1] = s[i] + directionAngle(c, points[loop[i]], points[loop[(i + 1) % loop.size()]]);
  return s;
}

// Three of the candidate boundary vertices, spread along the loop (the largest smallest gap in
// arc length), in loop order.
std::array<int, 3> spreadMarkers(const glm::dvec3& c, const TemplateMesh& mesh,
                                 const std::vector<int>& candidates) {
  const std::vector<double> s = loopArcLength(c, mesh.points, mesh.boundary);
  const double total = s.back();
  std::vector<std::pair<double, int>> on;
  for (std::size_t i = 0; i < mesh.boundary.size(); ++i)
    if (std::find(candidates.begin(), candidates.end(), mesh.boundary[i]) != candidates.end())
      on.emplace_back(s[i], mesh.boundary[i]);
  if (on.size() < 3)
    throw Error(ErrorCode::Internal, "display template: fewer than three marker candidates");
  std::array<int, 3> best{};
  double bestGap = -1;
  for (std::size_t i = 0; i < on.size(); ++i)
    for (std::size_t j = i + 1; j < on.size(); ++j)
      for (std::size_t k = j + 1; k < on.size(); ++k) {
        const double gap = std::min({on[j].first - on[i].first, on[k].first - on[j].first,
                                     total - on[k].first + on[i].first});
        if (gap > bestGap + 1e-12) bestGap = gap, best = {on[i].second, on[j].second, on[k].second};
      }
  return best;
}

// True when the markers follow the boundary loop's (counter-clockwise) cyclic order.
bool inLoopOrder(const std::vector<int>& loop, const std::array<int, 3>& markers) {
  std::array<long, 3> at{};
  for (int k = 0; k < 3; ++k) {
    const auto it = std::find(loop.begin(), loop.end(), markers[k]);
    if (it == loop.end()) return false;
    at[k] = it - loop.begin();
  }
  const int descents = (at[1] < at[0]) + (at[2] < at[1]) + (at[0] < at[2]);
  return descents == 1;
}

SizeField gradedSize(const DisplayConfig& config, double h, const TemplateGrading& grading,
                     const std::vector<glm::dvec3>& points) {
  SizeField size;
  size.maxEdge = h;
  if (grading.radiusDegrees <= 0) return size;
  size.radius = grading.radiusDegrees * std::numbers::pi / 180;
  size.exponent = grading.exponent;
  size.minScale = grading.minScale;
  for (const glm::dvec3& p : points) size.centres.push_back(glm::normalize(p - config.reference));
  return size;
}

int uniqueCopy(const std::vector<int>& origin, int coarse) {
  int found = -1;
  for (int v = 0; v < static_cast<int>(origin.size()); ++v)
    if (origin[v] == coarse) {
      if (found >= 0) throw Error(ErrorCode::Internal, "display template: a cut leaf was split");
      found = v;
    }
  if (found < 0) throw Error(ErrorCode::Internal, "display template: a cut leaf disappeared");
  return found;
}

// The refined target; a closed display is opened along the star of closedDisplayStar and
// `leaves` gets the star's leaf vertices.
TemplateMesh refinedTarget(const DisplayConfig& config, const CoarseDisplay& display, double h,
                           std::vector<int>& leaves, DisplayTemplates& out,
                           const SizeField& size = {}) {
  TemplateBuild mesh = display.mesh;
  if (!display.closed()) {
    if (size.graded()) refineTemplate(mesh, config.reference, size);
    else refineTemplate(mesh, config.reference, h);
    return toTemplateMesh(mesh, true, "target");
  }
  const StarCut star = closedDisplayStar(config, display, h);
  for (const auto& [a, b] : star.edges) addCutEdge(mesh, a, b);
  std::vector<int> coarseLeaves;
  for (const glm::dvec3& leaf : star.leaves) coarseLeaves.push_back(findVertex(mesh, leaf));
  refineTemplate(mesh, config.reference, h);
  std::vector<int> origin;
  const TemplateBuild opened = cutOpen(mesh, &origin);
  for (int v : coarseLeaves) leaves.push_back(uniqueCopy(origin, v));
  out.cutCentres = {star.centre};
  out.cutLeaves = star.leaves;
  return toTemplateMesh(opened, true, "closed display cut open");
}

DisplayTemplates hemisphereTemplates(const DisplayConfig& config, const CoarseDisplay& display,
                                     double h, const TemplateGrading& grading) {
  const glm::dvec3 c = config.reference;
  const glm::dvec3 axis = glm::normalize(config.hemisphereAxis);
  DisplayTemplates out;
  out.sourceKind = SourceKind::Hemisphere;
  std::vector<int> candidates;
  // Graded toward the display's boundary corners, on both meshes (the rim points at their
  // azimuths are the source's images of them).
  std::vector<glm::dvec3> corners;
  if (!display.closed())
    for (int v : boundaryCorners(c, display.mesh, display.topology.boundaryLoops.front(), false))
      corners.push_back(display.mesh.points[v]);
  const SizeField size = gradedSize(config, h, grading, corners);
  out.target = refinedTarget(config, display, h, candidates, out, size);
  auto hasAzimuth = [&](int v) {
    return std::abs(glm::dot(glm::normalize(out.target.points[v] - c), axis)) < 1 - 1e-6;
  };
  bool candidatesAreCorners = display.closed();  // a closed display's star leaves
  if (!display.closed()) {
    const std::vector<int>& loop = display.topology.boundaryLoops.front();
    candidates = boundaryCorners(c, display.mesh, loop, false);  // coarse ids survive refinement
    std::erase_if(candidates, [&](int v) { return !hasAzimuth(v); });
    candidatesAreCorners = candidates.size() >= 3;
    if (!candidatesAreCorners) {
      candidates = loop;
      std::erase_if(candidates, [&](int v) { return !hasAzimuth(v); });
    }
  }
  if (candidates.size() < 3)
    throw Error(ErrorCode::InvalidInput,
                config.name +
                    ": hemisphere source: the display boundary has fewer than three corners off "
                    "the hemisphere axis to anchor the map");
  out.targetMarkers = spreadMarkers(c, out.target, candidates);
  // Rim points at the azimuths of every display corner (of the markers alone where the corners
  // were too few), so that a display symmetric about the axis gets a symmetric source mesh.
  std::vector<int> rimCorners = candidatesAreCorners ? candidates : std::vector<int>{};
  for (int v : out.targetMarkers)
    if (std::find(rimCorners.begin(), rimCorners.end(), v) == rimCorners.end())
      rimCorners.push_back(v);
  std::vector<glm::dvec3> directions;
  for (int v : rimCorners) directions.push_back(glm::normalize(out.target.points[v] - c));
  // A half cube of the display's apparent size: area per steradian like the walls'.
  const double radius =
      std::sqrt(wallArea(config) * 2 * std::numbers::pi / (12 * solidAngle(display.mesh, c)));
  const HalfCube cube = hemisphereHalfCube(config, radius, directions);
  TemplateBuild source = assembleCells(cube.cells, c, cube.rimPoints);
  for (int k = 0; k < 3; ++k) {
    const auto at = std::find(rimCorners.begin(), rimCorners.end(), out.targetMarkers[k]);
    out.sourceMarkers[k] = findVertex(source, cube.rimPoints[at - rimCorners.begin()]);
  }
  SizeField sourceSize = size;
  for (const glm::dvec3& p : cube.rimPoints)
    if (sourceSize.graded()) sourceSize.centres.push_back(glm::normalize(p - c));
  if (sourceSize.graded()) refineTemplate(source, c, sourceSize);
  else refineTemplate(source, c, h);
  out.source = toTemplateMesh(source, false, "hemisphere source");
  const auto& m = out.sourceMarkers;
  if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2] || !inLoopOrder(out.source.boundary, m))
    throw Error(ErrorCode::InvalidInput,
                config.name +
                    ": hemisphere source: the display does not wind around source.axis as seen "
                    "from the reference point (its corners do not follow the hemisphere's rim in "
                    "order); point the axis into the display");
  return out;
}

DisplayTemplates closedTemplates(const DisplayConfig& config, const CoarseDisplay& display,
                                 double h) {
  DisplayTemplates out;
  out.sourceKind = SourceKind::Closed;
  std::vector<int> leaves;
  out.target = refinedTarget(config, display, h, leaves, out);
  out.targetMarkers = spreadMarkers(config.reference, out.target, leaves);
  out.source = out.target;
  out.source.lit.clear();
  out.sourceMarkers = out.targetMarkers;
  return out;
}

DisplayTemplates closureTemplates(const DisplayConfig& config, const CoarseDisplay& display,
                                  const SourceCap& cap, double h, const TemplateGrading& grading) {
  const glm::dvec3 c = config.reference;
  std::vector<FanCell> cells = display.cells;
  cells.insert(cells.end(), cap.cells.begin(), cap.cells.end());
  TemplateBuild closed = assembleCells(cells, c, cap.extraPoints);
  const TriangleTopology topo = analyzeTriangles(closed);
  if (!topo.manifold() || topo.components != 1 || !topo.boundaryLoops.empty() ||
      topo.eulerCharacteristic() != 2)
    throw Error(ErrorCode::Internal, config.name + ": the source template (display plus " +
                                         toString(cap.kind) + " cap) does not close into a sphere");
  for (const auto& [a, b] : cap.cutEdges) addCutEdge(closed, a, b);
  std::vector<int> coarseLeaves;
  for (const glm::dvec3& leaf : cap.leaves) coarseLeaves.push_back(findVertex(closed, leaf));
  // Graded toward the cut's leaves: the display corners where the map is singular.
  const SizeField size = gradedSize(config, h, grading, cap.leaves);
  if (size.graded()) refineTemplate(closed, c, size);
  else refineTemplate(closed, c, h);
  DisplayTemplates out;
  out.sourceKind = cap.kind;
  out.cutCentres = cap.centres;
  out.cutLeaves = cap.leaves;
  std::vector<int> targetIndex, origin;
  out.target =
      toTemplateMesh(extractTriangles(closed, closed.covered, &targetIndex), true, "target");
  out.source = toTemplateMesh(cutOpen(closed, &origin), false, "source cut open");
  std::vector<int> targetLeaves;
  for (int v : coarseLeaves) targetLeaves.push_back(targetIndex[v]);
  out.targetMarkers = spreadMarkers(c, out.target, targetLeaves);
  std::vector<int> targetOrigin(out.target.points.size(), -1);
  for (int v = 0; v < static_cast<int>(targetIndex.size()); ++v)
    if (targetIndex[v] >= 0) targetOrigin[targetIndex[v]] = v;
  for (int k = 0; k < 3; ++k)
    out.sourceMarkers[k] = uniqueCopy(origin, targetOrigin[out.targetMarkers[k]]);
  if (!inLoopOrder(out.source.boundary, out.sourceMarkers))
    throw Error(ErrorCode::Internal,
                config.name + ": source and target markers run in opposite directions");
  return out;
}

}  // namespace

bool displayMapIsIdentity(const DisplayConfig& displayConfig) {
  const DisplayConfig config = surfaceConfig(displayConfig);  // projector overlaps count once
  if (config.source != SourceField::FullSphere) return false;
  if (std::any_of(config.walls.begin(), config.walls.end(), hasBezel)) return false;
  // Without bezels every wall is one fan cell, whatever the edge length: the topology is cheap.
  return assembleDisplay(config, resolveEdgeLength(config, 0.0)).closed();
}

DisplayTemplates buildDisplayTemplates(const DisplayConfig& displayConfig, double edgeLength,
                                       const TemplateGrading& grading) {
  // The map sees display surfaces: projector walls overlapping on one plane are one rectangle,
  // previews none (display_surfaces.hpp).
  const DisplayConfig config = surfaceConfig(displayConfig);
  const double h = resolveEdgeLength(config, edgeLength);
  // The source of a sphere field is about as large as the display again (more for small ones).
  // Checked before anything is built: assembling a huge display at edge length h is itself slow.
  guardSize(config, wallArea(config) * (config.source == SourceField::Hemisphere ? 2 : 4), h);
  const CoarseDisplay display = assembleDisplay(config, h);
  if (config.source == SourceField::Hemisphere)
    return hemisphereTemplates(config, display, h, grading);
  if (display.closed()) return closedTemplates(config, display, h);
  if (const auto cap = boxCap(config, display))
    return closureTemplates(config, display, *cap, h, grading);
  return closureTemplates(config, display, coneCap(config, display, h), h, grading);
}

}  // namespace confvis
