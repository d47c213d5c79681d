#include "confvis/conformal/intrinsic_triangulation.hpp"

#include <array>

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

IntrinsicTriangulation buildTriangulation(const TriMesh& mesh, int skipFace) {
  IntrinsicTriangulation t;
  t.vertexCount = static_cast<int>(mesh.n_vertices());
  const int faces = static_cast<int>(mesh.n_faces()) - (skipFace >= 0 && skipFace < static_cast<int>(mesh.n_faces()));
  t.faceVertices.resize(faces);
  t.faceEdges.resize(faces);
  t.edgeVertices.reserve(mesh.n_edges());
  t.edgeFaces.reserve(mesh.n_edges());
  // OpenMesh's own edge indices identify the edges (no hashing); ours are numbered in order of
  // first appearance, so edges that only the skipped face had are left out.
  std::vector<int> edgeIndex(mesh.n_edges(), -1);
  int f = 0;
  // Plain handles, not OpenMesh's smart ranges: those validate every step out of line.
  for (int meshFace = 0; meshFace < static_cast<int>(mesh.n_faces()); ++meshFace) {
    if (meshFace == skipFace) continue;
    // Corner c is the target of the c-th half-edge; the edge opposite corner c is the
    // half-edge two further on.
    std::array<TriMesh::HalfedgeHandle, 3> h;
    h[0] = mesh.halfedge_handle(TriMesh::FaceHandle(meshFace));
    h[1] = mesh.next_halfedge_handle(h[0]);
    h[2] = mesh.next_halfedge_handle(h[1]);
    if (mesh.next_halfedge_handle(h[2]) != h[0])
      throw Error(ErrorCode::InvalidInput, "mesh has a non-triangular face");
    for (int c = 0; c < 3; ++c) t.faceVertices[f][c] = mesh.to_vertex_handle(h[c]).idx();
    for (int c = 0; c < 3; ++c) {
      const int meshEdge = mesh.edge_handle(h[(c + 2) % 3]).idx();
      int& e = edgeIndex[meshEdge];
      if (e < 0) {
        e = t.edgeCount();
        t.edgeVertices.push_back({t.faceVertices[f][(c + 1) % 3], t.faceVertices[f][(c + 2) % 3]});
        t.edgeFaces.push_back({f, -1});
      } else {
        t.edgeFaces[e][1] = f;
      }
      t.faceEdges[f][c] = e;
    }
    ++f;
  }
  t.vertexOnBoundary.assign(t.vertexCount, 0);
  for (int e = 0; e < t.edgeCount(); ++e)
    if (t.edgeOnBoundary(e)) {
      t.vertexOnBoundary[t.edgeVertices[e][0]] = 1;
      t.vertexOnBoundary[t.edgeVertices[e][1]] = 1;
    }
  return t;
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
