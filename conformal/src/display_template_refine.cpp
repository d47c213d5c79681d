// Longest-edge bisection of a template (dissertation 8.3.3: "a new vertex is introduced at the
// mid-point of each edge"). Always splitting the globally longest edge means the split edge is
// the longest of both its triangles, so triangle shapes stay bounded (Rivara), and every final
// triangle keeps its longest edge above maxEdge / 2 (no over-refinement).
#include <cmath>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "confvis/base/error.hpp"
#include "display_template_parts.hpp"

namespace confvis::detail {
namespace {

std::uint64_t key64(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

struct EdgeFaces {
  int t[2] = {-1, -1};
  void replace(int from, int to) { (t[0] == from ? t[0] : t[1]) = to; }
  void add(int f) { (t[0] < 0 ? t[0] : t[1]) = f; }
};

struct Candidate {
  double length;
  int a, b;
  bool operator<(const Candidate& o) const {  // max-heap by length, ties by indices
    if (length != o.length) return length < o.length;
    return a != o.a ? a > o.a : b > o.b;
  }
};

}  // namespace

void refineTemplate(TemplateBuild& mesh, const glm::dvec3& reference, double maxEdge) {
  std::unordered_map<std::uint64_t, EdgeFaces> edges;
  std::unordered_set<std::uint64_t> cut;
  edges.reserve(mesh.triangles.size() * 3);
  std::priority_queue<Candidate> queue;
  auto consider = [&](int a, int b) {
    const double length = glm::length(mesh.points[a] - mesh.points[b]);
    if (length > maxEdge) queue.push({length, std::min(a, b), std::max(a, b)});
  };
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      auto [it, inserted] = edges.try_emplace(key64(a, b));
      it->second.add(t);
      if (inserted) consider(a, b);
    }
  for (const auto& [a, b] : mesh.cut) cut.insert(key64(a, b));

  while (!queue.empty()) {
    const Candidate top = queue.top();
    queue.pop();
    const auto found = edges.find(key64(top.a, top.b));
    if (found == edges.end()) continue;  // already split
    const EdgeFaces faces = found->second;
    edges.erase(found);
    const glm::dvec3 pa = mesh.points[top.a], pb = mesh.points[top.b];
    bool spherical = true;
    for (int f : faces.t)
      if (f >= 0 && !mesh.spherical[f]) spherical = false;
    glm::dvec3 mid = 0.5 * (pa + pb);
    if (spherical) {
      const glm::dvec3 da = pa - reference, db = pb - reference;
      const double ra = glm::length(da), rb = glm::length(db);
      mid = reference + 0.5 * (ra + rb) * glm::normalize(da / ra + db / rb);
    }
    const int m = mesh.vertexCount();
    mesh.points.push_back(mid);
    const bool wasCut = cut.erase(key64(top.a, top.b)) > 0;
    if (wasCut) {
      cut.insert(key64(top.a, m));
      cut.insert(key64(m, top.b));
    }
    for (int f : faces.t) {
      if (f < 0) continue;
      const std::array<int, 3> tri = mesh.triangles[f];
      int k = 0;
      while (!((tri[k] == top.a && tri[(k + 1) % 3] == top.b) ||
               (tri[k] == top.b && tri[(k + 1) % 3] == top.a)))
        ++k;
      const int u = tri[k], v = tri[(k + 1) % 3], x = tri[(k + 2) % 3];
      const int g = static_cast<int>(mesh.triangles.size());
      mesh.triangles[f] = {u, m, x};
      mesh.triangles.push_back({m, v, x});
      mesh.lit.push_back(mesh.lit[f]);
      mesh.covered.push_back(mesh.covered[f]);
      mesh.spherical.push_back(mesh.spherical[f]);
      mesh.wall.push_back(mesh.wall[f]);
      edges[key64(v, x)].replace(f, g);
      edges[key64(u, m)].add(f);
      edges[key64(m, v)].add(g);
      EdgeFaces& median = edges[key64(m, x)];
      median.add(f);
      median.add(g);
      consider(m, x);
    }
    consider(top.a, m);
    consider(m, top.b);
  }
  mesh.cut.clear();
  for (std::uint64_t k : cut)
    mesh.cut.insert({static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu)});
}

}  // namespace confvis::detail
