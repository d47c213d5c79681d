#pragma once
// Internal: development of a flat, spherical or hyperbolic metric into its model space, face by
// face in breadth-first order, shared by the disk-map routes. Each route supplies how to place
// the first face's first two corners and how to place a face's third corner from the other two
// (counter-clockwise order); the traversal never crosses boundary or cut edges.
#include <array>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"

namespace confvis::conformal::detail {

// Per face, the positions of its corners. `placeFirstEdge(corners)` sets corners 0 and 1 of
// face 0; `placeThird(f, c0, corners)` sets corners[c0] from corners (c0+1)%3 and (c0+2)%3.
template <typename Point, typename PlaceFirstEdge, typename PlaceThird>
std::vector<std::array<Point, 3>> developFaces(const IntrinsicTriangulation& tri,
                                               const std::vector<char>& edgeCut,
                                               PlaceFirstEdge placeFirstEdge,
                                               PlaceThird placeThird) {
  std::vector<std::array<Point, 3>> corner(tri.faceCount());
  std::vector<char> placed(tri.faceCount(), 0);
  std::vector<int> queue;  // breadth first: a plain array, faces are queued once
  queue.reserve(tri.faceCount());
  {
    const int f = 0;
    placeFirstEdge(corner[f]);
    placeThird(f, 2, corner[f]);
    placed[f] = 1;
    queue.push_back(f);
  }
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const int f = queue[next];
    for (int c = 0; c < 3; ++c) {
      const int e = tri.faceEdges[f][c];
      if ((!edgeCut.empty() && edgeCut[e]) || tri.edgeOnBoundary(e)) continue;
      const int g = tri.edgeFaces[e][0] == f ? tri.edgeFaces[e][1] : tri.edgeFaces[e][0];
      if (placed[g]) continue;
      const int cg = tri.cornerOpposite(g, e);
      // Shared edge: in g it runs (cg+1) → (cg+2), the reverse of f's (c+1) → (c+2).
      corner[g][(cg + 1) % 3] = corner[f][(c + 2) % 3];
      corner[g][(cg + 2) % 3] = corner[f][(c + 1) % 3];
      placeThird(g, cg, corner[g]);
      placed[g] = 1;
      queue.push_back(g);
    }
  }
  for (char p : placed)
    if (!p) throw Error(ErrorCode::Internal, "disk map layout did not reach every face");
  return corner;
}

// One position per vertex from the per-face corners of an uncut development.
template <typename Point>
std::vector<Point> vertexPositions(const IntrinsicTriangulation& tri,
                                   const std::vector<std::array<Point, 3>>& corner) {
  std::vector<Point> position(tri.vertexCount);
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int c = 0; c < 3; ++c) position[tri.faceVertices[f][c]] = corner[f][c];
  return position;
}

}  // namespace confvis::conformal::detail
