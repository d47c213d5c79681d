#include "confvis/conformal/mesh.hpp"


#include <cmath>
#include <numeric>
#include <sstream>

#include "confvis/base/error.hpp"
#include "mesh_files.hpp"

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
  if (!std::filesystem::exists(path))
    throw Error(ErrorCode::FileNotFound, "mesh file '" + path.string() + "' does not exist");
  // Our own readers (mesh_files.hpp), not OpenMesh's: those hang or crash on small malformed
  // files. Polygons are fanned into triangles, as OpenMesh's TriMesh reader does.
  const detail::PolygonSoup soup = detail::readPolygonFile(path);
  TriMesh mesh;
  mesh.reserve(soup.points.size(), 3 * soup.starts.size(), soup.starts.size());
  for (const auto& p : soup.points) mesh.add_vertex(Vec3(p[0], p[1], p[2]));
  for (std::size_t f = 0; f < soup.starts.size(); ++f) {
    const std::size_t begin = soup.starts[f];
    const std::size_t end = f + 1 < soup.starts.size() ? soup.starts[f + 1] : soup.corners.size();
    for (std::size_t c = begin + 1; c + 1 < end; ++c) {
      const auto v = [&](std::size_t i) { return TriMesh::VertexHandle(soup.corners[i]); };
      if (soup.corners[begin] == soup.corners[c] || soup.corners[c] == soup.corners[c + 1] ||
          soup.corners[begin] == soup.corners[c + 1])
        throw Error(ErrorCode::InvalidInput, "mesh '" + path.string() + "': face " +
                                                 std::to_string(f) + " repeats a vertex");
      if (!mesh.add_face(v(begin), v(c), v(c + 1)).is_valid())
        throw Error(ErrorCode::InvalidInput,
                    "mesh '" + path.string() + "': face " + std::to_string(f) +
                        " cannot be added (a non-manifold edge or vertex, or a flipped face)");
    }
  }
  if (mesh.n_faces() == 0)
    throw Error(ErrorCode::InvalidInput, "mesh '" + path.string() + "' has no faces");
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Error(ErrorCode::InvalidInput, "mesh '" + path.string() + "' vertex " +
                                               std::to_string(v.idx()) +
                                               " has a non-finite coordinate");
  }
  for (auto e : mesh.edges()) {
    if (mesh.calc_edge_length(e) <= 0.0)
      throw Error(ErrorCode::InvalidInput,
                  "mesh '" + path.string() + "' has a zero-length edge between vertices " +
                      std::to_string(e.v0().idx()) + " and " + std::to_string(e.v1().idx()));
  }
  return mesh;
}

}  // namespace confvis::conformal
