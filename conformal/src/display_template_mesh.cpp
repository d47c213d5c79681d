// Template mesh plumbing: stitching fan cells, sub-meshes, cutting along a tree, topology.
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <numbers>
#include <numeric>

#include "confvis/base/error.hpp"
#include "display_template_parts.hpp"

namespace confvis::detail {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

// Newell normal of a polygon (not normalised).
glm::dvec3 polygonNormal(const std::vector<glm::dvec3>& polygon) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < polygon.size(); ++i)
    n += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return n;
}

// Corners of `candidates` strictly inside segment a-b, in order from a.
std::vector<glm::dvec3> pointsOnSegment(const glm::dvec3& a, const glm::dvec3& b,
                                        const std::vector<glm::dvec3>& candidates) {
  const glm::dvec3 d = b - a;
  const double length = glm::length(d);
  const glm::dvec3 u = d / length;
  std::vector<std::pair<double, glm::dvec3>> on;
  for (const glm::dvec3& p : candidates) {
    const double t = glm::dot(p - a, u);
    if (t <= kTemplateTolerance || t >= length - kTemplateTolerance) continue;
    if (glm::length(p - a - t * u) > kTemplateTolerance) continue;
    on.emplace_back(t, p);
  }
  std::sort(on.begin(), on.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<glm::dvec3> result;
  for (std::size_t i = 0; i < on.size(); ++i)
    if (i == 0 || on[i].first - on[i - 1].first > kTemplateTolerance)
      result.push_back(on[i].second);
  return result;
}

int vertexAt(TemplateBuild& mesh, const glm::dvec3& p) {
  const int found = findVertex(mesh, p);
  if (found >= 0) return found;
  mesh.points.push_back(p);
  return mesh.vertexCount() - 1;
}

// Directed edges of every triangle as (from, to, triangle, corner of `from`), sorted by the
// undirected key, so each interior edge's two sides are neighbours.
struct HalfEdge {
  std::uint64_t sortKey;  // undirected edge, then direction
  int from, to, triangle, corner;
  std::pair<int, int> key() const { return edgeKey(from, to); }
  std::uint64_t edge() const { return sortKey >> 1; }
};
std::vector<HalfEdge> sortedHalfEdges(const TemplateBuild& mesh) {
  // Counting sort by the lower vertex, then the few half-edges per vertex by their key: linear
  // time (a plain sort of all half-edges dominated the template stage).
  std::vector<int> start(mesh.points.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<HalfEdge> half(mesh.triangles.size() * 3);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
      const auto [lo, hi] = edgeKey(from, to);
      const std::uint64_t edge = (static_cast<std::uint64_t>(lo) << 31) | static_cast<std::uint64_t>(hi);
      half[fill[lo]++] = {(edge << 1) | (from > to ? 1u : 0u), from, to, t, k};
    }
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    std::sort(half.begin() + start[v], half.begin() + start[v + 1],
              [](const HalfEdge& a, const HalfEdge& b) { return a.sortKey < b.sortKey; });
  return half;
}

// Union of triangle corners (3t + k) around each vertex across interior edges not cut.
UnionFind cornerWedges(const TemplateBuild& mesh, const std::vector<HalfEdge>& half,
                       bool honourCut) {
  UnionFind wedges(static_cast<int>(mesh.triangles.size()) * 3);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].edge() == half[i].edge()) ++j;
    // Only manifold interior edges with opposite directions join wedges.
    const HalfEdge& a = half[i];
    if (j - i == 2 && a.from == half[i + 1].to && !(honourCut && mesh.cut.count(a.key()))) {
      const HalfEdge& b = half[i + 1];
      wedges.unite(3 * a.triangle + a.corner, 3 * b.triangle + (b.corner + 1) % 3);
      wedges.unite(3 * a.triangle + (a.corner + 1) % 3, 3 * b.triangle + b.corner);
    }
    i = j;
  }
  return wedges;
}

}  // namespace

int TemplateBuild::addTriangle(const std::array<int, 3>& t, const FanCell& cell) {
  triangles.push_back(t);
  lit.push_back(cell.lit ? 1 : 0);
  covered.push_back(cell.covered ? 1 : 0);
  spherical.push_back(cell.spherical ? 1 : 0);
  wall.push_back(cell.wall);
  return static_cast<int>(triangles.size()) - 1;
}

std::vector<EdgeSides> edgeSides(const TemplateBuild& mesh) {
  const auto half = sortedHalfEdges(mesh);
  std::vector<EdgeSides> edges;
  edges.reserve(half.size() / 2 + 1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].edge() == half[i].edge()) ++j;
    EdgeSides e{half[i].from, half[i].to, half[i].triangle, half[i].corner};
    if (j - i >= 2) e.t1 = half[i + 1].triangle, e.k1 = half[i + 1].corner;
    edges.push_back(e);
    i = j;
  }
  return edges;
}

int findVertex(const TemplateBuild& mesh, const glm::dvec3& p) {
  for (int i = 0; i < mesh.vertexCount(); ++i)
    if (glm::length(mesh.points[i] - p) <= kTemplateTolerance) return i;
  return -1;
}

TemplateBuild assembleCells(std::vector<FanCell> cells, const glm::dvec3& reference,
                            const std::vector<glm::dvec3>& extraPoints) {
  std::vector<glm::dvec3> corners = extraPoints;
  for (const FanCell& cell : cells)
    corners.insert(corners.end(), cell.polygon.begin(), cell.polygon.end());
  TemplateBuild mesh;
  for (FanCell& cell : cells) {
    if (!cell.spherical) {
      glm::dvec3 centroid(0.0);
      for (const glm::dvec3& p : cell.polygon) centroid += p / double(cell.polygon.size());
      if (glm::dot(polygonNormal(cell.polygon), reference - centroid) < 0)
        std::reverse(cell.polygon.begin(), cell.polygon.end());
    }
    std::vector<int> ring;
    for (std::size_t i = 0; i < cell.polygon.size(); ++i) {
      const glm::dvec3& a = cell.polygon[i];
      const glm::dvec3& b = cell.polygon[(i + 1) % cell.polygon.size()];
      ring.push_back(vertexAt(mesh, a));
      for (const glm::dvec3& p : pointsOnSegment(a, b, corners)) ring.push_back(vertexAt(mesh, p));
    }
    const int centre = vertexAt(mesh, cell.centre);
    for (std::size_t i = 0; i < ring.size(); ++i)
      mesh.addTriangle({centre, ring[i], ring[(i + 1) % ring.size()]}, cell);
  }
  return mesh;
}

void addCutEdge(TemplateBuild& mesh, const glm::dvec3& a, const glm::dvec3& b) {
  const int ia = findVertex(mesh, a), ib = findVertex(mesh, b);
  if (ia < 0 || ib < 0 || ia == ib)
    throw Error(ErrorCode::Internal,
                "display template: cut edge endpoint is not a template vertex");
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (edgeKey(t[k], t[(k + 1) % 3]) == edgeKey(ia, ib)) {
        mesh.cut.insert(edgeKey(ia, ib));
        return;
      }
  throw Error(ErrorCode::Internal, "display template: cut edge is not a template edge");
}

TemplateBuild extractTriangles(const TemplateBuild& mesh, const std::vector<std::uint8_t>& keep,
                               std::vector<int>* vertexMap) {
  std::vector<int> map(mesh.points.size(), -1);
  TemplateBuild out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!keep[t]) continue;
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      int& m = map[mesh.triangles[t][k]];
      if (m < 0) {
        m = out.vertexCount();
        out.points.push_back(mesh.points[mesh.triangles[t][k]]);
      }
      tri[k] = m;
    }
    out.triangles.push_back(tri);
    out.lit.push_back(mesh.lit[t]);
    out.covered.push_back(mesh.covered[t]);
    out.spherical.push_back(mesh.spherical[t]);
    out.wall.push_back(mesh.wall[t]);
  }
  for (const auto& [a, b] : mesh.cut)
    if (map[a] >= 0 && map[b] >= 0) out.cut.insert(edgeKey(map[a], map[b]));
  if (vertexMap) *vertexMap = std::move(map);
  return out;
}

TemplateBuild cutOpen(const TemplateBuild& mesh, std::vector<int>* origin) {
  const auto half = sortedHalfEdges(mesh);
  UnionFind wedges = cornerWedges(mesh, half, true);
  TemplateBuild out = mesh;
  out.points.clear();
  out.cut.clear();
  std::vector<int> copyOf(mesh.triangles.size() * 3, -1), from;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      int& id = copyOf[wedges.find(static_cast<int>(3 * t + k))];
      if (id < 0) {
        id = out.vertexCount();
        out.points.push_back(mesh.points[mesh.triangles[t][k]]);
        from.push_back(mesh.triangles[t][k]);
      }
      out.triangles[t][k] = id;
    }
  if (origin) *origin = std::move(from);
  return out;
}

TriangleTopology analyzeTriangles(const TemplateBuild& mesh) {
  TriangleTopology topo;
  topo.faces = static_cast<int>(mesh.triangles.size());
  const auto half = sortedHalfEdges(mesh);
  std::vector<char> used(mesh.points.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int v : t) used[v] = 1;
  topo.vertices = static_cast<int>(std::count(used.begin(), used.end(), 1));
  std::vector<int> boundaryNext(mesh.points.size(), -1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].edge() == half[i].edge()) ++j;
    ++topo.edges;
    if (j - i > 2 || (j - i == 2 && half[i].from == half[i + 1].from))
      topo.nonManifoldEdges.push_back(half[i].key());
    if (j - i == 1) {
      if (boundaryNext[half[i].from] >= 0) topo.nonManifoldVertices.push_back(half[i].from);
      boundaryNext[half[i].from] = half[i].to;
    }
    i = j;
  }
  // Separate fans at one vertex (cones touching at a point, bow ties).
  UnionFind wedges = cornerWedges(mesh, half, false);
  std::vector<int> fanOwner(mesh.triangles.size() * 3, -1), fans(mesh.points.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      int& owner = fanOwner[wedges.find(static_cast<int>(3 * t + k))];
      if (owner < 0) {
        owner = mesh.triangles[t][k];
        if (++fans[owner] == 2) topo.nonManifoldVertices.push_back(owner);
      }
    }
  std::sort(topo.nonManifoldVertices.begin(), topo.nonManifoldVertices.end());
  topo.nonManifoldVertices.erase(
      std::unique(topo.nonManifoldVertices.begin(), topo.nonManifoldVertices.end()),
      topo.nonManifoldVertices.end());
  UnionFind components(static_cast<int>(mesh.points.size()));
  for (const auto& t : mesh.triangles) {
    components.unite(t[0], t[1]);
    components.unite(t[1], t[2]);
  }
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (used[v] && components.find(static_cast<int>(v)) == static_cast<int>(v)) ++topo.components;
  if (!topo.manifold()) return topo;
  std::vector<char> visited(mesh.points.size(), 0);
  for (int start = 0; start < static_cast<int>(boundaryNext.size()); ++start) {
    if (boundaryNext[start] < 0 || visited[start]) continue;
    std::vector<int> loop;
    for (int v = start; v >= 0 && !visited[v]; v = boundaryNext[v]) {
      visited[v] = 1;
      loop.push_back(v);
    }
    topo.boundaryLoops.push_back(std::move(loop));
  }
  return topo;
}

double sphericalBoundaryAngle(const glm::dvec3& reference, const glm::dvec3& prev,
                              const glm::dvec3& v, const glm::dvec3& next) {
  const glm::dvec3 d = glm::normalize(v - reference);
  auto tangent = [&](const glm::dvec3& x) {
    const glm::dvec3 e = glm::normalize(x - reference);
    return glm::normalize(e - glm::dot(e, d) * d);
  };
  const glm::dvec3 tp = tangent(prev), tn = tangent(next);
  // Counter-clockwise as seen from the reference point: about -d.
  double angle = std::atan2(glm::dot(glm::cross(tn, tp), -d), glm::dot(tn, tp));
  if (angle <= 0) angle += 2 * std::numbers::pi;
  return angle;
}

std::pair<glm::dvec3, double> kernelCentre(const std::vector<glm::dvec3>& normals, int samples) {
  auto margin = [&](const glm::dvec3& q) {
    double m = 2;
    for (const glm::dvec3& n : normals) m = std::min(m, glm::dot(q, n));
    return m;
  };
  glm::dvec3 best(0, 0, 1);
  double bestMargin = -3;
  for (int i = 0; i < samples; ++i) {  // Fibonacci sphere
    const double z = 1 - (2 * i + 1.0) / samples, r = std::sqrt(1 - z * z);
    const double phi = i * std::numbers::pi * (3 - std::sqrt(5.0));
    const glm::dvec3 q(r * std::cos(phi), r * std::sin(phi), z);
    const double m = margin(q);
    if (m > bestMargin) bestMargin = m, best = q;
  }
  for (double step = 0.05; step > 1e-7; step *= 0.5)
    for (bool improved = true; improved;) {
      improved = false;
      const glm::dvec3 e1 = glm::normalize(
          glm::cross(best, std::abs(best.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
      const glm::dvec3 e2 = glm::cross(best, e1);
      for (const glm::dvec3& d : {e1, -e1, e2, -e2, e1 + e2, e1 - e2, -e1 + e2, -e1 - e2}) {
        const glm::dvec3 q = glm::normalize(best + step * d);
        const double m = margin(q);
        if (m > bestMargin + 1e-15) bestMargin = m, best = q, improved = true;
      }
    }
  return {best, bestMargin};
}

double directionAngle(const glm::dvec3& reference, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 u = a - reference, w = b - reference;
  return std::atan2(glm::length(glm::cross(u, w)), glm::dot(u, w));
}

}  // namespace confvis::detail
