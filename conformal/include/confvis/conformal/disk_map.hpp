#pragma once
// The Riemann map of a topological disk onto the unit disk, by one of three routes (the map is
// unique up to a Möbius map of the disk, so the routes can be compared after alignment):
// - Euclidean (dissertation §8.2, the default): remove a face (nearly) farthest from the boundary
//   (or a given vertex's star), flatten the annulus by Euclidean Ricci flow with zero target
//   curvature everywhere (a flat cylinder with straight boundaries), cut it along a shortest edge
//   path, lay it out, scale the period to 2πi, apply exp, normalise the outer circle to 1.
// - Spherical: spherical flow with zero target curvature everywhere, boundary included; by
//   Gauss-Bonnet the area is 2π and the boundary a geodesic: a hemisphere. Laid out on the unit
//   sphere, the boundary's pole turned to +z, stereographic projection onto the unit disk.
// - Hyperbolic (§6.2 iterated boundary curvature): hyperbolic flow with zero interior target
//   curvature; the boundary targets are those of a polygon inscribed in a hyperbolic circle
//   with the current boundary edge lengths, updated until they no longer change. Laid out in
//   the Poincaré disk, where the boundary circle is a Euclidean one, scaled onto the unit circle.
#include <array>
#include <complex>
#include <functional>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"
#include "confvis/conformal/mesh.hpp"
#include "confvis/conformal/ricci_flow.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

// Auto: flips from the start where the target needs them (a boundary vertex in a single
// triangle), else switched on mid-flow when steps degenerate triangles (no restart); only if
// the flow still fails, a second run with flips throughout.
enum class FlipPolicy { Off, On, Auto };

// Thread-safety: a value (options); onIteration is called on the thread that computes the map.
struct DiskMapOptions {
  Geometry geometry = Geometry::Euclidean;  // the route: background geometry of the flow
  Scheme scheme = Scheme::Yamabe;
  double tolerance = 1e-10;
  int maxIterations = 100;
  FlipPolicy flips = FlipPolicy::Auto;
  // Euclidean route: face to remove; -1 = the roundest of those (nearly) farthest from the
  // boundary.
  int removedFace = -1;
  // Euclidean route: an interior vertex whose star (the fan of its triangles) to remove instead
  // of one face; -1 = none (removedFace decides). The hole then has the star's symmetry: a
  // vertex on a mirror plane whose star is mirror-symmetric keeps the map mirror-symmetric,
  // where one triangle cannot. None of its neighbours may be on the boundary. The vertex maps
  // to the hole's centre, 0 (the star's triangles are then the hole's fill).
  int removedVertex = -1;
  // Euclidean route: start the flow from an estimate of the flattening factor (log map around
  // the removed face, corners opened to π) instead of the embedded metric. Fewer Newton steps on
  // refined display templates (cave5 20 cm: 6 + 5 -> 4 + 5) and on the lopsided benchmark disks
  // (see conformal/README.md), the same map to 1e-8 where no flips come on (with flips the
  // Delaunay triangulation reached depends on the start). A coarse irregular disk can stall from
  // it: the map is then computed again from the embedded metric. Ignored by the tangential and
  // Thurston schemes, whose starting metric is not the embedded one.
  bool flatteningGuess = true;
  // Spherical route: when a flow stalls, the hemisphere is approached by continuation with a
  // smaller step; after this many stalled stages the route fails with Error(Unreachable) (each
  // costs up to 20 Newton steps), for callers with a cheaper fallback (the display map's
  // Euclidean route). The default never gives up before the step falls below 1/1024.
  int maxStalledStages = 1000;
  // Spherical route: start from the factor of z^(π/α) around each boundary corner of angle α
  // (the flattening guess's corner cones, no log term). For meshes graded toward their corners,
  // where many rings of tiny triangles must open: cave3's graded source then converges directly
  // (8 Newton steps) instead of stalling into continuation; cave5 graded 5 + 4 -> 4 + 4 steps.
  bool cornerGuess = false;
  // Spherical route: a disk map of the same mesh (per vertex, in the unit disk; e.g. the
  // Euclidean route's), to start from the factor that takes the embedded edge lengths to those
  // of its hemisphere (inverse stereographic projection). Empty: no such start.
  std::vector<std::complex<double>> hemisphereGuess;
  std::function<void(int, double)> onIteration;
};

struct DiskMap {
  std::vector<std::complex<double>> uv;  // per input vertex, in the closed unit disk
  Geometry geometry = Geometry::Euclidean;  // the route taken
  int removedFace = -1;                     // Euclidean route only (-1 with a removed vertex)
  int removedVertex = -1;                   // Euclidean route with options.removedVertex
  int boundaryUpdates = 0;  // hyperbolic route: flows run, one per boundary target update
  bool usedFlips = false;
  RicciFlowReport flow;     // the hyperbolic route's counts and times summed over its flows
};

// Throws Error(InvalidInput) for a mesh that is not a disk (naming its Euler characteristic and
// boundary loops) or, for the Euclidean route, too coarse to have a face off the boundary;
// Error(Unreachable) if the flow fails. The map preserves the input orientation.
DiskMap computeDiskMap(const TriMesh& mesh, const DiskMapOptions& options = {});
// The same for points and counter-clockwise triangles, without building a half-edge mesh (the
// display map's ~3k-vertex disks are mapped at every re-bake). Also throws Error(InvalidInput)
// for an edge in more than two triangles or inconsistent orientations.
DiskMap computeDiskMap(const std::vector<glm::dvec3>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const DiskMapOptions& options = {});

// The same on `whole` = buildTriangulation(points.size(), triangles), for a caller that needs
// the triangulation before the map (to choose the removed face on it).
DiskMap computeDiskMap(const std::vector<glm::dvec3>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const IntrinsicTriangulation& whole, const DiskMapOptions& options = {});

// Per vertex, the shortest distance along edges (edgeLengths in tri's edge order) to the
// boundary: the Euclidean route removes a face (nearly) farthest from the boundary by it.
std::vector<double> distanceToBoundary(const IntrinsicTriangulation& tri,
                                       const std::vector<double>& edgeLengths);

// Applies a Möbius alignment sending boundary vertices a, b, c to 1, i, -1.
void alignDiskMap(std::vector<std::complex<double>>& uv, int a, int b, int c);

}  // namespace conformal
}  // namespace confvis
