// Longest-edge bisection of a template (dissertation 8.3.3: "a new vertex is introduced at the
// mid-point of each edge"). Always splitting the globally longest edge means the split edge is
// the longest of both its triangles, so triangle shapes stay bounded (Rivara), and every final
// triangle keeps its longest edge above maxEdge / 2 (no over-refinement). Triangles keep their
// neighbours across each edge, so a split is a constant-time update.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>

#include "confvis/base/error.hpp"
#include "display_template_parts.hpp"

namespace confvis::detail {
namespace {

struct Candidate {
  double length;
  int a, b, triangle;                         // the edge a-b, one of its triangles when queued
  bool operator<(const Candidate& o) const {  // max-heap by length, ties by indices
    if (length != o.length) return length < o.length;
    return a != o.a ? a > o.a : b > o.b;
  }
};

class Refiner {
 public:
  Refiner(TemplateBuild& mesh, const glm::dvec3& reference, const SizeField& size)
      : mesh_(mesh), reference_(reference), size_(size) {
    const std::size_t n = mesh.triangles.size();
    neighbour_.assign(n, {-1, -1, -1});
    cut_.assign(n, {0, 0, 0});
    for (const EdgeSides& e : edgeSides(mesh)) {
      const std::uint8_t isCut = mesh.cut.count(edgeKey(e.a, e.b)) ? 1 : 0;
      cut_[e.t0][e.k0] = isCut;
      if (e.t1 >= 0) {
        neighbour_[e.t0][e.k0] = e.t1;
        neighbour_[e.t1][e.k1] = e.t0;
        cut_[e.t1][e.k1] = isCut;
      }
      consider(e.a, e.b, e.t0);
    }
  }

  void run() {
    while (!queue_.empty()) {
      const Candidate top = queue_.top();
      queue_.pop();
      const int k = cornerOf(top.triangle, top.a, top.b);
      if (k < 0) continue;  // already split
      // Graded: the popped edge need not be the longest of its triangles; split those first.
      if (size_.graded()) {
        const int n = neighbour_[top.triangle][k];
        if (queueLonger(top.triangle, top.length) ||
            (n >= 0 && queueLonger(n, top.length))) {
          queue_.push(top);
          continue;
        }
      }
      // An isosceles triangle whose two equal sides are its longest (a fan triangle between
      // mirror-image corners) is split at its base first, into two mirror-image halves: bisecting
      // one equal side before the other would break the mirror symmetry of the display in its
      // mesh, and so in its map. The popped side is queued again.
      const int n = neighbour_[top.triangle][k];
      const int baseT = isoscelesBase(top.triangle, k);
      const int baseN = n >= 0 && baseT < 0 ? isoscelesBase(n, cornerOf(n, top.a, top.b)) : -1;
      if (baseT >= 0 || baseN >= 0) {
        if (baseT >= 0) split(top.triangle, baseT);
        else split(n, baseN);
        queue_.push(top);  // stale if the side moved to a child: split() queued it there
        continue;
      }
      split(top.triangle, k);
    }
    mesh_.cut.clear();
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        if (cut_[t][k])
          mesh_.cut.insert(edgeKey(mesh_.triangles[t][k], mesh_.triangles[t][(k + 1) % 3]));
  }

 private:
  void consider(int a, int b, int t) {
    const double length = glm::length(mesh_.points[a] - mesh_.points[b]);
    if (length <= size_.maxEdge * size_.minScale) return;
    double allowed = size_.maxEdge;
    if (size_.graded())
      allowed = size_.at(glm::normalize(0.5 * (mesh_.points[a] + mesh_.points[b]) - reference_));
    if (length > allowed) queue_.push({length, std::min(a, b), std::max(a, b), t});
  }

  // Queues t's longest edge if it is longer than `length` (beyond rounding); true if queued.
  bool queueLonger(int t, double length) {
    int longest = 0;
    for (int k = 1; k < 3; ++k)
      if (edgeLength(t, k) > edgeLength(t, longest)) longest = k;
    const double l = edgeLength(t, longest);
    if (l <= length * (1 + 1e-9)) return false;
    const auto& v = mesh_.triangles[t];
    const int a = v[longest], b = v[(longest + 1) % 3];
    queue_.push({l, std::min(a, b), std::max(a, b), t});
    return true;
  }

  // Corner k of t where the edge {a, b} starts, -1 if t has no such edge.
  int cornerOf(int t, int a, int b) const {
    const auto& v = mesh_.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int p = v[k], q = v[(k + 1) % 3];
      if ((p == a && q == b) || (p == b && q == a)) return k;
    }
    return -1;
  }

  double edgeLength(int t, int k) const {
    const auto& v = mesh_.triangles[t];
    return glm::length(mesh_.points[v[k]] - mesh_.points[v[(k + 1) % 3]]);
  }

  // The corner starting t's base where the edge at corner k ties with exactly one other edge of
  // t (to 1e-12) and both are longer than the third, the base; else -1.
  int isoscelesBase(int t, int k) const {
    if (k < 0) return -1;
    const double l = edgeLength(t, k), l1 = edgeLength(t, (k + 1) % 3),
                 l2 = edgeLength(t, (k + 2) % 3);
    const double tie = 1e-12 * l;
    if (std::abs(l1 - l) <= tie && l2 < l - tie) return (k + 2) % 3;
    if (std::abs(l2 - l) <= tie && l1 < l - tie) return (k + 1) % 3;
    return -1;
  }

  // Rotates triangle t so that its corner k comes first.
  void rotate(int t, int k) {
    auto spin = [k](auto& array) {
      const auto copy = array;
      for (int i = 0; i < 3; ++i) array[i] = copy[(i + k) % 3];
    };
    spin(mesh_.triangles[t]);
    spin(neighbour_[t]);
    spin(cut_[t]);
  }

  int addChild(int parent, const std::array<int, 3>& vertices) {
    mesh_.triangles.push_back(vertices);
    mesh_.lit.push_back(mesh_.lit[parent]);
    mesh_.covered.push_back(mesh_.covered[parent]);
    mesh_.spherical.push_back(mesh_.spherical[parent]);
    mesh_.wall.push_back(mesh_.wall[parent]);
    neighbour_.push_back({-1, -1, -1});
    cut_.push_back({0, 0, 0});
    return static_cast<int>(mesh_.triangles.size()) - 1;
  }

  void relink(int t, int from, int to) {
    if (t < 0) return;
    for (int& n : neighbour_[t])
      if (n == from) n = to;
  }

  glm::dvec3 midpoint(int a, int b, bool spherical) const {
    const glm::dvec3 pa = mesh_.points[a], pb = mesh_.points[b];
    if (!spherical) return 0.5 * (pa + pb);
    const glm::dvec3 da = pa - reference_, db = pb - reference_;
    const double ra = glm::length(da), rb = glm::length(db);
    return reference_ + 0.5 * (ra + rb) * glm::normalize(da / ra + db / rb);
  }

  // Splits the edge at corner k of t (and of its neighbour across it) at the mid-point.
  void split(int t, int k) {
    rotate(t, k);
    const int u = mesh_.triangles[t][0], v = mesh_.triangles[t][1], x = mesh_.triangles[t][2];
    const int n = neighbour_[t][0];
    const std::uint8_t isCut = cut_[t][0];
    const bool spherical = mesh_.spherical[t] && (n < 0 || mesh_.spherical[n]);
    const int m = mesh_.vertexCount();
    mesh_.points.push_back(midpoint(u, v, spherical));
    // t = (u, v, x) becomes (u, m, x) and g = (m, v, x).
    const int g = addChild(t, {m, v, x});
    const int tB = neighbour_[t][1];
    neighbour_[g] = {n, tB, t};
    cut_[g] = {isCut, cut_[t][1], 0};
    relink(tB, t, g);
    mesh_.triangles[t] = {u, m, x};
    neighbour_[t][1] = g;
    cut_[t][1] = 0;
    consider(m, x, t);
    if (n >= 0) {
      const int j = cornerOf(n, u, v);
      if (j < 0) throw Error(ErrorCode::Internal, "template refinement: broken neighbour link");
      rotate(n, j);  // n = (v, u, y)
      const int y = mesh_.triangles[n][2];
      // n becomes (v, m, y) and h = (m, u, y).
      const int h = addChild(n, {m, u, y});
      const int nD = neighbour_[n][1];
      neighbour_[h] = {t, nD, n};
      cut_[h] = {isCut, cut_[n][1], 0};
      relink(nD, n, h);
      mesh_.triangles[n] = {v, m, y};
      neighbour_[n] = {g, h, neighbour_[n][2]};
      cut_[n][1] = 0;
      neighbour_[g][0] = n;
      neighbour_[t][0] = h;
      consider(m, y, n);
      consider(u, y, h);  // moved from n to h
    }
    consider(u, m, t);
    consider(m, v, g);
    consider(v, x, g);  // moved from t to g: entries naming t for it are stale now
  }

  TemplateBuild& mesh_;
  glm::dvec3 reference_;
  const SizeField& size_;
  std::vector<std::array<int, 3>> neighbour_;  // across the edge starting at each corner
  std::vector<std::array<std::uint8_t, 3>> cut_;
  std::priority_queue<Candidate> queue_;
};

}  // namespace

double SizeField::at(const glm::dvec3& direction) const {
  double nearest = 1e300;
  for (const glm::dvec3& c : centres)
    nearest = std::min(nearest, std::acos(std::clamp(glm::dot(c, direction), -1.0, 1.0)));
  if (nearest >= radius) return maxEdge;
  return maxEdge * std::max(minScale, std::pow(nearest / radius, exponent));
}

void refineTemplate(TemplateBuild& mesh, const glm::dvec3& reference, double maxEdge) {
  SizeField size;
  size.maxEdge = maxEdge;
  Refiner(mesh, reference, size).run();
}

void refineTemplate(TemplateBuild& mesh, const glm::dvec3& reference, const SizeField& size) {
  Refiner(mesh, reference, size).run();
}

}  // namespace confvis::detail
