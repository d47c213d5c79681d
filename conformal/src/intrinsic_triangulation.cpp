#include "confvis/conformal/intrinsic_triangulation.hpp"

#include <unordered_map>

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
  t.faceVertices.reserve(mesh.n_faces());
  for (auto f : mesh.faces()) {
    if (f.idx() == skipFace) continue;
    std::array<int, 3> fv{};
    int c = 0;
    for (auto v : f.vertices()) {
      if (c == 3) throw Error(ErrorCode::InvalidInput, "mesh has a non-triangular face");
      fv[c++] = v.idx();
    }
    t.faceVertices.push_back(fv);
  }
  std::unordered_map<long long, int> edgeIndex;
  edgeIndex.reserve(t.faceVertices.size() * 2);
  t.faceEdges.resize(t.faceVertices.size());
  for (int f = 0; f < t.faceCount(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int a = t.faceVertices[f][(c + 1) % 3], b = t.faceVertices[f][(c + 2) % 3];
      const long long key = static_cast<long long>(std::min(a, b)) * t.vertexCount + std::max(a, b);
      auto [it, inserted] = edgeIndex.try_emplace(key, t.edgeCount());
      if (inserted) {
        t.edgeVertices.push_back({a, b});
        t.edgeFaces.push_back({f, -1});
      } else {
        auto& ef = t.edgeFaces[it->second];
        if (ef[1] >= 0)
          throw Error(ErrorCode::InvalidInput, "non-manifold edge between vertices " +
                                                   std::to_string(a) + " and " + std::to_string(b));
        ef[1] = f;
      }
      t.faceEdges[f][c] = it->second;
    }
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
