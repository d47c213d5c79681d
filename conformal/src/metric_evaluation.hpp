#pragma once
// Internal: evaluation of a circle packing metric (lengths, angles, curvature, per-face angle
// Jacobians), shared by metric.cpp and ricci_flow.cpp.
#include <array>
#include <vector>

#include "confvis/conformal/ricci_flow.hpp"

namespace confvis::conformal::detail {

struct MetricEvaluation {
  Geometry geometry = Geometry::Euclidean;
  std::vector<EdgeLength> edges;
  std::vector<std::array<double, 3>> angles;  // per face corner
  std::vector<double> curvature;              // per vertex
  int invalidEdge = -1;                        // first edge where (4.1.2) has no solution
  int invalidFace = -1;                        // first face violating the triangle inequality
  bool valid() const { return invalidEdge < 0 && invalidFace < 0; }
};

// Evaluates the metric at conformal factors `u` (may differ from metric.u, for line searches).
void evaluateMetric(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                    const std::vector<double>& u, MetricEvaluation& out);

// Recomputes edge e and the angles of its faces after a local change (an edge flip); the
// curvature is left stale for the caller to refresh with refreshCurvature. False if invalid.
bool updateAroundEdge(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                      int e, MetricEvaluation& eval);
void refreshCurvature(const IntrinsicTriangulation& tri, MetricEvaluation& eval);

// J[a][b] = ∂θ_a/∂u_b for the corners a, b of face f (chain rule through the edge lengths).
void faceAngleJacobian(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int f,
                       std::array<std::array<double, 3>, 3>& J);

// Length of the other diagonal of the two triangles at interior edge e, from the current metric
// (cosine law with the summed angles at one endpoint). Returns false if the quad is not convex.
bool flippedEdgeLength(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                       Geometry geometry, int e, double& length);

}  // namespace confvis::conformal::detail
