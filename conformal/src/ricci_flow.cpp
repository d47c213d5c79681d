// The Newton loop of the unified Ricci flow (Appendix B, Algorithm 7), production version:
// the Hessian's sparsity pattern and its symbolic LDLᵀ analysis are built once per
// connectivity and reused; the values are scattered straight into the matrix each iteration.
#include "confvis/conformal/ricci_flow.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "confvis/base/error.hpp"
#include "metric_evaluation.hpp"

namespace confvis::conformal {
namespace {

using detail::MetricEvaluation;
using SparseMatrix = Eigen::SparseMatrix<double>;

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

double residualNorm2(const std::vector<double>& target, const std::vector<double>& K) {
  double s = 0;
  for (std::size_t i = 0; i < K.size(); ++i) s += (target[i] - K[i]) * (target[i] - K[i]);
  return s;
}

// The Newton system over the free vertices: lower triangle of H = ∂K/∂u with, per face, the
// position of each (corner, corner) entry in the compressed value array.
class NewtonSystem {
 public:
  NewtonSystem(const IntrinsicTriangulation& tri, int pinnedVertex) { build(tri, pinnedVertex); }

  int unknownOf(int v) const { return unknown_[v]; }
  int size() const { return n_; }

  void assemble(const IntrinsicTriangulation& tri, const MetricEvaluation& eval) {
    double* values = H_.valuePtr();
    std::fill(values, values + H_.nonZeros(), 0.0);
    std::array<std::array<double, 3>, 3> J;
    for (int f = 0; f < tri.faceCount(); ++f) {
      detail::faceAngleJacobian(tri, eval, f, J);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b <= a; ++b) {
          const int slot = slots_[f][a][b];
          if (slot >= 0) values[slot] -= 0.5 * (J[a][b] + J[b][a]);  // K = 2π - Σθ
        }
    }
  }

  const SparseMatrix& matrix() const { return H_; }

 private:
  void build(const IntrinsicTriangulation& tri, int pinnedVertex) {
    unknown_.assign(tri.vertexCount, -1);
    n_ = 0;
    for (int v = 0; v < tri.vertexCount; ++v)
      if (v != pinnedVertex) unknown_[v] = n_++;
    std::vector<Eigen::Triplet<double>> pattern;
    pattern.reserve(tri.edgeCount() + n_);
    for (int i = 0; i < n_; ++i) pattern.emplace_back(i, i, 0.0);
    for (const auto& ev : tri.edgeVertices) {
      const int a = unknown_[ev[0]], b = unknown_[ev[1]];
      if (a >= 0 && b >= 0) pattern.emplace_back(std::max(a, b), std::min(a, b), 0.0);
    }
    H_.resize(n_, n_);
    H_.setFromTriplets(pattern.begin(), pattern.end());
    H_.makeCompressed();
    slots_.resize(tri.faceCount());
    for (int f = 0; f < tri.faceCount(); ++f)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b <= a; ++b) {
          const int ra = unknown_[tri.faceVertices[f][a]], rb = unknown_[tri.faceVertices[f][b]];
          slots_[f][a][b] = (ra < 0 || rb < 0) ? -1 : slotOf(std::max(ra, rb), std::min(ra, rb));
        }
  }

  int slotOf(int row, int col) const {
    const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
    const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, row);
    if (it == end || *it != row) throw Error(ErrorCode::Internal, "Hessian pattern misses an entry");
    return static_cast<int>(it - H_.innerIndexPtr());
  }

  std::vector<int> unknown_;
  int n_ = 0;
  SparseMatrix H_;
  std::vector<std::array<std::array<int, 3>, 3>> slots_;
};

// Flips every interior edge whose Hessian weight (∂θ/∂u summed over its two triangles) is
// negative — the edge is not (power) Delaunay — until none is left. Returns the flip count.
int restoreDelaunay(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                    MetricEvaluation& eval) {
  int flips = 0;
  const int limit = 20 * tri.edgeCount() + 100;
  bool changed = true;
  // Each face's angle Jacobian, computed once per pass; a flip refreshes only its two faces.
  std::vector<std::array<std::array<double, 3>, 3>> faceJ(tri.faceCount());
  auto refreshFacesOf = [&](int e) {
    for (int f : tri.edgeFaces[e]) detail::faceAngleJacobian(tri, eval, f, faceJ[f]);
  };
  while (changed && flips < limit) {
    changed = false;
    for (int f = 0; f < tri.faceCount(); ++f) detail::faceAngleJacobian(tri, eval, f, faceJ[f]);
    for (int e = 0; e < tri.edgeCount() && flips < limit; ++e) {
      if (tri.edgeOnBoundary(e)) continue;
      double weight = 0;
      for (int f : tri.edgeFaces[e]) {
        const int c = tri.cornerOpposite(f, e);
        weight += faceJ[f][(c + 1) % 3][(c + 2) % 3];
      }
      if (weight >= -1e-12) continue;
      double newLength;
      if (!detail::flippedEdgeLength(tri, eval, metric.geometry, e, newLength)) continue;
      const double oldEta = metric.eta[e];
      tri.flip(e);
      const int p = tri.edgeVertices[e][0], s = tri.edgeVertices[e][1];
      metric.eta[e] = etaForLength(metric.geometry, newLength, metric.u[p], metric.u[s],
                                   metric.epsilon[p], metric.epsilon[s]);
      if (!detail::updateAroundEdge(tri, metric, e, eval)) {
        // A nearly flat quad: rounding makes a new triangle invalid. Undo; flipping the new
        // diagonal restores the old one.
        tri.flip(e);
        metric.eta[e] = oldEta;
        if (!detail::updateAroundEdge(tri, metric, e, eval))
          throw Error(ErrorCode::Internal, "undoing an edge flip left an invalid triangle");
        refreshFacesOf(e);
        continue;
      }
      refreshFacesOf(e);
      ++flips;
      changed = true;
    }
  }
  if (flips > 0) detail::refreshCurvature(tri, eval);
  return flips;
}

std::string describeInvalid(const MetricEvaluation& eval) {
  return eval.invalidEdge >= 0 ? "edge " + std::to_string(eval.invalidEdge) + " has no length"
                               : "face " + std::to_string(eval.invalidFace) + " degenerates";
}

}  // namespace

RicciFlowReport runRicciFlow(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                             const std::vector<double>& target, const RicciFlowOptions& options) {
  checkTargetCurvature(tri, metric.geometry, target);
  RicciFlowReport report;
  MetricEvaluation eval, trial;
  detail::evaluateMetric(tri, metric, metric.u, eval);
  if (!eval.valid())
    throw Error(ErrorCode::InvalidInput, "initial metric is invalid: " + describeInvalid(eval));
  if (options.delaunayFlips) report.flips += restoreDelaunay(tri, metric, eval);

  // Euclidean curvature is invariant under u → u + c: pin one vertex to remove the null space.
  const int pinned = metric.geometry == Geometry::Euclidean ? 0 : -1;
  auto system = std::make_unique<NewtonSystem>(tri, pinned);
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> solver;
  solver.analyzePattern(system->matrix());
  report.symbolicAnalyses = 1;

  std::vector<double> u = metric.u, uTrial(u.size());
  Eigen::VectorXd rhs(system->size()), delta;
  double error = maxAbsDifference(target, eval.curvature);
  report.errorHistory.push_back(error);
  while (error > options.tolerance) {
    if (report.iterations >= options.maxIterations) {
      std::ostringstream s;
      s << "Ricci flow did not converge in " << options.maxIterations
        << " iterations (max curvature error " << error << ", tolerance " << options.tolerance
        << ")";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    system->assemble(tri, eval);
    solver.factorize(system->matrix());
    ++report.factorizations;
    for (int v = 0; v < tri.vertexCount; ++v)
      if (int i = system->unknownOf(v); i >= 0) rhs[i] = target[v] - eval.curvature[v];
    bool newtonOk = solver.info() == Eigen::Success;
    if (newtonOk) {
      delta = solver.solve(rhs);
      newtonOk = delta.allFinite();
    }
    // Without a usable Newton step (the spherical energy is not convex) fall back to the flow
    // direction du = K̄ - K itself.
    if (!newtonOk) delta = rhs;

    // Backtracking: the step must keep every triangle valid and reduce |K̄ - K|².
    const double r0 = residualNorm2(target, eval.curvature);
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 60; ++halving, alpha *= 0.5) {
      for (int v = 0; v < tri.vertexCount; ++v) {
        const int i = system->unknownOf(v);
        uTrial[v] = i >= 0 ? u[v] + alpha * delta[i] : u[v];
      }
      detail::evaluateMetric(tri, metric, uTrial, trial);
      if (trial.valid() && residualNorm2(target, trial.curvature) < (1 - 1e-4 * alpha) * r0) {
        accepted = true;
        break;
      }
      ++report.stepHalvings;
    }
    if (!accepted) {
      std::ostringstream s;
      s << "Ricci flow stalled at max curvature error " << error << " after " << report.iterations
        << " iterations: no step keeps every triangle valid ("
        << (trial.valid() ? "error would grow" : describeInvalid(trial)) << ")";
      if (!options.delaunayFlips) s << "; enabling Delaunay edge flips may help";
      s << ", or the target curvature is not reachable for this mesh";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    u.swap(uTrial);
    std::swap(eval, trial);
    metric.u = u;
    ++report.iterations;
    if (options.delaunayFlips) {
      const int flips = restoreDelaunay(tri, metric, eval);
      if (flips > 0) {
        report.flips += flips;
        system = std::make_unique<NewtonSystem>(tri, pinned);
        solver.analyzePattern(system->matrix());
        ++report.symbolicAnalyses;
      }
    }
    error = maxAbsDifference(target, eval.curvature);
    report.errorHistory.push_back(error);
    if (options.onIteration) options.onIteration(report.iterations, error);
  }
  for (double x : metric.u)
    if (!std::isfinite(x)) throw Error(ErrorCode::Internal, "Ricci flow produced a non-finite factor");
  report.maxCurvatureError = error;
  return report;
}

}  // namespace confvis::conformal
