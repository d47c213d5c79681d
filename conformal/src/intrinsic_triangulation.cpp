#include "confvis/conformal/intrinsic_triangulation.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include "confvis/base/error.hpp"

namespace confvis::conformal {

int IntrinsicTriangulation::cornerOpposite(int f, int e) const {
  for (int c = 0; c < 3; ++c)
    if (faceEdges[f][c] == e) return c;
  throw Error(ErrorCode::Internal, "edge " + std::to_string(e) + " is not in face " +
                                       std::to_string(f));
}

void IntrinsicTriangulation::flip(int e) {
  const int f0 = edgeFaces[e][0], f1 = edgeFaces[e][1];
  if (f1 < 0) throw Error(ErrorCode::Internal, "cannot flip boundary edge " + std::to_string(e));
  // f0 = (p, q, r) with e = qr opposite p; f1 = (s, r, q) with e opposite s.
  const int c0 = cornerOpposite(f0, e), c1 = cornerOpposite(f1, e);
  const int p = faceVertices[f0][c0], q = faceVertices[f0][(c0 + 1) % 3],
            r = faceVertices[f0][(c0 + 2) % 3];
  const int s = faceVertices[f1][c1];
  const int e_rp = faceEdges[f0][(c0 + 1) % 3], e_pq = faceEdges[f0][(c0 + 2) % 3];
  const int e_qs = faceEdges[f1][(c1 + 1) % 3], e_sr = faceEdges[f1][(c1 + 2) % 3];
  faceVertices[f0] = {p, q, s};
  faceEdges[f0] = {e_qs, e, e_pq};
  faceVertices[f1] = {s, r, p};
  faceEdges[f1] = {e_rp, e, e_sr};
  edgeVertices[e] = {p, s};
  auto replaceFace = [&](int edge, int from, int to) {
    for (int& f : edgeFaces[edge])
      if (f == from) f = to;
  };
  replaceFace(e_qs, f1, f0);
  replaceFace(e_rp, f0, f1);
}

std::vector<std::array<int, 3>> meshTriangles(const TriMesh& mesh) {
  std::vector<std::array<int, 3>> triangles(mesh.n_faces());
  // Plain handles, not OpenMesh's smart ranges: those validate every step out of line.
  for (int face = 0; face < static_cast<int>(mesh.n_faces()); ++face) {
    // Corner c is the target of the c-th half-edge from the face's own.
    std::array<TriMesh::HalfedgeHandle, 3> h;
    h[0] = mesh.halfedge_handle(TriMesh::FaceHandle(face));
    h[1] = mesh.next_halfedge_handle(h[0]);
    h[2] = mesh.next_halfedge_handle(h[1]);
    if (mesh.next_halfedge_handle(h[2]) != h[0])
      throw Error(ErrorCode::InvalidInput, "mesh has a non-triangular face");
    for (int c = 0; c < 3; ++c) triangles[face][c] = mesh.to_vertex_handle(h[c]).idx();
  }
  return triangles;
}

IntrinsicTriangulation buildTriangulation(const TriMesh& mesh, int skipFace) {
  return buildTriangulation(static_cast<int>(mesh.n_vertices()), meshTriangles(mesh), skipFace);
}

namespace {

void markBoundaryVertices(IntrinsicTriangulation& t) {
  t.vertexOnBoundary.assign(t.vertexCount, 0);
  for (int e = 0; e < t.edgeCount(); ++e)
    if (t.edgeOnBoundary(e)) {
      t.vertexOnBoundary[t.edgeVertices[e][0]] = 1;
      t.vertexOnBoundary[t.edgeVertices[e][1]] = 1;
    }
}

}  // namespace

IntrinsicTriangulation buildTriangulation(int vertexCount,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          int skipFace) {
  const int total = static_cast<int>(triangles.size());
  IntrinsicTriangulation t;
  t.vertexCount = vertexCount;
  const int faces = total - (skipFace >= 0 && skipFace < total);
  t.faceVertices.resize(faces);
  t.faceEdges.resize(faces);
  t.edgeVertices.reserve(3 * static_cast<std::size_t>(faces) / 2 + 2);
  t.edgeFaces.reserve(t.edgeVertices.capacity());
  auto fail = [](int face, const std::string& what) {
    throw Error(ErrorCode::InvalidInput, "triangle " + std::to_string(face) + " " + what);
  };
  // Edges listed by their smaller vertex (a linked list through `nextEdge`): a vertex has ~6.
  std::vector<int> firstEdge(vertexCount, -1), nextEdge;
  nextEdge.reserve(t.edgeVertices.capacity());
  int f = 0;
  for (int face = 0; face < total; ++face) {
    if (face == skipFace) continue;
    const std::array<int, 3>& v = triangles[face];
    for (int c = 0; c < 3; ++c)
      if (v[c] < 0 || v[c] >= vertexCount)
        fail(face, "refers to vertex " + std::to_string(v[c]) + " of " +
                       std::to_string(vertexCount));
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) fail(face, "repeats a corner");
    t.faceVertices[f] = v;
    for (int c = 0; c < 3; ++c) {
      const int a = v[(c + 1) % 3], b = v[(c + 2) % 3];
      const int low = std::min(a, b), high = std::max(a, b);
      int e = firstEdge[low];
      while (e >= 0 && t.edgeVertices[e][0] + t.edgeVertices[e][1] - low != high) e = nextEdge[e];
      if (e < 0) {
        e = t.edgeCount();
        t.edgeVertices.push_back({a, b});
        t.edgeFaces.push_back({f, -1});
        nextEdge.push_back(firstEdge[low]);
        firstEdge[low] = e;
      } else if (t.edgeFaces[e][1] >= 0) {
        fail(face, "shares edge (" + std::to_string(a) + ", " + std::to_string(b) +
                       ") with two other triangles");
      } else if (t.edgeVertices[e][0] != b) {
        fail(face, "runs edge (" + std::to_string(a) + ", " + std::to_string(b) +
                       ") the same way as its neighbour: orientations differ");
      } else {
        t.edgeFaces[e][1] = f;
      }
      t.faceEdges[f][c] = e;
    }
    ++f;
  }
  markBoundaryVertices(t);
  return t;
}

IntrinsicTriangulation withoutFace(const IntrinsicTriangulation& whole, int face) {
  if (face < 0 || face >= whole.faceCount())
    throw Error(ErrorCode::InvalidInput, "face " + std::to_string(face) + " out of range");
  IntrinsicTriangulation t;
  t.vertexCount = whole.vertexCount;
  t.faceVertices.reserve(whole.faceCount() - 1);
  t.faceEdges.resize(whole.faceCount() - 1);
  t.edgeVertices.reserve(whole.edgeCount());
  t.edgeFaces.reserve(whole.edgeCount());
  // As buildTriangulation: an edge is numbered, and runs as, in the first face that has it;
  // without `face` that is the other face for the edges `face` came to first.
  std::vector<int> renumbered(whole.edgeCount(), -1);
  int g = 0;
  for (int f = 0; f < whole.faceCount(); ++f) {
    if (f == face) continue;
    const std::array<int, 3>& v = whole.faceVertices[f];
    t.faceVertices.push_back(v);
    for (int c = 0; c < 3; ++c) {
      int& e = renumbered[whole.faceEdges[f][c]];
      if (e < 0) {
        e = t.edgeCount();
        t.edgeVertices.push_back({v[(c + 1) % 3], v[(c + 2) % 3]});
        t.edgeFaces.push_back({g, -1});
      } else {
        t.edgeFaces[e][1] = g;
      }
      t.faceEdges[g][c] = e;
    }
    ++g;
  }
  markBoundaryVertices(t);
  return t;
}

void requireDisk(const IntrinsicTriangulation& tri, const std::string& what) {
  const int n = tri.vertexCount;
  std::vector<int> parent(n), boundaryParent(n), faces(n, 0), interior(n, 0), boundary(n, 0);
  std::iota(parent.begin(), parent.end(), 0);
  std::iota(boundaryParent.begin(), boundaryParent.end(), 0);
  auto find = [](std::vector<int>& p, int x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  };
  for (const auto& fv : tri.faceVertices)
    for (int v : fv) ++faces[v];
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
    parent[find(parent, a)] = find(parent, b);
    if (tri.edgeOnBoundary(e)) {
      ++boundary[a], ++boundary[b];
      boundaryParent[find(boundaryParent, a)] = find(boundaryParent, b);
    } else {
      ++interior[a], ++interior[b];
    }
  }
  int components = 0, loops = 0;
  for (int v = 0; v < n; ++v) {
    components += find(parent, v) == v;
    loops += boundary[v] > 0 && find(boundaryParent, v) == v;
    // A single fan: closed (as many triangles as interior edges) or open between two boundary
    // edges (one triangle more).
    const bool fan = boundary[v] == 0 ? faces[v] > 0 && faces[v] == interior[v]
                                      : boundary[v] == 2 && faces[v] == interior[v] + 1;
    if (!fan)
      throw Error(ErrorCode::InvalidInput,
                  what + " is not a topological disk: vertex " + std::to_string(v) + " is in " +
                      std::to_string(faces[v]) + " triangles and " +
                      std::to_string(boundary[v]) + " boundary edges, not one fan");
  }
  if (components != 1 || loops != 1 || tri.eulerCharacteristic() != 1)
    throw Error(ErrorCode::InvalidInput,
                what + " is not a topological disk (expected 1 component, 1 boundary loop, "
                       "Euler characteristic 1; found " + std::to_string(components) +
                    " components, " + std::to_string(loops) + " boundary loops, Euler "
                    "characteristic " + std::to_string(tri.eulerCharacteristic()) + ")");
}

std::vector<double> embeddedEdgeLengths(const IntrinsicTriangulation& tri,
                                        const std::vector<Vec3d>& points) {
  std::vector<double> lengths(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e)
    lengths[e] = norm(points[tri.edgeVertices[e][0]] - points[tri.edgeVertices[e][1]]);
  return lengths;
}

std::vector<double> embeddedEdgeLengths(const IntrinsicTriangulation& tri, const TriMesh& mesh) {
  std::vector<double> lengths(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const auto& a = mesh.point(TriMesh::VertexHandle(tri.edgeVertices[e][0]));
    const auto& b = mesh.point(TriMesh::VertexHandle(tri.edgeVertices[e][1]));
    lengths[e] = (a - b).norm();
  }
  return lengths;
}

}  // namespace confvis::conformal
