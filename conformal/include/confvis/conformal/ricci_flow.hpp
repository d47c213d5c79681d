#pragma once
// The unified discrete surface Ricci flow (dissertation Chapter 4, Algorithm 7 of Appendix B):
// Newton's method on the discrete Ricci energy of a circle packing metric, for every scheme and
// background geometry, with step control that keeps every triangle valid, a sparse LDLᵀ whose
// symbolic analysis is reused across iterations, and optional (power) Delaunay edge flips.
#include <Eigen/SparseCore>

#include <functional>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/conformal/circle_packing.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct CirclePackingMetric {
  Geometry geometry = Geometry::Euclidean;
  Scheme scheme = Scheme::Yamabe;
  std::vector<double> u;        // conformal factor per vertex
  std::vector<int> epsilon;     // scheme coefficient per vertex: +1, 0 or -1
  std::vector<double> eta;      // conformal structure coefficient per edge
};

// ε per vertex used by Scheme::Mixed when none is given: +1 on even, 0 on odd vertex indices.
std::vector<int> defaultMixedEpsilon(int vertexCount);

// Initial metric per Appendix B, Step 1: radii chosen per scheme, then η solved from (4.1.2)
// so that the metric reproduces `lengths` (edge lengths in the background geometry). Exact for
// inversive distance, Yamabe, virtual radius and mixed; tangential (η ≡ 1) and Thurston
// (η ∈ [0,1]) cannot represent arbitrary lengths and only approximate them.
CirclePackingMetric initialMetric(const IntrinsicTriangulation& tri,
                                  const std::vector<double>& lengths, Scheme scheme,
                                  Geometry geometry, const std::vector<int>& mixedEpsilon = {});

// Edge lengths of a metric; throws Error(InvalidInput) naming the edge where (4.1.2) has no
// solution.
std::vector<double> metricEdgeLengths(const IntrinsicTriangulation& tri,
                                      const CirclePackingMetric& metric);

// Angle-deficit curvature (2π minus the angle sum inside, π on the boundary); throws naming the
// face if a triangle is invalid.
std::vector<double> vertexCurvature(const IntrinsicTriangulation& tri,
                                    const CirclePackingMetric& metric);

// The Hessian H = ∂K/∂u (full symmetric matrix), for tests and diagnostics.
Eigen::SparseMatrix<double> curvatureJacobian(const IntrinsicTriangulation& tri,
                                              const CirclePackingMetric& metric);

// Checks a target against Gauss-Bonnet and the per-vertex bounds before any flow runs.
// Euclidean: Σ K̄ = 2πχ. Hyperbolic: Σ K̄ > 2πχ (the excess is the area). Spherical: Σ K̄ < 2πχ.
// Throws Error(Unreachable) saying which condition fails, by how much.
void checkTargetCurvature(const IntrinsicTriangulation& tri, Geometry geometry,
                          const std::vector<double>& target);

// Thread-safety: a value (options); onIteration and updateTarget are called on the thread that
// runs the flow.
struct RicciFlowOptions {
  double tolerance = 1e-10;      // on max |K̄ - K|
  int maxIterations = 100;
  bool delaunayFlips = false;    // keep the triangulation (power) Delaunay by edge flips
  // Without delaunayFlips: switch them on (from the current metric, no restart) when a Newton
  // step is cut short by a degenerating triangle or the flow would stall, and from the start
  // when the target needs an angle no triangle can have (a vertex in too few triangles).
  bool flipsWhenStuck = false;
  // Called after each Newton iteration with (iteration, max curvature error).
  std::function<void(int, double)> onIteration;
  // Target curvature that depends on the metric (boundary conditions such as "the boundary is
  // a circle", dissertation §6.2): called after each Newton iteration, before the convergence
  // test, with the metric and its curvature; returns true if it changed `target`. The caller
  // keeps the changed target admissible.
  std::function<bool(const IntrinsicTriangulation&, const CirclePackingMetric&,
                     const std::vector<double>& curvature, std::vector<double>& target)>
      updateTarget;
};

struct RicciFlowReport {
  int iterations = 0;
  double maxCurvatureError = 0;
  int flips = 0;
  int flipsStartedAt = -1;       // Newton step (1-based) in which flips came on; 0: from the
                                 // start; -1: never
  int stepHalvings = 0;          // total line-search reductions
  int evaluations = 0;           // metric evaluations (curvature), line-search trials included
  int factorizations = 0;        // numeric LDLᵀ factorisations of the Hessian
  int symbolicAnalyses = 0;      // symbolic analyses (the first also orders the unknowns)
  int cgIterations = 0;          // conjugate-gradient steps preconditioned by a frozen factor
  int targetUpdates = 0;         // iterations in which options.updateTarget changed the target
  std::vector<double> errorHistory;
  // Where the time went, in seconds.
  struct Seconds {
    double evaluation = 0;     // lengths, angles and curvature (line-search trials included)
    double assembly = 0;       // Hessian values
    double analysis = 0;       // fill-reducing ordering and symbolic analysis
    double factorization = 0;  // numeric factorisations
    double solve = 0;          // triangular solves and conjugate gradients
    double flips = 0;          // Delaunay edge flips and pattern updates
  } seconds;
};

// Runs the flow in place: on return metric.u realises `target` to options.tolerance (and, with
// flips, `tri` is the final Delaunay triangulation). Throws Error(Unreachable) with the reason
// when the target is inadmissible, the flow stalls (no step keeps the triangles valid and
// reduces the error) or the iteration cap is hit. Never returns NaN.
RicciFlowReport runRicciFlow(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                             const std::vector<double>& target,
                             const RicciFlowOptions& options = {});

}  // namespace conformal
}  // namespace confvis
