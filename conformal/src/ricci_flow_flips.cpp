// Edge flips that keep the triangulation (power) Delaunay during the flow, driven by a work
// list: every interior edge is checked once, and a flip re-queues only the four edges around it.
#include <cmath>

#include "confvis/base/error.hpp"
#include "metric_evaluation.hpp"

namespace confvis::conformal::detail {
namespace {

// ∂θ/∂u weight of interior edge e summed over its two triangles: the (power) Delaunay
// criterion — negative means the edge is not Delaunay.
double edgeWeight(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int e) {
  double weight = 0;
  std::array<std::array<double, 3>, 3> J;
  for (int f : tri.edgeFaces[e]) {
    faceAngleJacobian(tri, eval, f, J);
    const int c = tri.cornerOpposite(f, e);
    weight += J[(c + 1) % 3][(c + 2) % 3];
  }
  return weight;
}

constexpr double kNotDelaunay = -1e-12;

}  // namespace

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
                    MetricEvaluation& eval, const std::vector<double>& weights) {
  int flips = 0;
  const int limit = 20 * tri.edgeCount() + 100;
  std::vector<int> work;
  std::vector<char> queued;
  for (int e = tri.edgeCount() - 1; e >= 0; --e)
    if (weights[e] < kNotDelaunay && !tri.edgeOnBoundary(e)) {
      if (queued.empty()) queued.assign(tri.edgeCount(), 0);
      work.push_back(e);
      queued[e] = 1;
    }
  while (!work.empty() && flips < limit) {
    const int e = work.back();
    work.pop_back();
    queued[e] = 0;
    if (edgeWeight(tri, eval, e) >= kNotDelaunay) continue;
    double newLength;
    if (!flippedEdgeLength(tri, eval, metric.geometry, e, newLength)) continue;
    const double oldEta = metric.eta[e];
    tri.flip(e);
    const int p = tri.edgeVertices[e][0], s = tri.edgeVertices[e][1];
    metric.eta[e] = etaForLength(metric.geometry, newLength, metric.u[p], metric.u[s],
                                 metric.epsilon[p], metric.epsilon[s]);
    if (!updateAroundEdge(tri, metric, e, eval)) {
      // A nearly flat quad: rounding makes a new triangle invalid. Undo; flipping the new
      // diagonal restores the old one.
      tri.flip(e);
      metric.eta[e] = oldEta;
      if (!updateAroundEdge(tri, metric, e, eval))
        throw Error(ErrorCode::Internal, "undoing an edge flip left an invalid triangle");
      continue;
    }
    ++flips;
    for (int f : tri.edgeFaces[e])
      for (int side : tri.faceEdges[f])
        if (side != e && !queued[side] && !tri.edgeOnBoundary(side)) {
          work.push_back(side);
          queued[side] = 1;
        }
  }
  if (flips > 0) refreshCurvature(tri, eval);
  return flips;
}

}  // namespace confvis::conformal::detail
