#pragma once
// Connectivity of a triangle mesh as flat index arrays, for the numerical kernels (the Newton
// loop touches every face each iteration; OpenMesh handles are too slow there). Supports edge
// flips, which keep the triangulation (power) Delaunay during the flow.
#include <array>
#include <vector>

#include "confvis/conformal/mesh.hpp"

namespace confvis::conformal {

struct IntrinsicTriangulation {
  int vertexCount = 0;
  std::vector<std::array<int, 3>> faceVertices;  // counter-clockwise
  std::vector<std::array<int, 3>> faceEdges;     // faceEdges[f][c]: edge opposite corner c
  std::vector<std::array<int, 2>> edgeVertices;
  std::vector<std::array<int, 2>> edgeFaces;     // -1 where the edge is on the boundary
  std::vector<char> vertexOnBoundary;

  int faceCount() const { return static_cast<int>(faceVertices.size()); }
  int edgeCount() const { return static_cast<int>(edgeVertices.size()); }
  bool edgeOnBoundary(int e) const { return edgeFaces[e][1] < 0; }
  int eulerCharacteristic() const { return vertexCount - edgeCount() + faceCount(); }

  // Corner of face f opposite edge e (e must be an edge of f).
  int cornerOpposite(int f, int e) const;

  // Replaces edge e (interior) by the other diagonal of its two triangles. Edge and face indices
  // stay the same; e now joins the two previously opposite vertices.
  void flip(int e);
};

// Builds the triangulation of `mesh`, optionally skipping one face (to make an annulus).
// Vertex indices are OpenMesh's; faces keep OpenMesh order (minus the skipped one).
IntrinsicTriangulation buildTriangulation(const TriMesh& mesh, int skipFace = -1);

// Euclidean edge lengths of `mesh` in the triangulation's edge order.
std::vector<double> embeddedEdgeLengths(const IntrinsicTriangulation& tri, const TriMesh& mesh);

}  // namespace confvis::conformal
