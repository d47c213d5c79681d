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
  std::vector<double> scale;                   // scratch: e^u per vertex (Euclidean)
  bool valid() const { return invalidEdge < 0 && invalidFace < 0; }
};

// Evaluates the metric at conformal factors `u` (may differ from metric.u, for line searches).
void evaluateMetric(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                    const std::vector<double>& u, MetricEvaluation& out);

// Corner angles of a Euclidean triangle from its edge lengths (l[c] opposite corner c), by
// half-angle tangents; false if the triangle inequality fails.
bool euclideanAngles(const std::array<double, 3>& l, std::array<double, 3>& angles);

// Recomputes eval.angles[f] from the current edge lengths; false if face f is invalid.
bool faceAngles(const IntrinsicTriangulation& tri, MetricEvaluation& eval, int f);

// Recomputes edge e and the angles of its faces after a local change (an edge flip); the
// curvature is left stale for the caller to refresh with refreshCurvature. False if invalid.
bool updateAroundEdge(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                      int e, MetricEvaluation& eval);
void refreshCurvature(const IntrinsicTriangulation& tri, MetricEvaluation& eval);

// J[a][b] = ∂θ_a/∂u_b for the corners a, b of face f (chain rule through the edge lengths).
void faceAngleJacobian(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int f,
                       std::array<std::array<double, 3>, 3>& J);

// Where on the way from the factors `uStart` (evaluated valid in `start`) to `uTrial` (evaluated
// in `trial`: some triangle inequality fails) the first triangle degenerates, as a fraction of
// the way, to 1e-4 relative: bisection of each failing face's triangle-inequality margin along
// the way (its linear interpolation put the point at half the true one in the first Newton steps
// at 100k, measured); 0 if that cannot be found (an edge without a length).
double degenerationStep(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                        const std::vector<double>& uStart, const std::vector<double>& uTrial,
                        const MetricEvaluation& start, const MetricEvaluation& trial);

// J[a][b] of faceAngleJacobian alone (cheaper in Euclidean geometry).
double faceAngleDerivative(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int f,
                           int a, int b);

// Length of the other diagonal of the two triangles at interior edge e, from the current metric
// (cosine law with the summed angles at one endpoint). Returns false if the quad is not convex.
bool flippedEdgeLength(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                       Geometry geometry, int e, double& length);

// Per edge, ∂θ/∂u across it summed over its triangles (the negated off-diagonal Hessian entry):
// negative on an interior edge that is not (power) Delaunay.
void edgeWeights(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                 std::vector<double>& weights);

// Flips interior edges of negative weight until none is left, updating `metric` (η of flipped
// edges) and `eval` (lengths, angles, curvature). `weights` (from edgeWeights or the Hessian
// assembly, at `eval`) says where to start; flips re-check only their neighbourhood. Edges
// marked in `locked` (empty: none) are never flipped. Returns the number of flips.
int restoreDelaunay(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                    MetricEvaluation& eval, const std::vector<double>& weights,
                    const std::vector<char>& locked);

// Where a target angle sum is out of reach of a vertex's triangles (each angle is below π, so
// a boundary vertex in one triangle cannot open to π), flips the edge opposite the vertex to
// give it one more, and locks that edge: the (power) Delaunay criterion need not agree (it
// never does for tangential packings, whose incircle centres keep every edge "Delaunay").
int widenFans(IntrinsicTriangulation& tri, CirclePackingMetric& metric, MetricEvaluation& eval,
              const std::vector<double>& target, std::vector<char>& locked);

}  // namespace confvis::conformal::detail
