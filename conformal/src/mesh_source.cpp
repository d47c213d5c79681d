// Reading a mesh file into a TriMesh with every problem named as the file numbers it: the
// polygon soup is checked (non-manifold edges and vertices, orientation) before OpenMesh sees a
// face, so no add_face ever fails (OpenMesh would print its own message and drop the face).
#include "confvis/conformal/mesh_source.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "mesh_files.hpp"

namespace confvis::conformal {
namespace {

using Triangle = std::array<int, 3>;

std::string lowerExtension(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

// "faces 3, 7 and 9", at most `shown` named, then "and N more".
std::string listNames(const std::vector<std::string>& names, std::size_t shown = 6) {
  std::string s;
  const std::size_t n = std::min(names.size(), shown);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) s += (i + 1 == names.size() ? " and " : ", ");
    s += names[i];
  }
  if (names.size() > shown) s += " and " + std::to_string(names.size() - shown) + " more";
  return s;
}

// The triangles (file point indices, possibly welded) with the file face of each.
struct Triangles {
  std::vector<Triangle> corners;
  std::vector<int> face;
};

class SoupChecker {
 public:
  SoupChecker(const MeshSource& source, const Triangles& tris)
      : source_(source), tris_(tris), corners_(3 * tris.corners.size()) {}

  // The first problem that keeps these triangles from being an oriented 2-manifold, or nothing.
  std::optional<std::string> problem() {
    if (auto p = nonManifoldEdge()) return p;
    if (auto p = orientation()) return p;
    return nonManifoldVertex();
  }

 private:
  struct EdgeUse {
    std::uint64_t edge;  // both vertices, the smaller in the high half
    int triangle;
    int from;  // the triangle runs the edge from this vertex
  };
  static int low(std::uint64_t edge) { return static_cast<int>(edge >> 32); }
  static int high(std::uint64_t edge) { return static_cast<int>(edge & 0xffffffffu); }

  std::string face(int t) const {
    return "face " + std::to_string(tris_.face[t] + source_.firstNumber);
  }
  std::string vertex(int v) const { return source_.fileVertexName(v); }
  static std::uint64_t key(int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  }

  std::optional<std::string> nonManifoldEdge() {
    uses_.reserve(3 * tris_.corners.size());
    for (int t = 0; t < static_cast<int>(tris_.corners.size()); ++t)
      for (int c = 0; c < 3; ++c) {
        const int a = tris_.corners[t][c], b = tris_.corners[t][(c + 1) % 3];
        uses_.push_back({key(a, b), t, a});
      }
    std::sort(uses_.begin(), uses_.end(), [](const EdgeUse& x, const EdgeUse& y) {
      return x.edge < y.edge || (x.edge == y.edge && x.triangle < y.triangle);
    });
    for (std::size_t i = 0; i < uses_.size();) {
      std::size_t j = i;
      while (j < uses_.size() && uses_[j].edge == uses_[i].edge) ++j;
      runs_.push_back({i, j});
      i = j;
    }
    // The non-manifold edge of the lowest-numbered face.
    const std::pair<std::size_t, std::size_t>* worst = nullptr;
    for (const auto& run : runs_)
      if (run.second - run.first > 2 &&
          (!worst || tris_.face[uses_[run.first].triangle] < tris_.face[uses_[worst->first].triangle]))
        worst = &run;
    if (!worst) return std::nullopt;
    std::vector<std::string> faces;
    for (std::size_t k = worst->first; k < worst->second; ++k) faces.push_back(face(uses_[k].triangle));
    const std::uint64_t edge = uses_[worst->first].edge;
    return "the edge between " + vertex(low(edge)) + " and " + vertex(high(edge)) + " is shared by " +
           std::to_string(faces.size()) + " faces (" + listNames(faces) +
           "): a non-manifold edge (an edge may border at most two faces)";
  }

  // Faces are propagated an orientation across shared edges; an edge both faces run the same
  // way means one of them is listed the other way round. The smaller side is named.
  std::optional<std::string> orientation() {
    const int n = static_cast<int>(tris_.corners.size());
    std::vector<int> flag(n, -1);
    std::vector<std::vector<std::pair<int, bool>>> neighbours(n);  // (triangle, same direction)
    bool anyConflict = false;
    for (const auto& [begin, end] : runs_)
      if (end - begin == 2) {
        const EdgeUse &x = uses_[begin], &y = uses_[begin + 1];
        const bool same = x.from == y.from;
        anyConflict |= same;
        neighbours[x.triangle].push_back({y.triangle, same});
        neighbours[y.triangle].push_back({x.triangle, same});
      }
    if (!anyConflict) return std::nullopt;
    for (int seed = 0; seed < n; ++seed) {
      if (flag[seed] >= 0) continue;
      std::vector<int> stack{seed}, members;
      flag[seed] = 0;
      while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        members.push_back(t);
        for (const auto& [u, same] : neighbours[t]) {
          const int want = same ? 1 - flag[t] : flag[t];
          if (flag[u] < 0) {
            flag[u] = want;
            stack.push_back(u);
          } else if (flag[u] != want) {
            return "the faces around " + face(t) + " and " + face(u) +
                   " cannot be oriented consistently (a Möbius band): the surface is not "
                   "orientable";
          }
        }
      }
      int reversed = 0;
      for (int t : members) reversed += flag[t];
      const int minority = 2 * reversed <= static_cast<int>(members.size()) ? 1 : 0;
      std::vector<std::string> names;
      std::vector<int> minorityFaces;
      for (int t : members)
        if (flag[t] == minority) minorityFaces.push_back(tris_.face[t]);
      std::sort(minorityFaces.begin(), minorityFaces.end());
      minorityFaces.erase(std::unique(minorityFaces.begin(), minorityFaces.end()), minorityFaces.end());
      if (minorityFaces.empty() || minorityFaces.size() == members.size()) continue;
      for (int f : minorityFaces) names.push_back(std::to_string(f + source_.firstNumber));
      return std::string(minorityFaces.size() == 1 ? "face " : "faces ") + listNames(names) +
             (minorityFaces.size() == 1 ? " lists its" : " list their") +
             " corners the other way round from the neighbouring faces: inconsistent "
             "orientation (reverse " + (minorityFaces.size() == 1 ? "its" : "their") +
             " corners)";
    }
    return std::nullopt;
  }

  // With every edge in at most two faces: the corners at a vertex joined across the edges
  // there form its fans; more than one fan is a non-manifold vertex.
  std::optional<std::string> nonManifoldVertex() {
    UnionFind fans(corners_);
    auto cornerOf = [&](int t, int v) {
      for (int c = 0; c < 3; ++c)
        if (tris_.corners[t][c] == v) return 3 * t + c;
      return -1;
    };
    for (const auto& [begin, end] : runs_) {
      if (end - begin != 2) continue;
      const EdgeUse &x = uses_[begin], &y = uses_[begin + 1];
      for (const int v : {low(x.edge), high(x.edge)})
        fans.join(cornerOf(x.triangle, v), cornerOf(y.triangle, v));
    }
    // Corners sorted by (vertex, fan): a vertex with two fans has two distinct roots in its run.
    std::vector<std::pair<int, int>> cornerFans;  // (vertex, fan root)
    cornerFans.reserve(corners_);
    for (int t = 0; t < static_cast<int>(tris_.corners.size()); ++t)
      for (int c = 0; c < 3; ++c) cornerFans.push_back({tris_.corners[t][c], fans.find(3 * t + c)});
    std::sort(cornerFans.begin(), cornerFans.end());
    cornerFans.erase(std::unique(cornerFans.begin(), cornerFans.end()), cornerFans.end());
    int worst = -1;
    std::vector<int> roots;
    for (std::size_t i = 0; i + 1 < cornerFans.size() && worst < 0; ++i)
      if (cornerFans[i].first == cornerFans[i + 1].first) worst = cornerFans[i].first;
    if (worst < 0) return std::nullopt;
    for (const auto& [v, root] : cornerFans)
      if (v == worst) roots.push_back(root);
    std::vector<std::string> names;
    for (int r : roots) names.push_back(face(r / 3));
    return vertex(worst) + " joins " + std::to_string(roots.size()) +
           " fans of faces that share no edge there (the fans of " + listNames(names) +
           "): a non-manifold vertex, as where two pieces touch at a point (a bowtie)";
  }

  const MeshSource& source_;
  const Triangles& tris_;
  std::size_t corners_;
  // Every triangle's three edge uses, sorted by edge: the uses of one edge are a run.
  std::vector<EdgeUse> uses_;
  std::vector<std::pair<std::size_t, std::size_t>> runs_;  // [begin, end) in uses_ per edge
};

[[noreturn]] void fail(const MeshSource& source, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, "mesh '" + source.path.string() + "': " + what + " (" +
                                           source.numbering() + ")");
}

}  // namespace

std::string MeshSource::fileVertexName(int fileIndex) const {
  std::ostringstream s;
  s << "vertex " << fileIndex + firstNumber;
  if (fileIndex >= 0 && fileIndex < static_cast<int>(filePoints.size())) {
    const auto& p = filePoints[fileIndex];
    s << " (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  }
  return s.str();
}

std::string MeshSource::faceName(int meshTriangle) const {
  return "face " + std::to_string(fileFace.at(meshTriangle) + firstNumber);
}

std::string MeshSource::numbering() const {
  if (format == "STL") return "facets numbered from 1, vertices from 1 in order of first use";
  return std::string("faces and vertices numbered from ") + (firstNumber == 1 ? "1" : "0") +
         " as in the " + format + " file";
}

TriMesh readMesh(const std::filesystem::path& path, MeshSource& source) {
  if (!pathExists(path))
    throw Error(ErrorCode::FileNotFound, "mesh file '" + path.string() + "' does not exist");
  // Our own readers (mesh_files.hpp), not OpenMesh's: those hang or crash on small malformed
  // files. Polygons are fanned into triangles, as OpenMesh's TriMesh reader does.
  detail::PolygonSoup soup = detail::readPolygonFile(path);
  const std::string extension = lowerExtension(path);
  source = MeshSource{};
  source.path = path;
  source.format = extension == ".obj" ? "OBJ" : extension == ".off" ? "OFF"
                  : extension == ".ply" ? "PLY" : "STL";
  source.firstNumber = source.format == "OFF" || source.format == "PLY" ? 0 : 1;
  source.filePoints = soup.points;
  const int points = static_cast<int>(soup.points.size());
  for (int i = 0; i < points; ++i)
    for (double c : soup.points[i])
      if (!std::isfinite(c)) fail(source, source.fileVertexName(i) + " has a non-finite coordinate");

  Triangles plain;
  for (std::size_t f = 0; f < soup.starts.size(); ++f) {
    const std::size_t begin = soup.starts[f];
    const std::size_t end = f + 1 < soup.starts.size() ? soup.starts[f + 1] : soup.corners.size();
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j)
        if (soup.corners[i] == soup.corners[j])
          fail(source, "face " + std::to_string(f + source.firstNumber) + " repeats " +
                           source.fileVertexName(soup.corners[i]));
    for (std::size_t c = begin + 1; c + 1 < end; ++c) {
      plain.corners.push_back({soup.corners[begin], soup.corners[c], soup.corners[c + 1]});
      plain.face.push_back(static_cast<int>(f));
    }
  }
  if (plain.corners.empty()) fail(source, "has no faces");

  // Welding: each point to the first point at the same position (-0 and +0 alike).
  std::vector<int> weldedTo(points);
  {
    std::map<std::array<std::uint64_t, 3>, int> first;
    for (int i = 0; i < points; ++i) {
      std::array<std::uint64_t, 3> k;
      for (int c = 0; c < 3; ++c) k[c] = std::bit_cast<std::uint64_t>(soup.points[i][c] + 0.0);
      weldedTo[i] = first.try_emplace(k, i).first->second;
    }
  }
  Triangles welded = plain;
  bool weldingCollapses = false;
  for (Triangle& t : welded.corners) {
    for (int& v : t) v = weldedTo[v];
    weldingCollapses |= t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
  }
  // Welding is kept only where it leaves a manifold, consistently oriented mesh; otherwise the
  // file's own vertices are checked, and any problem named as the file has it.
  const Triangles* chosen = &welded;
  if (weldingCollapses || SoupChecker(source, welded).problem()) {
    if (auto p = SoupChecker(source, plain).problem()) fail(source, *p);
    chosen = &plain;
  }

  // Mesh vertices: the referenced (welded) points in file order.
  std::vector<int> meshVertexOf(points, -1);
  for (const Triangle& t : chosen->corners)
    for (int v : t) meshVertexOf[v] = 0;
  TriMesh mesh;
  for (int i = 0; i < points; ++i) {
    if (meshVertexOf[i] < 0) {
      if (chosen == &welded && weldedTo[i] != i && meshVertexOf[weldedTo[i]] >= 0)
        ++source.weldedVertices;
      else
        ++source.unreferencedVertices;
      continue;
    }
    meshVertexOf[i] = static_cast<int>(source.fileVertex.size());
    source.fileVertex.push_back(i);
    mesh.add_vertex(Vec3(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
  }
  mesh.reserve(source.fileVertex.size(), 3 * chosen->corners.size(), chosen->corners.size());
  for (std::size_t t = 0; t < chosen->corners.size(); ++t) {
    const Triangle& c = chosen->corners[t];
    const auto v = [&](int i) { return TriMesh::VertexHandle(meshVertexOf[c[i]]); };
    if (!mesh.add_face(v(0), v(1), v(2)).is_valid())
      throw Error(ErrorCode::Internal, "mesh '" + path.string() + "': checked face " +
                                           std::to_string(chosen->face[t] + source.firstNumber) +
                                           " could not be added");
    source.fileFace.push_back(chosen->face[t]);
  }
  for (auto e : mesh.edges())
    if (mesh.calc_edge_length(e) <= 0.0)
      fail(source, "the edge between " + source.vertexName(e.v0().idx()) + " and " +
                       source.vertexName(e.v1().idx()) +
                       " has zero length (two corners of a face at the same position)");
  return mesh;
}

void requireDisk(const TriMesh& mesh, const MeshSource& source) {
  const MeshTopology topology = analyzeTopology(mesh);
  if (topology.isDisk()) return;
  std::string where;
  // Pieces: faces joined across edges.
  UnionFind pieces(mesh.n_faces());
  for (auto e : mesh.edges())
    if (!e.is_boundary()) pieces.join(e.h0().face().idx(), e.h1().face().idx());
  std::map<int, std::pair<int, int>> byRoot;  // root -> (first triangle, triangles)
  for (int f = 0; f < static_cast<int>(mesh.n_faces()); ++f) {
    auto [it, inserted] = byRoot.try_emplace(pieces.find(f), f, 0);
    ++it->second.second;
  }
  const auto loops = boundaryLoops(mesh);
  if (byRoot.size() > 1) {
    std::vector<std::pair<int, int>> list;
    for (const auto& [root, piece] : byRoot) list.push_back(piece);
    std::sort(list.begin(), list.end());
    std::vector<std::string> names;
    for (const auto& [first, count] : list)
      names.push_back("the piece with " + source.faceName(first) + " (" + std::to_string(count) +
                      " triangles)");
    where = "it has " + std::to_string(list.size()) + " separate pieces: " + listNames(names, 4);
  } else if (loops.empty()) {
    where = "it has no boundary (a closed surface): cut it open";
  } else if (loops.size() > 1) {
    // The longest loop is taken as the outer boundary; the others are holes.
    std::size_t outer = 0;
    for (std::size_t i = 1; i < loops.size(); ++i)
      if (loops[i].size() > loops[outer].size()) outer = i;
    std::vector<std::string> holes;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      if (i == outer) continue;
      std::vector<std::string> vertices;
      for (int v : loops[i]) vertices.push_back(std::to_string(source.fileVertex.at(v) + source.firstNumber));
      holes.push_back("a hole bounded by vertices " + listNames(vertices, 5) + " (" +
                      std::to_string(loops[i].size()) + " boundary edges)");
    }
    where = "besides its outer boundary, it has " + listNames(holes, 3) + ": fill the hole";
  } else if (topology.isolatedVertices == 0) {
    where = "it has " + std::to_string((1 - topology.eulerCharacteristic) / 2) +
            " handle(s) (genus above 0): cut it to a disk";
  }
  fail(source, "not a topological disk (expected 1 component, 1 boundary loop, Euler "
               "characteristic 1; found " + topology.describe() + ")" +
                   (where.empty() ? "" : ": " + where));
}

}  // namespace confvis::conformal
