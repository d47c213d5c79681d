#pragma once
// The Riemann map of a topological disk onto the unit disk (dissertation §8.2): remove the face
// farthest from the boundary, flatten the annulus by Euclidean Ricci flow with zero target
// curvature everywhere (a flat cylinder with straight boundaries), cut it along a shortest
// edge path, lay it out, scale the period to 2πi, apply exp, normalise the outer circle to 1.
#include <array>
#include <complex>
#include <functional>
#include <vector>

#include "confvis/base/vec3.hpp"
#include "confvis/conformal/mesh.hpp"
#include "confvis/conformal/ricci_flow.hpp"

namespace confvis::conformal {

// Auto: flips from the start where the target needs them (a boundary vertex in a single
// triangle), else switched on mid-flow when steps degenerate triangles (no restart); only if
// the flow still fails, a second run with flips throughout.
enum class FlipPolicy { Off, On, Auto };

struct DiskMapOptions {
  Scheme scheme = Scheme::Yamabe;
  double tolerance = 1e-10;
  int maxIterations = 100;
  FlipPolicy flips = FlipPolicy::Auto;
  int removedFace = -1;  // face index to remove; -1 = the one farthest from the boundary
  std::function<void(int, double)> onIteration;
};

struct DiskMap {
  std::vector<std::complex<double>> uv;  // per input vertex, in the closed unit disk
  int removedFace = -1;
  bool usedFlips = false;
  RicciFlowReport flow;
};

// Throws Error(InvalidInput) for a mesh that is not a disk (naming its Euler characteristic and
// boundary loops) or too coarse to have a face off the boundary; Error(Unreachable) if the
// flow fails. The map preserves the input orientation.
DiskMap computeDiskMap(const TriMesh& mesh, const DiskMapOptions& options = {});
// The same for points and counter-clockwise triangles, without building a half-edge mesh (the
// display map's ~3k-vertex disks are mapped at every re-bake). Also throws Error(InvalidInput)
// for an edge in more than two triangles or inconsistent orientations.
DiskMap computeDiskMap(const std::vector<Vec3d>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const DiskMapOptions& options = {});

// Applies a Möbius alignment sending boundary vertices a, b, c to 1, i, -1.
void alignDiskMap(std::vector<std::complex<double>>& uv, int a, int b, int c);

}  // namespace confvis::conformal
