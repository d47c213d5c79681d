#pragma once
// Connectivity of a triangle mesh as flat index arrays, for the numerical kernels (the Newton
// loop touches every face each iteration; OpenMesh handles are too slow there). Supports edge
// flips, which keep the triangulation (power) Delaunay during the flow.
#include <array>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"

#include "confvis/conformal/mesh.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
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

// The faces of `mesh` as corner triples in half-edge order (corner c: target of the c-th
// half-edge from the face's own), the order buildTriangulation uses.
std::vector<std::array<int, 3>> meshTriangles(const TriMesh& mesh);

// buildTriangulation from an indexed triangle list (corners in the given order), without a
// half-edge mesh: edges are numbered in order of first appearance, so a list read off a TriMesh
// in its faces' half-edge order gives exactly buildTriangulation(mesh, skipFace). Throws
// Error(InvalidInput) naming the triangle for an index out of range, a repeated corner, an edge
// in more than two triangles or two triangles of opposite orientation.
IntrinsicTriangulation buildTriangulation(int vertexCount,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          int skipFace = -1);

// buildTriangulation(vertexCount, triangles, face) from `whole` = buildTriangulation(vertexCount,
// triangles) (unflipped), with the same numbering, without searching for each edge again.
IntrinsicTriangulation withoutFace(const IntrinsicTriangulation& whole, int face);

// Euclidean edge lengths of `mesh` in the triangulation's edge order.
std::vector<double> embeddedEdgeLengths(const IntrinsicTriangulation& tri, const TriMesh& mesh);
std::vector<double> embeddedEdgeLengths(const IntrinsicTriangulation& tri,
                                        const std::vector<glm::dvec3>& points);

// requireDisk for a triangulation: one component, one boundary loop, Euler characteristic 1,
// every vertex a single fan of triangles. Throws Error(InvalidInput) naming `what`.
void requireDisk(const IntrinsicTriangulation& tri, const std::string& what);

}  // namespace conformal
}  // namespace confvis
