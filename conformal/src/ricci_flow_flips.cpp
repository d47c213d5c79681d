// Edge flips that keep the triangulation (power) Delaunay during the flow, driven by a work
// list: every interior edge is checked once, and a flip re-queues only the four edges around it.
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "metric_evaluation.hpp"

namespace confvis::conformal::detail {
namespace {

// ∂θ/∂u weight of interior edge e summed over its two triangles: the (power) Delaunay
// criterion — negative means the edge is not Delaunay.
double edgeWeight(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int e) {
  double weight = 0;
  for (int f : tri.edgeFaces[e]) {
    const int c = tri.cornerOpposite(f, e);
    weight += faceAngleDerivative(tri, eval, f, (c + 1) % 3, (c + 2) % 3);
  }
  return weight;
}

constexpr double kNotDelaunay = -1e-12;

// Flips interior edge e to the other diagonal of its quad, keeping the metric's lengths (η of
// the new edge from the current factors); false, with nothing changed, if the quad is not
// convex or rounding would leave a new triangle invalid.
bool flipKeepingLengths(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                        MetricEvaluation& eval, int e) {
  double newLength;
  if (!flippedEdgeLength(tri, eval, metric.geometry, e, newLength)) return false;
  const double oldEta = metric.eta[e];
  tri.flip(e);
  const int p = tri.edgeVertices[e][0], s = tri.edgeVertices[e][1];
  metric.eta[e] = etaForLength(metric.geometry, newLength, metric.u[p], metric.u[s],
                               metric.epsilon[p], metric.epsilon[s]);
  if (updateAroundEdge(tri, metric, e, eval)) return true;
  // A nearly flat quad: undo; flipping the new diagonal restores the old one.
  tri.flip(e);
  metric.eta[e] = oldEta;
  if (!updateAroundEdge(tri, metric, e, eval))
    throw Error(ErrorCode::Internal, "undoing an edge flip left an invalid triangle");
  return false;
}

}  // namespace

int widenFans(IntrinsicTriangulation& tri, CirclePackingMetric& metric, MetricEvaluation& eval,
              const std::vector<double>& target, std::vector<char>& locked) {
  constexpr double pi = std::numbers::pi;
  std::vector<int> fanSize(tri.vertexCount, 0);
  for (const auto& fv : tri.faceVertices)
    for (int v : fv) ++fanSize[v];
  std::vector<int> tooNarrow;
  for (int v = 0; v < tri.vertexCount; ++v)
    if ((tri.vertexOnBoundary[v] ? 1 : 2) * pi - target[v] > fanSize[v] * pi - 1e-9)
      tooNarrow.push_back(v);
  int flips = 0;
  for (int v : tooNarrow)  // rare: a scan of the faces each is fine
    for (int f = 0; f < tri.faceCount(); ++f) {
      int c = 0;
      while (c < 3 && tri.faceVertices[f][c] != v) ++c;
      if (c == 3) continue;
      // Flip the edge opposite v: v gains a triangle.
      const int e = tri.faceEdges[f][c];
      if (tri.edgeOnBoundary(e) || locked[e] || !flipKeepingLengths(tri, metric, eval, e)) continue;
      locked[e] = 1;
      ++flips;
      break;
    }
  if (flips > 0) refreshCurvature(tri, eval);
  return flips;
}

void edgeWeights(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                 std::vector<double>& weights) {
  weights.assign(tri.edgeCount(), 0.0);
  std::array<std::array<double, 3>, 3> J;
  for (int f = 0; f < tri.faceCount(); ++f) {
    faceAngleJacobian(tri, eval, f, J);
    for (int c = 0; c < 3; ++c) weights[tri.faceEdges[f][c]] += J[(c + 1) % 3][(c + 2) % 3];
  }
}

int restoreDelaunay(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                    MetricEvaluation& eval, const std::vector<double>& weights,
                    const std::vector<char>& locked) {
  int flips = 0;
  const int limit = 20 * tri.edgeCount() + 100;
  std::vector<int> work;
  std::vector<char> queued;
  auto flippable = [&](int e) {
    return !tri.edgeOnBoundary(e) && (locked.empty() || !locked[e]);
  };
  for (int e = tri.edgeCount() - 1; e >= 0; --e)
    if (weights[e] < kNotDelaunay && flippable(e)) {
      if (queued.empty()) queued.assign(tri.edgeCount(), 0);
      work.push_back(e);
      queued[e] = 1;
    }
  while (!work.empty() && flips < limit) {
    const int e = work.back();
    work.pop_back();
    queued[e] = 0;
    if (edgeWeight(tri, eval, e) >= kNotDelaunay) continue;
    if (!flipKeepingLengths(tri, metric, eval, e)) continue;
    ++flips;
    for (int f : tri.edgeFaces[e])
      for (int side : tri.faceEdges[f])
        if (side != e && !queued[side] && flippable(side)) {
          work.push_back(side);
          queued[side] = 1;
        }
  }
  if (flips > 0) refreshCurvature(tri, eval);
  return flips;
}

}  // namespace confvis::conformal::detail
