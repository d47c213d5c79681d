#include "confvis/conformal/mesh.hpp"


#include <cmath>
#include <numeric>
#include <sstream>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh_source.hpp"

namespace confvis::conformal {

std::string MeshTopology::describe() const {
  std::ostringstream s;
  s << "V=" << vertices << ", E=" << edges << ", F=" << faces << ", Euler characteristic "
    << eulerCharacteristic << ", " << boundaryLoops << " boundary loop"
    << (boundaryLoops == 1 ? "" : "s") << ", " << components << " component"
    << (components == 1 ? "" : "s");
  if (isolatedVertices > 0) s << ", " << isolatedVertices << " isolated vertices";
  return s.str();
}

std::vector<std::vector<int>> boundaryLoops(const TriMesh& mesh) {
  std::vector<std::vector<int>> loops;
  std::vector<char> seen(mesh.n_halfedges(), 0);
  for (auto h : mesh.halfedges()) {
    if (!h.is_boundary() || seen[h.idx()]) continue;
    std::vector<int> loop;
    auto cur = h;
    // A boundary loop returns to its start; the bound guards against non-manifold input.
    for (std::size_t steps = 0; steps <= mesh.n_halfedges(); ++steps) {
      seen[cur.idx()] = 1;
      loop.push_back(cur.from().idx());
      cur = cur.next();
      if (cur == h) break;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

MeshTopology analyzeTopology(const TriMesh& mesh) {
  MeshTopology t;
  t.vertices = static_cast<int>(mesh.n_vertices());
  t.edges = static_cast<int>(mesh.n_edges());
  t.faces = static_cast<int>(mesh.n_faces());
  for (auto v : mesh.vertices())
    if (mesh.is_isolated(v)) ++t.isolatedVertices;
  t.eulerCharacteristic = t.vertices - t.edges + t.faces;
  t.boundaryLoops = static_cast<int>(boundaryLoops(mesh).size());
  // Components by union-find over edges (isolated vertices count as their own).
  std::vector<int> parent(mesh.n_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (auto e : mesh.edges()) parent[find(e.v0().idx())] = find(e.v1().idx());
  for (int v = 0; v < t.vertices; ++v)
    if (find(v) == v) ++t.components;
  return t;
}

void requireDisk(const TriMesh& mesh, const std::string& what) {
  const MeshTopology t = analyzeTopology(mesh);
  if (!t.isDisk())
    throw Error(ErrorCode::InvalidInput,
                what + " is not a topological disk (expected 1 component, 1 boundary loop, "
                       "Euler characteristic 1; found " + t.describe() + ")");
}

TriMesh readMesh(const std::filesystem::path& path) {
  MeshSource source;
  return readMesh(path, source);
}

}  // namespace confvis::conformal
