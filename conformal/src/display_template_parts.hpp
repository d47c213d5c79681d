#pragma once
// Private building blocks of the display templates (display_template.hpp): planar fan cells,
// their assembly into one stitched mesh, longest-edge refinement, cutting along a tree and
// plain triangle-list topology. Positions are physical (metres) until the final projection.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "confvis/engine/display_config.hpp"

namespace confvis::detail {

// Positions closer than this (metres) are the same template vertex; configs are written to
// millimetres, so 1 µm separates distinct points safely.
inline constexpr double kTemplateTolerance = 1e-6;

// A convex polygon (or, for the generic sphere cap, a star-shaped loop) triangulated as a fan
// from `centre`: triangles (centre, polygon[i], polygon[i+1]). Corners are counter-clockwise as
// seen from the reference point.
struct FanCell {
  std::vector<glm::dvec3> polygon;
  glm::dvec3 centre{0.0};
  bool lit = true;         // false on bezels
  bool covered = true;     // on a wall (part of the target D); false on the source's cap
  bool spherical = false;  // refined on a sphere around the reference (generic caps)
  // Triangulate from polygon[0] instead of the centre (thin convex quads: no needles), unless
  // stitching inserted points on its sides.
  bool fanFromFirstCorner = false;
  int wall = -1;  // index into config.walls, -1 for caps
};

// A triangle mesh in physical space with per-triangle flags and a set of cut edges.
struct TemplateBuild {
  std::vector<glm::dvec3> points;
  std::vector<std::array<int, 3>> triangles;          // counter-clockwise seen from the reference
  std::vector<std::uint8_t> lit, covered, spherical;  // per triangle
  std::vector<int> wall;                              // per triangle, -1 on caps
  std::set<std::pair<int, int>> cut;                  // (min, max) vertex pairs

  int addTriangle(const std::array<int, 3>& t, const FanCell& cell);
  int vertexCount() const { return static_cast<int>(points.size()); }
};

inline std::pair<int, int> edgeKey(int a, int b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

// Stitches cells into one mesh: every cell side gets, as extra polygon corners, the corners of
// all other cells lying on it (shared edges, T-junctions), then coincident points merge.
// `extraPoints` are inserted the same way (markers on a boundary). Planar cells are reoriented
// to face the reference point.
TemplateBuild assembleCells(std::vector<FanCell> cells, const glm::dvec3& reference,
                            const std::vector<glm::dvec3>& extraPoints = {});

// Index of the vertex at `p` (within kTemplateTolerance), -1 if none.
int findVertex(const TemplateBuild& mesh, const glm::dvec3& p);

// Marks the edge between the vertices at positions a and b as cut; throws Error(Internal) if
// the template has no such edge.
void addCutEdge(TemplateBuild& mesh, const glm::dvec3& a, const glm::dvec3& b);

// Each undirected edge once, with the triangle and corner (where the edge starts) on each side;
// t1 = -1 on the boundary. Linear time.
struct EdgeSides {
  int a, b, t0, k0, t1 = -1, k1 = -1;
};
std::vector<EdgeSides> edgeSides(const TemplateBuild& mesh);

// Longest-edge bisection at mid-points until no edge exceeds maxEdge (metres). Edges of
// spherical triangles split at the mid-direction around `reference` (radius averaged), all
// others at the straight mid-point, so walls stay exactly planar. Cut edges stay cut.
void refineTemplate(TemplateBuild& mesh, const glm::dvec3& reference, double maxEdge);

// The edge length allowed at a point: maxEdge, graded toward `centres` (unit directions from the
// reference) by TemplateGrading's power law.
struct SizeField {
  double maxEdge = 0;
  std::vector<glm::dvec3> centres;
  double radius = 0, exponent = 1, minScale = 1;  // radians; radius 0: uniform
  double at(const glm::dvec3& direction) const;
  bool graded() const { return radius > 0 && !centres.empty(); }
};
// The same with a graded size field; the edge split is always the longest of both its triangles
// (a shorter one waits for the longer: longest-edge propagation), so shapes stay bounded.
void refineTemplate(TemplateBuild& mesh, const glm::dvec3& reference, const SizeField& size);

// The triangles with keep[t] != 0, reindexed; vertexMap (optional) gets old -> new (-1 if gone).
TemplateBuild extractTriangles(const TemplateBuild& mesh, const std::vector<std::uint8_t>& keep,
                               std::vector<int>* vertexMap = nullptr);

// Opens the mesh along its cut edges: a vertex on the cut gets one copy per wedge between cut
// edges. origin (optional) gets, per new vertex, the vertex it was copied from.
TemplateBuild cutOpen(const TemplateBuild& mesh, std::vector<int>* origin = nullptr);

// Topology of a triangle list. Non-manifold spots are listed, not thrown, so the caller can
// name the walls meeting there.
struct TriangleTopology {
  int vertices = 0, edges = 0, faces = 0, components = 0;
  std::vector<std::vector<int>> boundaryLoops;        // counter-clockwise around the surface
  std::vector<int> nonManifoldVertices;               // two or more separate fans meet there
  std::vector<std::pair<int, int>> nonManifoldEdges;  // 3+ triangles or clashing orientation
  int eulerCharacteristic() const { return vertices - edges + faces; }
  bool manifold() const { return nonManifoldVertices.empty() && nonManifoldEdges.empty(); }
};
TriangleTopology analyzeTriangles(const TemplateBuild& mesh);

// Interior angle of the surface at boundary vertex v between its boundary neighbours prev and
// next, measured on the unit sphere around the reference point (pi on a straight boundary).
double sphericalBoundaryAngle(const glm::dvec3& reference, const glm::dvec3& prev,
                              const glm::dvec3& v, const glm::dvec3& next);

// Unit direction q maximising min_i dot(q, normals[i]) (the Chebyshev centre of the
// intersection of the hemispheres n_i . q >= 0) and that margin: `samples` directions spread
// over the sphere, then a pattern search from the best.
std::pair<glm::dvec3, double> kernelCentre(const std::vector<glm::dvec3>& normals, int samples);

// Great-circle angle between the directions of a and b from the reference point.
double directionAngle(const glm::dvec3& reference, const glm::dvec3& a, const glm::dvec3& b);

bool hasBezel(const Wall& w);

// The grid over the lit area of a wall with bezels: n x m quads, corner points (i, j).
struct LitGrid {
  Wall wall;
  int n = 2, m = 2;
  glm::dvec3 point(int i, int j) const;
};
LitGrid litGrid(const Wall& w, double maxEdge);

// The cells of every wall: without bezels one fan over the wall; with bezels a grid of quads
// (sides up to maxEdge) over the lit area and the four mitred bezel strips around it.
std::vector<FanCell> wallCells(const DisplayConfig& config, double maxEdge);

// The walls stitched into the coarse target after checking the visible region: walls hiding or
// touching each other as seen from the reference point, pinches, several pieces or holes all
// throw Error(InvalidInput) naming the walls. The topology is a disk or a closed sphere.
struct CoarseDisplay {
  std::vector<FanCell> cells;  // wallCells
  TemplateBuild mesh;
  TriangleTopology topology;
  bool closed() const { return topology.boundaryLoops.empty(); }
};
CoarseDisplay assembleDisplay(const DisplayConfig& config, double maxEdge);

// Names of the walls of the triangles around vertex v, quoted and comma-separated.
std::string wallsAround(const DisplayConfig& config, const TemplateBuild& mesh, int v);

}  // namespace confvis::detail
